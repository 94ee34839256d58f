// Simulated queries (section 10.1): three views 45 degrees apart from a
// random side, a random pose, noise along the rays, optionally an occluder
// and the ground around the vehicle that every airborne scan contains.
#pragma once
#include <cstdint>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "mesh/mesh.hpp"
#include "scan/scan_simulator.hpp"

namespace spinhash::experiment {

enum class Ground : uint8_t {
  kNone,     // the vehicle alone (the paper's setting)
  kScanned,  // a ground square around the vehicle scanned with it (removed by the recognizer's default)
  kKept,     // scanned, and the recognizer's ground removal turned off (ground_clearance = 0)
};
const char* ground_name(Ground g);  // "none", "scanned", "kept"

// The paper's query density: 5 cm between neighbouring rays at the object
// (an airborne sensor at 20 m; 0.10 m is about 40 m, 0.15 m about 60 m).
constexpr double kPaperQuerySpacing = 0.05;

struct QueryCondition {
  double noise = 0.05;     // m along each ray
  double occlusion = 0.0;  // fraction of the object hidden
  Ground ground = Ground::kNone;
  double spacing = kPaperQuerySpacing;  // m between rays at the object
  double slope_deg = 0.0;               // terrain slope under the vehicle (with ground)
  // e.g. "noise0.05_occ0.2_ground"; "_sp0.1" is added for another spacing,
  // "_slope10" for a sloped ground.
  std::string label() const;
};

struct Query {
  uint32_t model = 0;  // index of the scanned model in the database
  uint32_t index = 0;  // query number for this model
  uint64_t seed = 0;
  std::vector<double> xyz;  // the cloud
  uint32_t object_points = 0;
  Eigen::Matrix4d true_pose = Eigen::Matrix4d::Identity();  // model -> query frame
};

// The same (model, q) gets the same seed, hence the same sides and pose,
// under every condition: conditions differ only in what they change.
uint64_t query_seed(uint64_t base_seed, uint32_t model, uint32_t q);

// One query scan's settings: the query views (query_scan_options), a
// random pose, and with `ground` a level ground square at ground_z
// reaching ground_margin beyond the object's footprint on each side.
struct QueryScan {
  uint64_t seed = 1;
  double noise = 0.05, occlusion = 0.0, spacing = kPaperQuerySpacing;
  double slope_deg = 0.0;  // the object (and the ground) tilted together
  bool ground = false;
  double ground_z = 0.0, ground_margin = 3.0;
};
// false with *error (naming the mesh) when the simulator fails.
bool scan_query(const host::Mesh& mesh, const QueryScan& s, host::ScanResult* out, std::string* error);

// ground_margin: metres of ground beyond the vehicle's footprint on each side.
bool simulate_query(const host::Mesh& mesh, uint32_t model, uint32_t q, const QueryCondition& c,
                    uint64_t base_seed, double ground_margin, Query* out, std::string* error);

// Cartesian product of the lists, ground states outermost: none, then
// scanned (with_ground), then scanned and kept (with_kept); then slope (for
// the ground states only), spacing, noise, occlusion.
std::vector<QueryCondition> make_conditions(const std::vector<double>& noise,
                                            const std::vector<double>& occlusion,
                                            const std::vector<double>& spacing,
                                            const std::vector<double>& slopes, bool with_ground,
                                            bool with_kept);

}  // namespace spinhash::experiment
