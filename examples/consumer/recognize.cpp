// Host-side consumer of the installed core: reads a database blob and a
// query cloud, recognises, prints the ranking (docs/firmware.md).
//
//   recognize DB.shdb CLOUD [EXPECTED_TOP_MODEL]
//
// CLOUD is either .i16 (x y z little-endian int16 millimetres, the format of
// tests/golden/golden_query0.i16) or text (x y z in metres per line, '#'
// comments). Exit codes as the spinhash command: 0 ok, 1 error, 2 bad
// arguments, 3 the expected model was not ranked first.
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

#include "spinhash/limits.hpp"
#include "spinhash/recognizer.hpp"

namespace {

constexpr int kExitError = 1;
constexpr int kExitUsage = 2;
constexpr int kExitCheckFailed = 3;
constexpr uint32_t kRanksShown = 5;
constexpr double kMetresPerMillimetre = 0.001;
constexpr size_t kBytesPerI16Point = 6;

struct FreeDeleter {
  void operator()(void* p) const { std::free(p); }
};
using AlignedBytes = std::unique_ptr<uint8_t[], FreeDeleter>;

// The core wants the blob and the workspace on kBufferAlignment boundaries
// (kMisalignedBuffer otherwise); aligned_alloc needs a multiple of it.
AlignedBytes aligned_bytes(size_t size) {
  const size_t a = spinhash::kBufferAlignment;
  const size_t rounded = (size + a - 1) / a * a;
  return AlignedBytes(static_cast<uint8_t*>(std::aligned_alloc(a, rounded == 0 ? a : rounded)));
}

bool read_file(const char* path, std::vector<char>* out) {
  std::ifstream in(path, std::ios::binary);
  if (!in) return false;
  out->assign(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
  return !in.bad();
}

bool ends_with(const std::string& s, const std::string& suffix) {
  return s.size() >= suffix.size() && s.compare(s.size() - suffix.size(), suffix.size(), suffix) == 0;
}

// .i16: decoded bytewise, so big-endian hosts read the same points.
bool load_i16(const std::vector<char>& raw, std::vector<double>* xyz) {
  if (raw.size() % kBytesPerI16Point != 0) return false;
  for (size_t i = 0; i + 1 < raw.size(); i += 2) {
    const auto lo = static_cast<uint8_t>(raw[i]), hi = static_cast<uint8_t>(raw[i + 1]);
    const auto mm = static_cast<int16_t>(static_cast<uint16_t>(lo | hi << 8));
    xyz->push_back(mm * kMetresPerMillimetre);
  }
  return true;
}

// Text: three numbers per line; anything else is an error, not a skipped line.
bool load_text(const std::vector<char>& raw, std::vector<double>* xyz, std::string* why) {
  std::istringstream in(std::string(raw.begin(), raw.end()));
  std::string line;
  for (int n = 1; std::getline(in, line); ++n) {
    const size_t first = line.find_first_not_of(" \t\r");
    if (first == std::string::npos || line[first] == '#') continue;
    std::istringstream fields(line);
    double x, y, z;
    std::string rest;
    if (!(fields >> x >> y >> z) || (fields >> rest)) {
      *why = "line " + std::to_string(n) + ": expected x y z";
      return false;
    }
    xyz->insert(xyz->end(), {x, y, z});
  }
  return true;
}

bool load_cloud(const char* path, std::vector<double>* xyz, std::string* why) {
  std::vector<char> raw;
  if (!read_file(path, &raw)) {
    *why = "cannot read";
    return false;
  }
  if (!ends_with(path, ".i16")) return load_text(raw, xyz, why);
  if (load_i16(raw, xyz)) return true;
  *why = "size is not a multiple of 6 bytes";
  return false;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc < 3 || argc > 4) {
    std::fprintf(stderr, "usage: %s DB.shdb CLOUD(.i16|text x y z) [EXPECTED_TOP_MODEL]\n", argv[0]);
    return kExitUsage;
  }
  std::vector<char> file;
  if (!read_file(argv[1], &file)) {
    std::fprintf(stderr, "%s: cannot read\n", argv[1]);
    return kExitError;
  }
  // The view keeps pointing into these bytes: they must outlive db.
  AlignedBytes blob = aligned_bytes(file.size());
  std::memcpy(blob.get(), file.data(), file.size());
  spinhash::Database db;
  spinhash::Status s = spinhash::Database::open(blob.get(), file.size(), &db);
  if (s != spinhash::Status::kOk) {
    std::fprintf(stderr, "%s: %s\n", argv[1], spinhash::status_name(s));
    return kExitError;
  }

  std::vector<double> xyz;
  std::string why;
  if (!load_cloud(argv[2], &xyz, &why)) {
    std::fprintf(stderr, "%s: %s\n", argv[2], why.c_str());
    return kExitError;
  }

  // Defaults (the paper's setting), with the workspace sized for this
  // database's model count instead of the default 2 048 models.
  spinhash::RecognizerConfig config;
  config.max_models = db.model_count();
  const size_t workspace_bytes = spinhash::required_workspace_bytes(config);
  std::printf("database: %u models, %zu bytes; workspace %zu bytes\n", db.model_count(), file.size(),
              workspace_bytes);
  AlignedBytes workspace = aligned_bytes(workspace_bytes);
  spinhash::Recognizer recognizer;
  s = recognizer.init(&db, config, workspace.get(), workspace_bytes);
  if (s != spinhash::Status::kOk) {
    std::fprintf(stderr, "init: %s\n", spinhash::status_name(s));
    return kExitError;
  }

  const auto points = static_cast<uint32_t>(xyz.size() / 3);
  const spinhash::Result r = recognizer.recognize(xyz.data(), points);
  std::printf("query: %u points, status %s, confident %s, %u features, %u hypotheses%s\n", points,
              spinhash::status_name(r.status), r.confident ? "yes" : "no", r.stats.extract.features,
              r.stats.draws.hypotheses, r.stats.draws.budget_exhausted ? ", work budget exhausted" : "");
  if (r.status != spinhash::Status::kOk || r.ranking_count == 0) return kExitError;
  for (uint32_t i = 0; i < r.ranking_count && i < kRanksShown; ++i) {
    const spinhash::RankedModel& m = r.ranking[i];
    const double* t = m.pose.translation;
    std::printf("  %u. %-10s score %10.3f  t = (%.3f, %.3f, %.3f)\n", i + 1, db.model(m.model).name,
                static_cast<double>(m.score), t[0], t[1], t[2]);
  }
  const char* top = db.model(r.ranking[0].model).name;
  if (argc == 4 && std::strcmp(top, argv[3]) != 0) {
    std::fprintf(stderr, "expected %s first, got %s\n", argv[3], top);
    return kExitCheckFailed;
  }
  return 0;
}
