// The command line as a new user meets it: clouds from stdin,
// machine-readable info and verify, a version on every JSON line, valid JSON
// whatever the file names, builds that name every unreadable mesh, and the
// overlay and picture of one answer. Runs the built binary on two generated
// vehicles.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <string>
#include <vector>

#include "cli_runner.hpp"
#include "cloud/cloud_reader.hpp"
#include "cloud/ply_header.hpp"
#include "cloud_test_support.hpp"

namespace fs = std::filesystem;
using namespace spinhash::host::test;

namespace {

constexpr int kExitOk = 0, kExitError = 1, kExitUsage = 2;

struct Fixture {
  TempDir dir{"cli-papercuts"};
  std::string meshes = dir.file("meshes"), db = dir.file("two.shdb");
  std::string query = dir.file("van-00.q.ply"), pose = dir.file("van-00.pose");
  std::string version;

  CliRun run(const std::string& args) const { return run_spinhash(dir, args); }
  std::string q(const std::string& path) const { return shell_quoted(path); }

  Fixture() {
    REQUIRE(run("generate --count 2 -o " + q(meshes)).exit_code == kExitOk);
    REQUIRE(run("build --quiet --no-calibration -o " + q(db) + " " + q(meshes)).exit_code == kExitOk);
    const std::string mesh = meshes + "/" + fs::path(first_mesh()).filename().string();
    const CliRun scan =
        run("scan " + q(mesh) + " -o " + q(query) +
            " --noise 0.03 --seed 4 --random-pose --offset 431000 4020000 85 --pose-out " + q(pose));
    REQUIRE(scan.exit_code == kExitOk);
    const CliRun v = run("--version");
    REQUIRE(v.exit_code == kExitOk);
    version = v.out.substr(0, v.out.find('\n'));
    REQUIRE(!version.empty());
  }
  std::string first_mesh() const {
    std::vector<std::string> names;
    for (const auto& e : fs::directory_iterator(meshes)) names.push_back(e.path().string());
    std::sort(names.begin(), names.end());
    return names.front();
  }
  std::string model() const { return fs::path(first_mesh()).stem().string(); }
};

const Fixture& fx() {
  static const Fixture f;
  return f;
}

bool has_version(const Fixture& f, const std::string& line) {
  return contains(line, "\"version\":\"" + f.version + "\"");
}

}  // namespace

TEST_CASE("'-' reads a cloud from stdin in recognize and scene; its name in JSON is \"stdin\"") {
  const Fixture& f = fx();
  const CliRun r = f.run("recognize --top 1 --db " + f.q(f.db) + " - < " + f.q(f.query));
  INFO(r.err);
  CHECK(r.exit_code == kExitOk);
  REQUIRE(r.lines().size() == 1);
  CHECK(contains(r.lines()[0],
                 "{\"query\":\"stdin\",\"status\":\"ok\",\"ranking\":[{\"model\":\"" + f.model()));

  const CliRun s = f.run("scene --db " + f.q(f.db) + " - < " + f.q(f.query));
  INFO(s.err);
  CHECK(s.exit_code == kExitOk);
  REQUIRE(!s.lines().empty());
  for (const std::string& line : s.lines()) CHECK(contains(line, "{\"tile\":\"stdin\",\"object\":"));

  const CliRun twice = f.run("recognize --db " + f.q(f.db) + " - - < " + f.q(f.query));
  CHECK(twice.exit_code == kExitUsage);  // stdin can be read only once
  CHECK(contains(twice.err, "stdin"));
  const CliRun text = f.run("recognize --db " + f.q(f.db) + " - < /dev/null");
  CHECK(text.exit_code == 3);  // an empty stream is an unreadable query, not a crash
  CHECK(contains(text.out, "\"query\":\"stdin\",\"status\":\"unreadable\""));
}

TEST_CASE("info and verify --format json: one strict JSON object with the documented keys") {
  const Fixture& f = fx();
  const CliRun info = f.run("info --format json " + f.q(f.db));
  INFO(info.err);
  REQUIRE(info.exit_code == kExitOk);
  REQUIRE(info.lines().size() == 1);
  CHECK(strict_json_lines(f.dir, info.out));
  for (const char* key : {"\"models\":2", "\"features\":", "\"bytes\":", "\"fingerprint\":\"", "\"lsh\":{",
                          "\"model_list\":[{\"name\":\""})
    CHECK_MESSAGE(contains(info.out, key), key);
  CHECK(contains(info.out, f.model()));

  const CliRun verify = f.run("verify --quiet --queries 1 --format json " + f.q(f.db) + " " + f.q(f.meshes));
  INFO(verify.err);
  REQUIRE(verify.exit_code == kExitOk);
  REQUIRE(verify.lines().size() == 1);
  CHECK(strict_json_lines(f.dir, verify.out));
  CHECK(contains(verify.out, "\"integrity\":\"ok\""));
  CHECK(contains(verify.out, "\"scans\":2,\"hits\":2"));

  const CliRun plain = f.run("verify --format json " + f.q(f.db));
  CHECK(plain.exit_code == kExitOk);
  CHECK(strict_json_lines(f.dir, plain.out));
  CHECK(contains(plain.out, "\"scans\":0"));
  CHECK(f.run("info --format yaml " + f.q(f.db)).exit_code == kExitUsage);
}

TEST_CASE("every JSON line carries the version: recognize, scene, info, verify, unreadable queries") {
  const Fixture& f = fx();
  write_bytes(f.dir.file("garbage.ply"), "ply\nnonsense\n");
  const std::vector<std::string> commands = {
      "recognize --db " + f.q(f.db) + " " + f.q(f.query) + " " + f.q(f.dir.file("garbage.ply")),
      "scene --db " + f.q(f.db) + " " + f.q(f.query), "info --format json " + f.q(f.db),
      "verify --format json " + f.q(f.db)};
  for (const std::string& args : commands) {
    CAPTURE(args);
    const CliRun r = f.run(args);
    REQUIRE(!r.lines().empty());
    for (const std::string& line : r.lines()) CHECK(has_version(f, line));
    CHECK(strict_json_lines(f.dir, r.out));
  }
}

TEST_CASE("file names that are not UTF-8 still give valid JSON (U+FFFD for each bad byte)") {
  const Fixture& f = fx();
  const std::string odd = f.dir.file("van\xff\xfe.ply"), missing = f.dir.file("gone\xc3.ply");
  fs::copy_file(f.query, odd, fs::copy_options::overwrite_existing);
  const CliRun r = f.run("recognize --top 1 --db " + f.q(f.db) + " " + f.q(odd) + " " + f.q(missing));
  INFO(r.err);
  REQUIRE(r.lines().size() == 2);
  CHECK(strict_json_lines(f.dir, r.out));
  CHECK(contains(r.lines()[0], "{\"query\":\"van\xef\xbf\xbd\xef\xbf\xbd\",\"status\":\"ok\""));
  CHECK(contains(r.lines()[1], "\"status\":\"unreadable\""));
  CHECK(contains(r.lines()[1], "gone\xef\xbf\xbd.ply"));
  const CliRun s = f.run("scene --db " + f.q(f.db) + " " + f.q(odd));
  CHECK(strict_json_lines(f.dir, s.out));
}

TEST_CASE("build names every unreadable mesh at once and writes nothing") {
  const Fixture& f = fx();
  TempDir dir("cli-papercuts-build");
  write_bytes(dir.file("broken-a.obj"), "this is not a mesh\x01\x02");
  write_bytes(dir.file("broken-b.ply"), "ply\nformat ascii 1.0\nelement vertex 3\nend_header\n");
  write_bytes(dir.file("flat-c.obj"), "v 0 0 0\nv 1 0 0\nv 2 0 0\nf 1 2 3\n");
  const std::string out = dir.file("new.shdb");
  const CliRun r =
      f.run("build --quiet --no-calibration -o " + f.q(out) + " " + f.q(dir.file("broken-a.obj")) + " " +
            f.q(f.meshes) + " " + f.q(dir.file("broken-b.ply")) + " " + f.q(dir.file("flat-c.obj")));
  CHECK(r.exit_code == kExitError);
  for (const char* name : {"broken-a.obj", "broken-b.ply", "flat-c.obj"})
    CHECK_MESSAGE(contains(r.err, name), std::string(name));
  CHECK(contains(r.err, "3 of 5 meshes unreadable"));
  CHECK_FALSE(fs::exists(out));
}

TEST_CASE("build takes a generated binary PLY vehicle whose first body byte is a line end") {
  const Fixture& f = fx();
  TempDir dir("cli-papercuts-ply");
  const std::string meshes = dir.file("ply");
  REQUIRE(f.run("generate --count 1 --format ply -o " + f.q(meshes)).exit_code == kExitOk);
  const std::string mesh = fs::directory_iterator(meshes)->path().string();
  std::string bytes = read_bytes(mesh);
  const size_t body = bytes.find("end_header\n");
  REQUIRE(body != std::string::npos);
  bytes[body + 11] = '\n';  // the low byte of the first x: moves it by about 1e-7 of itself
  write_bytes(mesh, bytes);
  const CliRun r =
      f.run("build --quiet --no-calibration -o " + f.q(dir.file("ply.shdb")) + " " + f.q(meshes));
  INFO(r.err);
  CHECK(r.exit_code == kExitOk);  // Assimp 5.2.5: "mIndices[0] is out of range"
  CHECK(fs::exists(dir.file("ply.shdb")));
}

namespace {

// The overlay PLY: binary little-endian double x y z, uchar red green blue.
struct Overlay {
  std::vector<double> xyz;
  std::vector<int> colour;  // red channel per point: tells query from model
};

Overlay read_overlay(const std::string& path) {
  Overlay o;
  std::string bytes, error;
  REQUIRE_MESSAGE(spinhash::host::read_file(path, 1u << 28, &bytes, &error), error);
  spinhash::host::ply::Header h;
  REQUIRE_MESSAGE(spinhash::host::ply::parse_header(bytes, &h, &error), error);
  REQUIRE(h.format == spinhash::host::ply::Format::kBinaryLittleEndian);
  REQUIRE(h.elements.size() == 1);
  REQUIRE(h.elements[0].properties.size() == 6);
  constexpr size_t kStride = 3 * 8 + 3;
  REQUIRE(bytes.size() == h.data_offset + kStride * h.elements[0].count);
  for (uint64_t i = 0; i < h.elements[0].count; ++i) {
    const char* p = bytes.data() + h.data_offset + kStride * i;
    for (int a = 0; a < 3; ++a) {
      double v;
      std::memcpy(&v, p + 8 * a, 8);  // the test host is little-endian (x86-64)
      o.xyz.push_back(v);
    }
    o.colour.push_back(static_cast<unsigned char>(p[24]));
  }
  return o;
}

}  // namespace

TEST_CASE("recognize --overlay-out and --picture-out show the posed model over the query") {
  const Fixture& f = fx();
  const std::string overlay = f.dir.file("answer.ply"), picture = f.dir.file("answer.png");
  const CliRun r = f.run("recognize --top 1 --db " + f.q(f.db) + " --overlay-out " + f.q(overlay) +
                         " --picture-out " + f.q(picture) + " " + f.q(f.query));
  INFO(r.err);
  REQUIRE(r.exit_code == kExitOk);
  std::vector<double> query;
  std::string error;
  REQUIRE(spinhash::host::test::try_read_cloud(f.query, &query, &error));
  const Overlay o = read_overlay(overlay);
  const size_t n = o.colour.size(), nq = query.size() / 3;
  REQUIRE(n > nq + 50);  // the query and the model's stored points
  // The query's points first, unchanged (georeferenced), in one colour.
  for (size_t i = 0; i < nq; ++i) REQUIRE(o.xyz[3 * i] == query[3 * i]);
  // The model's points in another colour, posed onto the query: most lie within 0.2 m of a query point.
  size_t model_points = 0, close = 0;
  for (size_t i = nq; i < n; ++i) {
    CHECK(o.colour[i] != o.colour[0]);
    ++model_points;
    double best = 1e30;
    for (size_t j = 0; j < nq; j += 3) {
      const double dx = o.xyz[3 * i] - query[3 * j], dy = o.xyz[3 * i + 1] - query[3 * j + 1],
                   dz = o.xyz[3 * i + 2] - query[3 * j + 2];
      best = std::min(best, dx * dx + dy * dy + dz * dz);
    }
    close += best < 0.2 * 0.2 ? 1u : 0u;
  }
  CHECK(close > model_points / 3);  // the query sees 3 sides: about half the model's surface
  std::string png;
  REQUIRE(spinhash::host::read_file(picture, 1u << 26, &png, &error));
  CHECK(png.rfind("\x89PNG\r\n\x1a\n", 0) == 0);
  CHECK(png.size() > 10000);

  // Several queries: FILE-NAME.ply per query.
  const std::string second = f.dir.file("again.ply");
  fs::copy_file(f.query, second, fs::copy_options::overwrite_existing);
  const CliRun many = f.run("recognize --db " + f.q(f.db) + " --overlay-out " + f.q(f.dir.file("many.ply")) +
                            " " + f.q(f.query) + " " + f.q(second));
  CHECK(many.exit_code == kExitOk);
  CHECK(fs::exists(f.dir.file("many-van-00.q.ply")));
  CHECK(fs::exists(f.dir.file("many-again.ply")));
  CHECK(
      f.run("recognize --db " + f.q(f.db) + " --overlay-out " + f.q(f.dir.file("x.las")) + " " + f.q(f.query))
          .exit_code == kExitUsage);
}
