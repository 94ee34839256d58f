// spinhash-experiment laz-speed: how fast our LAZ decoder turns files into
// raw point records, and into x y z through the chunked PointSource, in
// points per second on one core, with the process's peak RSS. The
// yardstick: the reference LASzip library decodes format-0 tiles at about
// 4 M points/s on this machine. Times are the process's CPU time (the
// machine is shared; wall time would count other processes), and the
// steady rate leaves out opening the file and its first chunk's setup, so
// that small sample files say what a tile of millions of points would.
#include <sys/resource.h>
#include <time.h>

#include <CLI/CLI.hpp>

#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <memory>
#include <string>
#include <vector>

#include "cloud/byte_source.hpp"
#include "cloud/las_points.hpp"
#include "cloud/laz/item_codec.hpp"
#include "cloud/point_source.hpp"
#include "experiments.hpp"
#include "laz_tile_writer.hpp"

namespace spinhash::experiment {
namespace {

constexpr double kMinSeconds = 1.0;  // repeat a small file until this much time has passed
constexpr size_t kMaxRepeats = 100000;

struct SpeedArgs {
  std::vector<std::string> files;
  double min_seconds = kMinSeconds;
  std::string tile_out;     // write a format-0 LAZ tile here first
  std::string tile_source;  // from these LAS/LAZ points
  unsigned copies = 10;     // side by side along x
};

constexpr uint32_t kTileChunk = 50000;  // LASzip's default chunk size
constexpr size_t kFormat0Bytes = 20;

double cpu_seconds() {
  timespec t{};
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
  return static_cast<double>(t.tv_sec) + 1e-9 * static_cast<double>(t.tv_nsec);
}

// Decodes at most `limit` records of the file, LAS 1.4's layers as `layers`
// says; returns how many.
uint64_t decode_some(const std::string& path, uint64_t limit,
                     host::laz::LayerChoice layers = host::laz::LayerChoice::kAll) {
  host::LasRecordReader reader(host::file_source(path), layers);
  const size_t batch = host::las_batch_records(reader.header());
  std::vector<uint8_t> records(batch * reader.header().record_length);
  uint64_t total = 0;
  for (size_t n;
       total < limit && (n = reader.read(records.data(), std::min<uint64_t>(batch, limit - total))) > 0;)
    total += n;
  return total;
}
uint64_t decode_records(const std::string& path) { return decode_some(path, UINT64_MAX); }
uint64_t decode_first(const std::string& path) { return decode_some(path, 1); }
uint64_t decode_pipeline_fields(const std::string& path) {
  return decode_some(path, UINT64_MAX, host::laz::LayerChoice::kPipeline);
}

uint64_t decode_xyz(const std::string& path) {
  auto source = host::open_point_source(path);
  std::vector<double> xyz(3 * host::kDefaultChunkPoints);
  uint64_t total = 0;
  for (size_t n; (n = source->read(xyz.data(), host::kDefaultChunkPoints)) > 0;) total += n;
  return total;
}

struct Timing {
  double seconds_per_run = 0;
  uint64_t points_per_run = 0;
  double rate() const { return static_cast<double>(points_per_run) / seconds_per_run; }
};

// CPU seconds per run of `run`, over repeats lasting at least min_seconds.
Timing time_runs(uint64_t (*run)(const std::string&), const std::string& path, double min_seconds) {
  Timing t;
  const double t0 = cpu_seconds();
  size_t repeats = 0;
  do {
    t.points_per_run = run(path);
    ++repeats;
  } while (cpu_seconds() - t0 < min_seconds && repeats < kMaxRepeats);
  t.seconds_per_run = (cpu_seconds() - t0) / static_cast<double>(repeats);
  return t;
}

long peak_rss_kib() {
  rusage u{};
  getrusage(RUSAGE_SELF, &u);
  return u.ru_maxrss;
}

// All raw records of a file, cut to their first 20 bytes (format 0).
std::vector<uint8_t> format0_records(const std::string& path, host::LasHeader* h) {
  host::LasRecordReader reader(host::file_source(path));
  *h = reader.header();
  const size_t batch = host::las_batch_records(*h);
  std::vector<uint8_t> records(batch * h->record_length), out;
  for (size_t n; (n = reader.read(records.data(), batch)) > 0;)
    for (size_t i = 0; i < n; ++i) {
      const uint8_t* r = records.data() + i * h->record_length;
      out.insert(out.end(), r, r + kFormat0Bytes);
    }
  return out;
}

// `copies` copies of the source's points side by side along x, as a
// format-0 LAZ tile; checks that our decoder gives the records back.
int make_tile(const SpeedArgs& a) {
  host::LasHeader h;
  const std::vector<uint8_t> one = format0_records(a.tile_source, &h);
  const int32_t step = static_cast<int32_t>((h.max[0] - h.min[0]) / h.scale[0]) + 1;
  std::vector<uint8_t> all;
  for (unsigned c = 0; c < a.copies; ++c)
    for (size_t i = 0; i < one.size(); i += kFormat0Bytes) {
      uint8_t r[kFormat0Bytes];
      std::memcpy(r, &one[i], kFormat0Bytes);
      host::laz::put_i32(r, host::laz::get_i32(r) + static_cast<int32_t>(c) * step);
      all.insert(all.end(), r, r + kFormat0Bytes);
    }
  h.max[0] += (a.copies - 1) * step * h.scale[0];
  std::string error;
  if (!write_format0_laz(a.tile_out, h, all, kTileChunk, &error)) {
    std::fprintf(stderr, "laz-speed: %s\n", error.c_str());
    return 1;
  }
  host::LasHeader back;
  if (format0_records(a.tile_out, &back) != all) {
    std::fprintf(stderr, "laz-speed: %s does not decode to the records written\n", a.tile_out.c_str());
    return 1;
  }
  std::fprintf(stderr, "laz-speed: %s: %zu points, decodes to the records written\n", a.tile_out.c_str(),
               all.size() / kFormat0Bytes);
  return 0;
}

int run_speed(SpeedArgs a) {
  if (!a.tile_out.empty()) {
    try {
      if (make_tile(a) != 0) return 1;
    } catch (const host::CloudError& e) {
      std::fprintf(stderr, "laz-speed: %s\n", e.what());
      return 1;
    }
    a.files.insert(a.files.begin(), a.tile_out);
  }
  std::printf(
      "file,format,compressed,points,open_ms,records_per_s,steady_records_per_s,pipeline_records_per_s,"
      "xyz_per_s,peak_rss_kib\n");
  for (const std::string& path : a.files) {
    try {
      const host::CloudHeader h = host::read_cloud_header(path);
      const Timing open = time_runs(decode_first, path, a.min_seconds / 4);
      const Timing records = time_runs(decode_records, path, a.min_seconds);
      const Timing pipeline = time_runs(decode_pipeline_fields, path, a.min_seconds);
      const Timing xyz = time_runs(decode_xyz, path, a.min_seconds);
      // Points after the first, over the time after the open and first point.
      const uint64_t after_first = records.points_per_run - std::min<uint64_t>(records.points_per_run, 1);
      const double steady =
          static_cast<double>(after_first) / std::max(1e-9, records.seconds_per_run - open.seconds_per_run);
      std::printf("%s,%u,%s,%llu,%.3f,%.0f,%.0f,%.0f,%.0f,%ld\n", path.c_str(),
                  static_cast<unsigned>(h.las_point_format), h.format == "laz" ? "yes" : "no",
                  static_cast<unsigned long long>(h.point_count), 1e3 * open.seconds_per_run, records.rate(),
                  steady, pipeline.rate(), xyz.rate(), peak_rss_kib());
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
  cmd->add_option("files", a->files, "LAS or LAZ files")->check(CLI::ExistingFile);
  cmd->add_option(
      "--write-format0-tile", a->tile_out,
      "first write a format-0 LAZ tile (our benchmark writer) of --copies copies of --source's points");
  cmd->add_option("--source", a->tile_source, "LAS or LAZ points for the tile")->check(CLI::ExistingFile);
  cmd->add_option("--copies", a->copies, "copies side by side along x")
      ->check(CLI::Range(1u, 1000u))
      ->capture_default_str();
  cmd->add_option("--min-seconds", a->min_seconds, "repeat each file for at least this long")
      ->check(CLI::Range(0.0, 600.0))
      ->capture_default_str();
  cmd->callback([a, exit_code] { *exit_code = run_speed(*a); });
}

}  // namespace spinhash::experiment
