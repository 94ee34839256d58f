// Records the golden vectors on the host: the toy database in both byte
// orders, a set of query clouds, and the ranking every target must reproduce;
// then a short flight-line strip and the stream's objects on it
// (record_golden_stream.cpp).
//   cmake --build build --target record_golden && build/tests/record_golden tests/golden
// Re-record (and review the diff) whenever recognition changes on purpose.
#include <cinttypes>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <string>
#include <vector>

#include "blob/aligned_bytes.hpp"
#include "blob/blob_writer.hpp"
#include "blob/file_io.hpp"
#include "db/database_builder.hpp"
#include "golden/golden_format.hpp"
#include "golden/record_golden_stream.hpp"
#include "spinhash/recognizer.hpp"
#include "support/toy_database.hpp"

using namespace spinhash;

namespace {

constexpr float kModelSpacing = 0.05f;  // m between toy surface samples (as the toy tests)
constexpr float kQuerySpacing = 0.10f;  // ~ cloud_voxel (0.08): denser adds bytes, not information
// Sparser basis points than the default (0.25 m) keep each blob under 300 KB.
constexpr float kGoldenBasisSpacing = 0.45f;

struct QuerySpec {
  uint32_t model;
  Mode mode;
};
// Four models under BRAN, one under each baseline.
const QuerySpec kQueries[] = {{0, Mode::kBran}, {2, Mode::kBran}, {3, Mode::kBran},
                              {5, Mode::kBran}, {1, Mode::kSran}, {4, Mode::kSind}};

bool fail(const std::string& what) {
  std::fprintf(stderr, "record_golden: %s\n", what.c_str());
  return false;
}

bool write_bytes(const std::string& path, const std::vector<uint8_t>& bytes) {
  std::string error;
  return host::write_file_atomically(path, bytes, &error) || fail(path + ": " + error);
}

// Queries are stored as little-endian int16 millimetres (golden::decode_mm
// gives every target the same floats); returns the decoded cloud.
std::vector<float> append_mm(const std::vector<double>& xyz, std::vector<uint8_t>* out) {
  std::vector<float> decoded;
  for (double v : xyz) {
    const auto mm = static_cast<int16_t>(std::lround(v * 1000.0));
    const auto u = static_cast<uint16_t>(mm);
    out->push_back(static_cast<uint8_t>(u & 0xFFu));
    out->push_back(static_cast<uint8_t>(u >> 8));
    decoded.push_back(golden::decode_mm(out->data() + out->size() - 2));
  }
  return decoded;
}

void write_entry(FILE* h, const golden::GoldenQuery& g) {
  std::fprintf(h, "    {%u, %u, Mode::%s, %u, %u, %s, %u,\n     {", g.first_point, g.point_count,
               g.mode == Mode::kBran ? "kBran" : (g.mode == Mode::kSran ? "kSran" : "kSind"), g.features,
               g.hypotheses, g.budget_exhausted ? "true" : "false", g.ranking_count);
  for (uint32_t i = 0; i < golden::kMaxGoldenRanked; ++i)
    std::fprintf(h, "{%u, %.9ef}%s", g.ranking[i].model, static_cast<double>(g.ranking[i].score),
                 i + 1 < golden::kMaxGoldenRanked ? ", " : "},\n     {");
  for (int i = 0; i < 12; ++i) std::fprintf(h, "%.17g%s", g.pose[i], i < 11 ? ", " : "}},\n");
}

bool record(const std::string& dir) {
  std::vector<host::ModelCloud> clouds;
  for (uint32_t i = 0; i < test::kToyModels; ++i)
    clouds.push_back(host::ModelCloud{"toy-" + std::to_string(i), test::toy_vehicle_points(i, kModelSpacing),
                                      test::toy_class(i)});
  host::BlobContent content;
  host::BuildReport report;
  std::string error;
  host::BuildOptions options;
  options.features.basis_spacing = kGoldenBasisSpacing;
  if (!host::build_database(clouds, options, &content, &report, &error)) return fail(error);
  std::vector<uint8_t> le, be;
  if (!host::serialize_blob(content, host::ByteOrder::kLittle, &le, &error) ||
      !host::serialize_blob(content, host::ByteOrder::kBig, &be, &error))
    return fail(error);
  if (!write_bytes(dir + "/golden_le.shdb", le) || !write_bytes(dir + "/golden_be.shdb", be)) return false;

  std::vector<uint8_t> native;
  if (!host::serialize_blob(content, host::ByteOrder::kNative, &native, &error)) return fail(error);
  host::AlignedBytes bytes = host::AlignedBytes::copy_of(native);
  Database db;
  if (Database::open(bytes.data(), bytes.size(), &db) != Status::kOk) return fail("blob does not open");

  std::vector<uint8_t> query_bytes;
  std::vector<golden::GoldenQuery> expected;
  uint32_t next_point = 0;
  for (const QuerySpec& q : kQueries) {
    const double t[3] = {12.5, -3.25, 0.5};
    std::vector<double> xyz = test::toy_query(test::toy_vehicle_points(q.model, kQuerySpacing), 0.3 + q.model,
                                              t, 0.03, q.model + 11);
    std::vector<float> pts = append_mm(xyz, &query_bytes);  // the targets read exactly these floats
    RecognizerConfig cfg = golden::golden_config(q.mode);
    host::AlignedBytes workspace(required_workspace_bytes(cfg));
    Recognizer rec;
    if (rec.init(&db, cfg, workspace.data(), workspace.size()) != Status::kOk) return fail("init");
    Result r = rec.recognize(pts.data(), static_cast<uint32_t>(pts.size() / 3));
    if (r.status != Status::kOk || r.ranking_count == 0) return fail("query not recognised");
    golden::GoldenQuery g{};
    g.first_point = next_point;
    g.point_count = static_cast<uint32_t>(pts.size() / 3);
    g.mode = q.mode;
    g.features = r.stats.extract.features;
    g.hypotheses = r.stats.draws.hypotheses;
    g.budget_exhausted = r.stats.draws.budget_exhausted;
    g.ranking_count = r.ranking_count;
    for (uint32_t i = 0; i < r.ranking_count && i < golden::kMaxGoldenRanked; ++i)
      g.ranking[i] = golden::GoldenEntry{r.ranking[i].model, r.ranking[i].score};
    const Pose& p = r.ranking[0].pose;
    for (int i = 0; i < 9; ++i) g.pose[i] = static_cast<double>(p.rotation[i]);
    for (int i = 0; i < 3; ++i) g.pose[9 + i] = p.translation[i];
    expected.push_back(g);
    next_point += g.point_count;
    std::printf("query %zu: model %u mode %d -> top %u score %g, %u hypotheses\n", expected.size() - 1,
                q.model, static_cast<int>(q.mode), r.ranking[0].model,
                static_cast<double>(r.ranking[0].score), r.stats.draws.hypotheses);
  }
  if (!write_bytes(dir + "/golden_queries.i16", query_bytes)) return false;
  // The first query alone, for the C example (examples/c/recognize_blob.c).
  const size_t first_bytes = static_cast<size_t>(expected[0].point_count) * 3u * golden::kBytesPerCoordinate;
  if (!write_bytes(dir + "/golden_query0.i16",
                   std::vector<uint8_t>(query_bytes.begin(), query_bytes.begin() + first_bytes)))
    return false;

  FILE* h = std::fopen((dir + "/golden_expected.hpp").c_str(), "w");
  if (h == nullptr) return fail("cannot write golden_expected.hpp");
  std::fprintf(h,
               "// Generated by tests/golden/record_golden.cpp on the host: do not edit.\n"
               "#pragma once\n#include \"golden/golden_format.hpp\"\n\n"
               "namespace spinhash {\nnamespace golden {\n\n"
               "constexpr uint64_t kBlobBytes = %zu;  // each byte order\n"
               "constexpr uint32_t kQueryPoints = %u;\n"
               "const GoldenQuery kGoldenQueries[] = {\n",
               le.size(), next_point);
  for (const golden::GoldenQuery& g : expected) write_entry(h, g);
  std::fprintf(h, "};\n\n}  // namespace golden\n}  // namespace spinhash\n");
  if (std::fclose(h) != 0) return fail("cannot close golden_expected.hpp");
  return golden::record_stream(dir, db);
}

}  // namespace

int main(int argc, char** argv) {
  if (argc != 2) {
    std::fprintf(stderr, "usage: record_golden OUTPUT_DIR\n");
    return 2;
  }
  return record(argv[1]) ? 0 : 1;
}
