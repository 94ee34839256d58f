// spinhash-experiment laz-speed: how fast our LAZ decoder turns files into
// raw point records, and into x y z through the chunked PointSource, in
// points per second on one core, with the process's peak RSS. The issue's
// yardstick: the reference LASzip library decodes format-0 tiles at about
// 4 M points/s on this machine.
#include <sys/resource.h>

#include <CLI/CLI.hpp>

#include <chrono>
#include <cstdio>
#include <memory>
#include <string>
#include <vector>

#include "cloud/byte_source.hpp"
#include "cloud/las_points.hpp"
#include "cloud/point_source.hpp"
#include "experiments.hpp"

namespace spinhash::experiment {
namespace {

constexpr double kMinSeconds = 1.0;  // repeat a small file until this much time has passed
constexpr size_t kMaxRepeats = 100000;

struct SpeedArgs {
  std::vector<std::string> files;
  double min_seconds = kMinSeconds;
};

double seconds_since(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

// Decodes every record of the file once; returns the points.
uint64_t decode_records(const std::string& path) {
  host::LasRecordReader reader(host::file_source(path));
  const size_t batch = host::las_batch_records(reader.header());
  std::vector<uint8_t> records(batch * reader.header().record_length);
  uint64_t total = 0;
  for (size_t n; (n = reader.read(records.data(), batch)) > 0;) total += n;
  return total;
}

uint64_t decode_xyz(const std::string& path) {
  auto source = host::open_point_source(path);
  std::vector<double> xyz(3 * host::kDefaultChunkPoints);
  uint64_t total = 0;
  for (size_t n; (n = source->read(xyz.data(), host::kDefaultChunkPoints)) > 0;) total += n;
  return total;
}

// Points per second of `run` over repeats lasting at least min_seconds.
double rate(uint64_t (*run)(const std::string&), const std::string& path, double min_seconds) {
  uint64_t points = 0;
  const auto t0 = std::chrono::steady_clock::now();
  size_t repeats = 0;
  do {
    points += run(path);
    ++repeats;
  } while (seconds_since(t0) < min_seconds && repeats < kMaxRepeats);
  return static_cast<double>(points) / seconds_since(t0);
}

long peak_rss_kib() {
  rusage u{};
  getrusage(RUSAGE_SELF, &u);
  return u.ru_maxrss;
}

int run_speed(const SpeedArgs& a) {
  std::printf("file,format,compressed,points,records_per_s,xyz_per_s,peak_rss_kib\n");
  for (const std::string& path : a.files) {
    try {
      const host::CloudHeader h = host::read_cloud_header(path);
      const double records = rate(decode_records, path, a.min_seconds);
      const double xyz = rate(decode_xyz, path, a.min_seconds);
      std::printf("%s,%u,%s,%llu,%.0f,%.0f,%ld\n", path.c_str(), static_cast<unsigned>(h.las_point_format),
                  h.format == "laz" ? "yes" : "no", static_cast<unsigned long long>(h.point_count), records,
                  xyz, peak_rss_kib());
    } catch (const host::CloudError& e) {
      std::fprintf(stderr, "laz-speed: %s\n", e.what());
      return 1;
    }
  }
  return 0;
}

}  // namespace

void add_laz_speed(CLI::App* parent, int* exit_code) {
  auto a = std::make_shared<SpeedArgs>();
  CLI::App* cmd = parent->add_subcommand(
      "laz-speed",
      "LAS/LAZ decoding speed (points/s, raw records and x y z) and peak RSS, one CSV row per file");
  cmd->add_option("files", a->files, "LAS or LAZ files")->required()->check(CLI::ExistingFile);
  cmd->add_option("--min-seconds", a->min_seconds, "repeat each file for at least this long")
      ->check(CLI::Range(0.0, 600.0))
      ->capture_default_str();
  cmd->callback([a, exit_code] { *exit_code = run_speed(*a); });
}

}  // namespace spinhash::experiment
