// Worst-case inputs for the work budget (onboard rule 5, docs/onboard-rules.md), measured by
// instruction count under callgrind (scripts/stages/23-work-budget.sh):
//   worst_case_runner prepare DIR        builds the databases and clouds (natively)
//   worst_case_runner run DIR CASE       one recognition, the part callgrind counts
//   worst_case_runner golden GOLDEN_DIR [INDEX]  the golden queries (all, or one)
//   worst_case_runner query DB.shdb CLOUD.f64 MODE  one query of the instruction
//                 benchmark (scripts/instructions-per-query.sh --target): raw
//                 little-endian float64 xyz, the default config in MODE (bran,
//                 sran, sind), recognition between spinhash_bench_begin() and
//                 spinhash_bench_end(), where scripts/qemu/insn_count.c counts;
//                 further arguments name=value change the config's fields
//                 (host/config/config_assign.hpp), as the host's flags do
// Cases:
//   max_points    toy database, a query of exactly config.max_points points
//   symmetric     toy models plus a sphere, a sphere query: every doublet on a
//                 sphere matches every model pair at the same distance
//   huge_buckets  32 identical spheres: every feature in the same LSH buckets
// `run` fails when the stats and the budget flag disagree, and when a case
// that must hit the budget does not say so.
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>
#include <vector>

#include "blob/aligned_bytes.hpp"
#include "blob/blob_writer.hpp"
#include "blob/file_io.hpp"
#include "config/config_assign.hpp"
#include "db/database_builder.hpp"
#include "golden/golden_expected.hpp"
#include "spinhash/recognizer.hpp"
#include "support/geometry_fixtures.hpp"
#include "support/toy_database.hpp"

using namespace spinhash;

namespace {

constexpr float kSphereRadius = 1.5f;       // m: vehicle-sized, many basis points
constexpr uint32_t kSpherePoints = 6000;    // ~0.07 m apart, near the 0.08 m voxel
constexpr uint32_t kHugeBucketModels = 32;  // identical spheres
constexpr float kDenseSpacing = 0.02f;      // m: a toy view denser than max_points allows
const char* const kCases[] = {"max_points", "symmetric", "huge_buckets"};

int fail(const std::string& what) {
  std::fprintf(stderr, "worst_case_runner: %s\n", what.c_str());
  return 1;
}

std::vector<double> sphere(float radius, uint32_t n) {
  std::vector<float> f = test::fibonacci_sphere(n, radius, 0.0f, 0.0f, 1.0f);
  return std::vector<double>(f.begin(), f.end());
}

// The query files are raw native-order float32 xyz: written and read on the same host.
bool write_floats(const std::string& path, const std::vector<double>& xyz) {
  std::vector<uint8_t> bytes(xyz.size() * sizeof(float));
  for (size_t i = 0; i < xyz.size(); ++i) {
    const float f = static_cast<float>(xyz[i]);
    std::memcpy(bytes.data() + i * sizeof f, &f, sizeof f);
  }
  std::string error;
  return host::write_file_atomically(path, bytes, &error);
}

bool write_database(const std::string& path, const std::vector<host::ModelCloud>& models) {
  host::BlobContent content;
  host::BuildReport report;
  std::string error;
  std::vector<uint8_t> bytes;
  if (!host::build_database(models, host::BuildOptions{}, &content, &report, &error) ||
      !host::serialize_blob(content, host::ByteOrder::kNative, &bytes, &error) ||
      !host::write_file_atomically(path, bytes, &error)) {
    std::fprintf(stderr, "worst_case_runner: %s: %s\n", path.c_str(), error.c_str());
    return false;
  }
  std::printf("%s: %u features, largest LSH bucket %u\n", path.c_str(), report.features, report.max_bucket);
  return true;
}

std::vector<host::ModelCloud> toy_models() {
  std::vector<host::ModelCloud> m;
  for (uint32_t i = 0; i < test::kToyModels; ++i)
    m.push_back(host::ModelCloud{"toy-" + std::to_string(i), test::toy_vehicle_points(i, 0.05f)});
  return m;
}

int prepare(const std::string& dir) {
  const uint32_t max_points = RecognizerConfig{}.max_points;
  const double t[3] = {0.0, 0.0, 0.0};
  std::vector<double> dense = test::toy_query(test::toy_vehicle_points(2, kDenseSpacing), 0.5, t, 0.02, 3);
  if (dense.size() / 3 < max_points) return fail("dense view smaller than max_points");
  std::vector<double> exact;  // exactly max_points, spread evenly over the dense view
  for (uint64_t i = 0; i < max_points; ++i) {
    const size_t p = static_cast<size_t>(i * (dense.size() / 3) / max_points);
    exact.insert(exact.end(), dense.begin() + 3 * p, dense.begin() + 3 * p + 3);
  }
  std::vector<host::ModelCloud> with_sphere = toy_models();
  with_sphere.push_back(host::ModelCloud{"sphere", sphere(kSphereRadius, kSpherePoints)});
  std::vector<host::ModelCloud> spheres;
  for (uint32_t i = 0; i < kHugeBucketModels; ++i)
    spheres.push_back(host::ModelCloud{"sphere-" + std::to_string(i), sphere(kSphereRadius, kSpherePoints)});
  const std::vector<double> sphere_query = sphere(kSphereRadius, kSpherePoints / 2);
  const bool ok = write_database(dir + "/max_points.shdb", toy_models()) &&
                  write_floats(dir + "/max_points.f32", exact) &&
                  write_database(dir + "/symmetric.shdb", with_sphere) &&
                  write_floats(dir + "/symmetric.f32", sphere_query) &&
                  write_database(dir + "/huge_buckets.shdb", spheres) &&
                  write_floats(dir + "/huge_buckets.f32", sphere_query);
  return ok ? 0 : fail("prepare failed");
}

// One recognition with the default config; prints the stats as one line.
int recognise(const Database& db, const float* xyz, uint32_t count, const char* name, bool must_exhaust,
              const RecognizerConfig& cfg) {
  host::AlignedBytes workspace(required_workspace_bytes(cfg));
  Recognizer rec;
  if (rec.init(&db, cfg, workspace.data(), workspace.size()) != Status::kOk) return fail("init failed");
  Result r = rec.recognize(xyz, count);
  const RecognitionStats& s = r.stats;
  std::printf(
      "%s: status=%s points=%u features=%u trials=%u pair_checks=%llu hypotheses=%u poses_tilted=%llu "
      "bucket_entries=%llu bucket_scan_truncated=%d budget_exhausted=%d passes=%u work=%llu work_capped=%d\n",
      name, status_name(r.status), count, s.extract.features, s.draws.trials,
      static_cast<unsigned long long>(s.draws.pair_checks), s.draws.hypotheses,
      static_cast<unsigned long long>(s.draws.poses_tilted),
      static_cast<unsigned long long>(s.candidates.bucket_entries),
      s.candidates.bucket_scan_truncated ? 1 : 0, s.draws.budget_exhausted ? 1 : 0, s.cascade.passes,
      static_cast<unsigned long long>(s.cascade.work), s.cascade.work_capped ? 1 : 0);
  // The work cap's answer is the best so far: an answer.
  if (r.status != Status::kOk && r.status != Status::kWorkCapReached)
    return fail(std::string(name) + ": not recognised");
  // The hypothesis budget counts the poses found, tilted ones too (max_tilt_deg); the work cap stops the
  // draws as well.
  const bool cap_reached = s.draws.poses_found() >= cfg.draws.max_hypotheses ||
                           s.draws.pair_checks >= cfg.draws.max_pair_checks || s.cascade.work_capped;
  if (cap_reached != s.draws.budget_exhausted)
    return fail(std::string(name) + ": budget flag disagrees with the stats");
  if (must_exhaust && !s.draws.budget_exhausted)
    return fail(std::string(name) + ": worst case did not reach the budget");
  return 0;
}

int run(const std::string& dir, const std::string& name) {
  bool known = false;
  for (const char* c : kCases) known = known || name == c;
  if (!known) return fail("unknown case " + name);
  host::AlignedBytes blob, cloud;
  std::string error;
  if (!host::read_file(dir + "/" + name + ".shdb", &blob, &error) ||
      !host::read_file(dir + "/" + name + ".f32", &cloud, &error))
    return fail(error + " (run prepare first)");
  Database db;
  if (Database::open(blob.data(), blob.size(), &db) != Status::kOk) return fail("database does not open");
  const auto* xyz = reinterpret_cast<const float*>(cloud.data());  // 64-byte aligned buffer
  return recognise(db, xyz, static_cast<uint32_t>(cloud.size() / (3 * sizeof(float))), name.c_str(),
                   name != "max_points", RecognizerConfig{});
}

}  // namespace

// Markers around the counted recognition: a QEMU plugin counts the
// instructions between their calls (no callgrind on emulated targets).
extern "C" __attribute__((noinline)) void spinhash_bench_begin() { __asm__ volatile(""); }
extern "C" __attribute__((noinline)) void spinhash_bench_end() { __asm__ volatile(""); }

namespace {

bool parse_mode(const std::string& name, Mode* mode) {
  const struct {
    const char* name;
    Mode mode;
  } modes[] = {{"bran", Mode::kBran}, {"sran", Mode::kSran}, {"sind", Mode::kSind}};
  for (const auto& m : modes)
    if (name == m.name) *mode = m.mode;
  return name == "bran" || name == "sran" || name == "sind";
}

int query(const std::string& db_path, const std::string& cloud_path, const std::string& mode_name,
          const std::vector<std::string>& settings) {
  host::AlignedBytes blob, cloud;
  std::string error;
  RecognizerConfig cfg;
  if (!parse_mode(mode_name, &cfg.mode)) return fail("unknown mode " + mode_name);
  for (const std::string& s : settings)
    if (!host::assign_config_field(s, &cfg, &error)) return fail(error);
  if (!host::read_file(db_path, &blob, &error) || !host::read_file(cloud_path, &cloud, &error))
    return fail(error);
  Database db;
  if (Database::open(blob.data(), blob.size(), &db) != Status::kOk) return fail("database does not open");
  const auto* xyz = reinterpret_cast<const double*>(cloud.data());  // 64-byte aligned buffer
  host::AlignedBytes workspace(required_workspace_bytes(cfg));
  Recognizer rec;
  if (rec.init(&db, cfg, workspace.data(), workspace.size()) != Status::kOk) return fail("init failed");
  spinhash_bench_begin();
  const Result r = rec.recognize(xyz, static_cast<uint32_t>(cloud.size() / (3 * sizeof(double))));
  spinhash_bench_end();
  if ((r.status != Status::kOk && r.status != Status::kWorkCapReached) || r.ranking_count == 0)
    return fail(std::string("query: ") + status_name(r.status));
  std::printf("top=%s hypotheses=%u features=%u passes=%u work=%llu status=%s\n",
              db.model(r.ranking[0].model).name, r.stats.draws.hypotheses, r.stats.extract.features,
              r.stats.cascade.passes, static_cast<unsigned long long>(r.stats.cascade.work),
              status_name(r.status));
  return 0;
}

int golden_queries(const std::string& dir, int only) {
  host::AlignedBytes blob, raw;
  std::string error;
  if (!host::read_file(dir + "/golden_le.shdb", &blob, &error) ||
      !host::read_file(dir + "/golden_queries.i16", &raw, &error))
    return fail(error);
  Database db;
  if (Database::open(blob.data(), blob.size(), &db) != Status::kOk) return fail("golden blob does not open");
  std::vector<float> xyz(raw.size() / golden::kBytesPerCoordinate);
  for (size_t i = 0; i < xyz.size(); ++i)
    xyz[i] = golden::decode_mm(raw.data() + golden::kBytesPerCoordinate * i);
  int status = 0;
  for (size_t q = 0; q < sizeof(golden::kGoldenQueries) / sizeof(golden::kGoldenQueries[0]); ++q) {
    if (only >= 0 && static_cast<size_t>(only) != q) continue;
    const golden::GoldenQuery& g = golden::kGoldenQueries[q];
    const std::string name = "golden-" + std::to_string(q);
    status |= recognise(db, xyz.data() + 3u * g.first_point, g.point_count, name.c_str(), false,
                        golden::golden_config(g.mode));
  }
  return status;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc == 3 && std::strcmp(argv[1], "prepare") == 0) return prepare(argv[2]);
  if (argc == 4 && std::strcmp(argv[1], "run") == 0) return run(argv[2], argv[3]);
  if (argc >= 5 && std::strcmp(argv[1], "query") == 0)
    return query(argv[2], argv[3], argv[4], std::vector<std::string>(argv + 5, argv + argc));
  if ((argc == 3 || argc == 4) && std::strcmp(argv[1], "golden") == 0)
    return golden_queries(argv[2], argc == 4 ? std::atoi(argv[3]) : -1);
  std::fprintf(stderr,
               "usage: worst_case_runner prepare DIR | run DIR CASE | golden GOLDEN_DIR [INDEX] | "
               "query DB.shdb CLOUD.f64 MODE [KEY=VALUE...]\n");
  return 2;
}
