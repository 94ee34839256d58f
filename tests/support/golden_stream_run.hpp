// Runs the stream's golden strip (golden/golden_stream_format.hpp) through
// SceneStream and keeps what the recording holds: shared by the recorder
// (host) and the check on every target, so both read the objects alike.
#pragma once
#include <vector>

#include "golden/golden_stream_format.hpp"
#include "spinhash/database.hpp"

namespace spinhash {
namespace test {

struct GoldenStreamRun {
  Status status = Status::kNotOpen;           // init, then the worst of the pushes and the flush
  std::vector<golden::GoldenObject> objects;  // in reported order
  golden::GoldenStreamStats stats{};
};

// Pushes xyz (georeferenced doubles) in chunks of `chunk` points, then flushes.
GoldenStreamRun run_golden_stream(const Database& db, const std::vector<double>& xyz, size_t chunk);

}  // namespace test
}  // namespace spinhash
