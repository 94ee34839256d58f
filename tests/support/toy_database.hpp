// A small database of box-built toy vehicles, made in-process (no files), so
// recognition can be tested end to end on every target.
#pragma once
#include <cstdint>
#include <vector>

#include "blob/aligned_bytes.hpp"
#include "db/database_builder.hpp"
#include "spinhash/database.hpp"

namespace spinhash {
namespace test {

// Surface points of toy vehicle `index` (0..kToyModels-1) in its model frame.
std::vector<double> toy_vehicle_points(uint32_t index, float spacing);
constexpr uint32_t kToyModels = 6;
// The class of toy `index`: sedan, pickup, truck, tracked, van, sedan (two
// sedans, so a class has more than one model).
VehicleClass toy_class(uint32_t index);

struct ToyDatabase {
  host::AlignedBytes bytes;
  Database db;
};
// Builds, serialises (native byte order) and opens the toy database. With
// twin_of < kToyModels, a last model "toy-twin" repeats that toy exactly (a
// look-alike in the same frame).
constexpr uint32_t kNoTwin = 0xFFFFFFFFu;
bool make_toy_database(ToyDatabase* out, uint32_t twin_of = kNoTwin);

// The same database, built once per process and shared read-only by every
// case that reads it: building it is most of such a case's time, several
// seconds under emulation. Aborts, saying so, if it cannot be built.
const ToyDatabase& shared_toy_database(uint32_t twin_of = kNoTwin);
// The toys' clouds, named "toy-0".. in index order.
std::vector<host::ModelCloud> toy_clouds();
// Builds, serialises (native byte order) and opens a database of `clouds`.
bool make_database(const std::vector<host::ModelCloud>& clouds, ToyDatabase* out,
                   const host::BuildOptions& options = host::BuildOptions());

// A partial view of a vehicle's points: keeps those with x >= -2.5 m,
// y >= -0.5 m and z >= 0.2 m (the front-left half, from above), rotates
// about z by yaw, translates by t and adds deterministic noise of `noise` m.
std::vector<double> toy_query(const std::vector<double>& model, double yaw, const double t[3], double noise,
                              uint64_t seed);
// An airborne view from the front-left: the top whole, the front and the
// left side; not the back face, the right side or the bottom. Unlike
// toy_query's, it shows the vehicle's full length and width, which a
// confident answer needs (recognize/confidence.hpp). Moved and noisy alike.
std::vector<double> toy_airborne_query(const std::vector<double>& model, double yaw, const double t[3],
                                       double noise, uint64_t seed);

}  // namespace test
}  // namespace spinhash
