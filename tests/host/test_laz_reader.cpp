// The LAZ decoder and the CRS reader on the public files in
// ../shared/data/laz (PDAL, laz-rs, laspy, laz-perf and LASzip test data;
// its README lists them): every LAZ twin gives the raw point records of its
// uncompressed twin field by field, COPC the same points in another order,
// the format-8 file agrees with its header, LAS 1.4 files read for the
// pipeline keep x y z, returns and class and skip the other layers, the
// broken files are refused each with its own message, and a CRS is read
// from every CRS sample. The x/y predictor's streaming median follows
// LASzip's insertion rules.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <map>
#include <string>
#include <tuple>
#include <vector>

#include "cloud/byte_source.hpp"
#include "cloud/cloud_reader.hpp"
#include "cloud/las_points.hpp"
#include "cloud/las_reader.hpp"
#include "cloud/laz/item_codec.hpp"
#include "cloud/point_source.hpp"
#include "cloud_test_support.hpp"

using namespace spinhash::host;

namespace {

const std::string kLaz = SPINHASH_LAZ_SAMPLES;  // ../shared/data/laz beside the clone

bool laz_samples_present() {
  if (std::filesystem::is_directory(kLaz)) return true;
  MESSAGE("LAZ samples not found at " << kLaz << ": skipped (they live in shared/, beside the clone)");
  return false;
}

struct Records {
  LasHeader header;
  Crs crs;
  std::vector<uint8_t> bytes;  // raw records, record_length each
  size_t count() const { return bytes.size() / header.record_length; }
  const uint8_t* at(size_t i) const { return bytes.data() + i * header.record_length; }
};

Records read_records(const std::string& path, size_t batch = 4096,
                     laz::LayerChoice layers = laz::LayerChoice::kAll) {
  LasRecordReader r(file_source(path), layers);
  Records out{r.header(), r.crs(), {}};
  std::vector<uint8_t> buf(batch * r.header().record_length);
  for (size_t n; (n = r.read(buf.data(), batch)) > 0;)
    out.bytes.insert(out.bytes.end(), buf.begin(), buf.begin() + n * r.header().record_length);
  return out;
}

// The field of a LAS record at a byte offset (formats 0-5 and 6-10 layouts),
// to say which field differs.
std::string field_at(uint8_t format, size_t at) {
  struct Field {
    size_t end;
    const char* name;
  };
  static const Field legacy[] = {
      {4, "X"},      {8, "Y"},           {12, "Z"},         {14, "intensity"},   {15, "return/flags"},
      {16, "class"}, {17, "scan angle"}, {18, "user data"}, {20, "point source"}};
  static const Field modern[] = {{4, "X"},           {8, "Y"},
                                 {12, "Z"},          {14, "intensity"},
                                 {15, "returns"},    {16, "flags/channel"},
                                 {17, "class"},      {18, "user data"},
                                 {20, "scan angle"}, {22, "point source"},
                                 {30, "GPS time"}};
  const bool f14 = format >= kLasFirstFormat14;
  for (const Field& f : f14 ? std::vector<Field>(std::begin(modern), std::end(modern))
                            : std::vector<Field>(std::begin(legacy), std::end(legacy)))
    if (at < f.end) return f.name;
  const bool gps = f14 || format == 1 || format == 3 || format == 4 || format == 5;
  if (!f14 && gps && at < 28) return "GPS time";
  return "colour or extra bytes (byte " + std::to_string(at) + ")";
}

struct Twin {
  const char* laz;
  const char* las;
  uint64_t points;
};

const Twin kTwins[] = {
    {"simple.laz", "simple.las", 1065},
    {"simple-compressor-1.laz", "simple.las", 1065},
    {"basefile-laszip.laz", "basefile.las", 1065},
    {"basefile-laszip-padding.laz", "basefile.las", 1065},
    {"basefile-liblas.laz", "basefile.las", 1065},
    {"autzen_trim.laz", "autzen_trim.las", 110000},
    {"point10.laz", "point10.las", 1065},
    {"point-time.laz", "point-time.las", 1065},
    {"point-color.laz", "point-color.las", 1065},
    {"point-time-color.laz", "point-time-color.las", 1065},
    {"extra-bytes.laz", "extra-bytes.las", 1065},
    {"point-version-1-point-wise.laz", "point-version-1-point-wise.las", 11781},
    {"1815.laz", "1815.las", 1247},
    {"no-points-1.3.laz", "no-points-1.3.las", 0},
    {"1_4_w_evlr.laz", "1_4_w_evlr.las", 1000},
};

// The fields both COPC (format 7) and its format-3 twin carry, in metres
// to the centimetre (their offsets differ).
using PointKey =
    std::tuple<int64_t, int64_t, int64_t, uint16_t, int, int, int, uint64_t, uint16_t, uint16_t, uint16_t>;

uint16_t u16(const uint8_t* p) { return static_cast<uint16_t>(p[0] | (p[1] << 8)); }
uint64_t u64(const uint8_t* p) {
  uint64_t v;
  std::memcpy(&v, p, sizeof v);
  return v;
}

PointKey point_key(const Records& r, size_t i) {
  const uint8_t* p = r.at(i);
  double xyz[3];
  las_record_xyz(r.header, p, xyz);
  const bool f14 = r.header.point_format >= kLasFirstFormat14;
  const int ret = f14 ? p[14] & 0x0F : p[14] & 0x07;
  const int nret = f14 ? p[14] >> 4 : (p[14] >> 3) & 0x07;
  const size_t gps_at = f14 ? 22 : 20, rgb_at = f14 ? 30 : 28;
  return {std::llround(xyz[0] * 100),
          std::llround(xyz[1] * 100),
          std::llround(xyz[2] * 100),
          u16(p + 12),
          ret,
          nret,
          las_record_class(r.header, p),
          u64(p + gps_at),
          u16(p + rgb_at),
          u16(p + rgb_at + 2),
          u16(p + rgb_at + 4)};
}

std::map<PointKey, int> multiset(const Records& r) {
  std::map<PointKey, int> m;
  for (size_t i = 0; i < r.count(); ++i) ++m[point_key(r, i)];
  return m;
}

}  // namespace

TEST_CASE("every LAZ twin decodes to the point records of its LAS twin, field by field") {
  if (!laz_samples_present()) return;
  for (const Twin& t : kTwins) {
    INFO(t.laz);
    const Records laz = read_records(kLaz + "/twins/" + t.laz);
    const Records las = read_records(kLaz + "/twins/" + t.las);
    CHECK(laz.header.compressed);
    CHECK_FALSE(las.header.compressed);
    REQUIRE(laz.header.record_length == las.header.record_length);
    CHECK(laz.header.point_format == las.header.point_format);
    REQUIRE(laz.count() == t.points);
    REQUIRE(las.count() == t.points);
    size_t differing = 0;
    for (size_t i = 0; i < laz.count() && differing < 5; ++i) {
      const auto* a = laz.at(i);
      const auto* b = las.at(i);
      for (size_t k = 0; k < laz.header.record_length; ++k)
        if (a[k] != b[k]) {
          ++differing;
          FAIL_CHECK("point " << i << ": " << field_at(laz.header.point_format, k) << " differs");
          break;
        }
    }
    CHECK(differing == 0);
  }
}

TEST_CASE("COPC files read as the LAZ files they are: the points of simple-rgb.las in another order") {
  if (!laz_samples_present()) return;
  const Records las = read_records(kLaz + "/twins/simple-rgb.las");
  const auto expected = multiset(las);
  for (const char* copc : {"simple-rgb.copc.laz", "simple-rgb-paged.copc.laz"}) {
    INFO(copc);
    const Records r = read_records(kLaz + "/twins/" + copc);
    CHECK(r.header.point_format == 7);
    REQUIRE(r.count() == las.count());
    CHECK(multiset(r) == expected);
    bool same_order = true;
    for (size_t i = 0; i < r.count() && same_order; ++i) same_order = point_key(r, i) == point_key(las, i);
    CHECK_FALSE(same_order);  // a COPC file orders its points by octree node
    CHECK(r.crs.source == "wkt");
    CHECK(r.crs.describe() == "EPSG:2991+6360");  // a compound WKT whose parts carry their EPSG IDs
  }
}

TEST_CASE("the format-8 LAZ file without a twin agrees with its header: count, bounds, points by return") {
  if (!laz_samples_present()) return;
  const Records r = read_records(kLaz + "/no-twin/format8-nir-extrabytes.laz");
  CHECK(r.header.point_format == 8);
  CHECK(r.header.record_length == 41);  // 38 + 3 extra bytes
  REQUIRE(r.count() == r.header.point_count);
  CHECK(r.count() == 37805);
  std::vector<uint64_t> by_return(15, 0);
  for (size_t i = 0; i < r.count(); ++i) {
    double xyz[3];
    las_record_xyz(r.header, r.at(i), xyz);
    for (int a = 0; a < 3; ++a) {
      const double slack = 0.5 * r.header.scale[a];
      REQUIRE(xyz[a] >= r.header.min[a] - slack);
      REQUIRE(xyz[a] <= r.header.max[a] + slack);
    }
    const uint8_t ret = las_record_return(r.header, r.at(i));
    REQUIRE(ret >= 1);
    ++by_return[ret - 1];
  }
  for (int k = 0; k < 15; ++k) CHECK(by_return[k] == r.header.points_by_return[k]);
  CHECK(by_return[0] == 31373);
  CHECK(r.crs.describe() == "EPSG:2154");  // RGF93 / Lambert-93: the WKT's own ID
}

TEST_CASE("LAS 1.4 LAZ read for the pipeline: x y z, returns and class as whole, the other layers unread") {
  if (!laz_samples_present()) return;
  constexpr size_t kIntensityAt = 12, kReturnsAt = 14, kClassAt = 16;
  for (const char* name : {"twins/1_4_w_evlr.laz", "twins/simple-rgb.copc.laz",
                           "twins/simple-rgb-paged.copc.laz", "no-twin/format8-nir-extrabytes.laz"}) {
    INFO(name);
    const Records whole = read_records(kLaz + "/" + name);
    const Records part = read_records(kLaz + "/" + name, 4096, laz::LayerChoice::kPipeline);
    REQUIRE(whole.header.point_format >= kLasFirstFormat14);
    REQUIRE(part.count() == whole.count());
    REQUIRE(part.count() > 0);
    size_t kept_differ = 0, intensity_differ = 0;
    for (size_t i = 0; i < whole.count(); ++i) {
      const uint8_t* a = whole.at(i);
      const uint8_t* b = part.at(i);
      if (std::memcmp(a, b, kIntensityAt) != 0 || a[kReturnsAt] != b[kReturnsAt] ||
          a[kClassAt] != b[kClassAt])
        ++kept_differ;
      if (std::memcmp(a + kIntensityAt, b + kIntensityAt, 2) != 0) ++intensity_differ;
    }
    CHECK(kept_differ == 0);
    CHECK(intensity_differ > 0);  // the intensity layer was skipped: it holds each chunk's first value
  }
  // Formats 0-5 interleave every field in one stream: decoded whole either way.
  const Records whole = read_records(kLaz + "/twins/autzen_trim.laz");
  const Records part = read_records(kLaz + "/twins/autzen_trim.laz", 4096, laz::LayerChoice::kPipeline);
  CHECK(part.bytes == whole.bytes);
}

TEST_CASE("each broken LAZ file is refused with a message naming what is wrong and the file") {
  if (!laz_samples_present()) return;
  // broken_size.laz and broken_version.laz are byte-identical (both carry
  // item version 6): they get the same message.
  const std::pair<const char*, const char*> broken[] = {
      {"broken_coder.laz", "coder 15"}, {"broken_compressor.laz", "compressor 16"},
      {"broken_type.laz", "type 22"},   {"broken_version.laz", "version 6"},
      {"broken_size.laz", "version 6"},
  };
  for (const auto& [file, what] : broken) {
    INFO(file);
    const std::string path = kLaz + "/broken/" + file;
    std::string message;
    try {
      auto src = open_point_source(path);
      std::vector<double> xyz(3 * 1024);
      while (src->read(xyz.data(), 1024) > 0) {
      }
    } catch (const CloudError& e) {
      message = e.what();
    }
    CHECK(message.find(what) != std::string::npos);
    CHECK(message.find("LAZ") != std::string::npos);
    CHECK(message.find(file) != std::string::npos);
    LasCloud cloud;
    std::string error;
    std::string bytes((std::istreambuf_iterator<char>(std::ifstream(path, std::ios::binary).rdbuf())), {});
    CHECK_FALSE(parse_las(bytes, &cloud, &error));
    CHECK(error.find(what) != std::string::npos);
    CHECK(cloud.xyz.empty());
  }
}

TEST_CASE("a CRS is read from every CRS sample; the malformed GeoKey directory reads as its one valid key") {
  if (!laz_samples_present()) return;
  struct Expect {
    const char* file;
    const char* describe;
    const char* source;
  };
  const Expect expected[] = {
      {"autzen-utm10.las", "EPSG:26910", "geokeys"},  // LAS 1.2: the liblas WKT record is not the CRS
      {"utm17.las", "EPSG:32617", "geokeys"},
      {"epsg_4326.las", "EPSG:4326", "geokeys"},
      {"file_with_both_wkt_and_geotiff_vlrs.las", "NAD83_2011_Nebraska_ft", "wkt"},  // the WKT bit decides
      {"bad-geotiff-keys.las", "EPSG:32617", "geokeys"},
  };
  for (const Expect& e : expected) {
    INFO(e.file);
    const CloudHeader h = read_cloud_header(kLaz + "/crs/" + e.file);
    CHECK(h.crs.known());
    CHECK(h.crs.describe() == e.describe);
    CHECK(h.crs.source == e.source);
  }
  // bad-geotiff-keys.las: its directory counts 8 keys, the last 4 all zero;
  // its one CRS key (ProjectedCSTypeGeoKey 3072 = 32617) stands, the blank
  // entries are named in a warning and nothing else is invented.
  const CloudHeader bad = read_cloud_header(kLaz + "/crs/bad-geotiff-keys.las");
  CHECK(bad.crs.vertical_epsg == 0);
  CHECK(bad.crs.wkt.empty());
  REQUIRE(bad.crs.warnings.size() == 1);
  CHECK(bad.crs.warnings[0].find("blank") != std::string::npos);
  const CloudHeader both = read_cloud_header(kLaz + "/crs/file_with_both_wkt_and_geotiff_vlrs.las");
  CHECK(both.crs.horizontal_epsg == 32104);  // the GeoKeys are kept beside the WKT
  CHECK(read_cloud_header(kLaz + "/twins/1815.laz").crs.describe() == "EPSG:6580+5703");
}

TEST_CASE("chunked reading gives the same points for chunks of 1, 7, 4096 and the whole file") {
  if (!laz_samples_present()) return;
  for (const char* file : {"twins/autzen_trim.laz", "twins/simple-rgb.copc.laz", "twins/1_4_w_evlr.laz",
                           "twins/simple-compressor-1.laz", "twins/autzen_trim.las"}) {
    INFO(file);
    std::vector<std::vector<double>> runs;
    for (size_t chunk : {size_t{1}, size_t{7}, size_t{4096}, size_t{0}}) {
      auto src = open_point_source(kLaz + "/" + file);
      const size_t step = chunk == 0 ? static_cast<size_t>(src->header().point_count) : chunk;
      std::vector<double> all, buf(3 * step);
      for (size_t n; (n = src->read(buf.data(), step)) > 0;) {
        CHECK(n <= step);
        all.insert(all.end(), buf.begin(), buf.begin() + 3 * n);
      }
      CHECK(all.size() == 3 * src->header().point_count);
      runs.push_back(std::move(all));
    }
    for (size_t i = 1; i < runs.size(); ++i) CHECK(runs[i] == runs[0]);
  }
  // The LAZ tile and its LAS twin give the same coordinates.
  std::vector<double> laz, las;
  std::string error;
  REQUIRE(spinhash::host::test::try_read_cloud(kLaz + "/twins/autzen_trim.laz", &laz, &error));
  REQUIRE(spinhash::host::test::try_read_cloud(kLaz + "/twins/autzen_trim.las", &las, &error));
  CHECK(laz == las);
}

TEST_CASE("a LAZ header is read without its points: a file cut after its VLRs still gives its header") {
  if (!laz_samples_present()) return;
  const CloudHeader h = read_cloud_header(kLaz + "/twins/autzen_trim.laz");
  CHECK(h.format == "laz");
  CHECK(h.point_count == 110000);
  CHECK(h.las_point_format == 3);
  CHECK(h.las_version[1] == 2);
  CHECK(h.bounds_known);
  CHECK(h.max[0] > h.min[0]);
  // The header and VLRs alone (points and chunk table cut off).
  std::ifstream in(kLaz + "/twins/autzen_trim.laz", std::ios::binary);
  std::string head(2200, '\0');
  in.read(head.data(), static_cast<std::streamsize>(head.size()));
  const auto cut = std::filesystem::temp_directory_path() / "spinhash_laz_header_only.laz";
  std::ofstream(cut, std::ios::binary) << head;
  const CloudHeader ch = read_cloud_header(cut.string());
  CHECK(ch.point_count == 110000);
  auto src = open_point_source(cut.string());
  std::vector<double> xyz(3 * 16);
  std::string message;
  try {
    src->read(xyz.data(), 16);
  } catch (const CloudError& e) {
    message = e.what();
  }
  CHECK(message.find("chunk table") != std::string::npos);
  std::filesystem::remove(cut);
}

TEST_CASE("truncated and corrupted LAZ data is refused with a message, never a crash") {
  if (!laz_samples_present()) return;
  std::ifstream in(kLaz + "/twins/point-time-color.laz", std::ios::binary);
  const std::string good((std::istreambuf_iterator<char>(in)), {});
  LasCloud cloud;
  std::string error;
  REQUIRE_MESSAGE(parse_las(good, &cloud, &error), error);
  // Cut inside the points: the chunk table (at the end) is gone.
  CHECK_FALSE(parse_las(good.substr(0, good.size() / 2), &cloud, &error));
  CHECK(error.find("LAZ") != std::string::npos);
  // Every byte of the compressed points flipped in turn (a sample of them):
  // a clean refusal or points, never a crash.
  for (size_t at = 400; at < good.size(); at += 97) {
    std::string bad = good;
    bad[at] = static_cast<char>(bad[at] ^ 0x5A);
    if (!parse_las(bad, &cloud, &error)) CHECK(!error.empty());
  }
}

namespace {

// LASzip's streaming median of five, its insertions spelled out branch by
// branch: the reference the decoder's min/max form must follow.
struct ReferenceMedian5 {
  int32_t x[5] = {0, 0, 0, 0, 0};
  bool high = true;
  void add(int32_t v) {
    if (high) {
      if (v < x[2]) {
        x[4] = x[3];
        x[3] = x[2];
        if (v < x[0]) {
          x[2] = x[1];
          x[1] = x[0];
          x[0] = v;
        } else if (v < x[1]) {
          x[2] = x[1];
          x[1] = v;
        } else {
          x[2] = v;
        }
      } else {
        if (v < x[3]) {
          x[4] = x[3];
          x[3] = v;
        } else {
          x[4] = v;
        }
        high = false;
      }
    } else {
      if (x[2] < v) {
        x[0] = x[1];
        x[1] = x[2];
        if (x[4] < v) {
          x[2] = x[3];
          x[3] = x[4];
          x[4] = v;
        } else if (x[3] < v) {
          x[2] = x[3];
          x[3] = v;
        } else {
          x[2] = v;
        }
      } else {
        if (x[1] < v) {
          x[0] = x[1];
          x[1] = v;
        } else {
          x[0] = v;
        }
        high = true;
      }
    }
  }
};

}  // namespace

TEST_CASE("LAZ: the x/y predictor's median follows LASzip's insertions, ties and runs included") {
  laz::Median5 median;
  ReferenceMedian5 reference;
  uint32_t state = 12345u;
  for (int i = 0; i < 200000; ++i) {
    state = state * 1664525u + 1013904223u;
    // Small values (many ties), runs of one value, and the int32 extremes.
    int32_t v = static_cast<int32_t>(state >> 28) - 8;
    if (i % 97 < 5) v = 3;
    if (i % 1009 == 0) v = i % 2 == 0 ? INT32_MIN : INT32_MAX;
    if (i % 3 == 0) v = static_cast<int32_t>(state);
    median.add(v);
    reference.add(v);
    REQUIRE(median.get() == reference.x[2]);
  }
}
