// The spinhash command on bad input: every failure gives a message on stderr
// and a non-zero exit (1 error, 2 bad arguments, 3 a query or check failed), recognize still
// writes its JSON line, and a failed build never clobbers a good database.
// Runs the built binary (SPINHASH_TEST_BINARY) on small temporary files.
#include <doctest/doctest.h>

#include <cstddef>
#include <cstring>
#include <filesystem>
#include <string>
#include <vector>

#include "cli_runner.hpp"
#include "geometry_test_support.hpp"
#include "spinhash/blob_format.hpp"
#include "spinhash/status.hpp"

namespace fs = std::filesystem;
using spinhash::host::test::read_bytes;
using spinhash::host::test::TempDir;
using spinhash::host::test::write_bytes;

namespace {

constexpr int kExitOk = 0;
constexpr int kExitError = 1;
constexpr int kExitUsage = 2;
constexpr int kExitCheckFailed = 3;

using Run = spinhash::host::test::CliRun;
using spinhash::host::test::contains;

// Two generated vehicles, their database and a small scan, made once.
struct Fixture {
  TempDir dir{"cli-errors"};
  std::string meshes = dir.file("meshes");
  std::string good_db = dir.file("good.shdb");
  std::string query = dir.file("view.ply");
  std::string good_bytes;

  Run run(const std::string& args) const { return spinhash::host::test::run_spinhash(dir, args); }
  std::string q(const std::string& path) const { return spinhash::host::test::shell_quoted(path); }

  Fixture() {
    REQUIRE(run("generate --count 2 -o " + q(meshes)).exit_code == kExitOk);
    REQUIRE(run("build --quiet --no-calibration -o " + q(good_db) + " " + q(meshes)).exit_code == kExitOk);
    const std::string mesh = fs::directory_iterator(meshes)->path().string();
    REQUIRE(run("scan " + q(mesh) + " -o " + q(query) + " --views 2 --spacing 0.08 --seed 3").exit_code ==
            kExitOk);
    good_bytes = read_bytes(good_db);
    REQUIRE(!good_bytes.empty());
  }
};

const Fixture& fx() {
  static const Fixture f;
  return f;
}

// Bad model inputs, by name, with their content ("" with is_dir: a directory).
struct BadInput {
  const char* name;
  const char* content;
  bool is_dir;
};
const BadInput kBadInputs[] = {
    {"garbage.obj", "this is not a mesh\x01\x02", false},
    {"empty.obj", "", false},
    {"point.obj", "v 0 0 0\nv 0 0 0\nv 0 0 0\nf 1 2 3\n", false},  // zero area
    {"line.obj", "v 0 0 0\nv 1 0 0\nv 2 0 0\nf 1 2 3\n", false},   // collinear: zero area
    {"nomeshes", "", true},                                        // holds only a text file
    {"nan.obj", "v nan 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n", false},
    {"index.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 9\n", false},         // a face past the vertices
    {"huge.obj", "v 0 0 0\nv 1e30 0 0\nv 0 1e30 0\nf 1 2 3\n", false},    // far too many rays to scan
    {"tiny.obj", "v 0 0 0\nv 0.001 0 0\nv 0 0.001 0\nf 1 2 3\n", false},  // smaller than a ray step
};

std::string make_bad_input(const TempDir& dir, const BadInput& b) {
  const std::string path = dir.file(b.name);
  if (b.is_dir) {
    fs::create_directories(path);
    write_bytes(path + "/readme.txt", "no meshes here\n");
  } else {
    write_bytes(path, b.content);
  }
  return path;
}

}  // namespace

TEST_CASE("the fixture's good path: build, verify and recognize succeed") {
  const Fixture& f = fx();
  const Run v = f.run("verify " + f.q(f.good_db));
  CHECK(v.exit_code == kExitOk);
  const Run r = f.run("recognize --db " + f.q(f.good_db) + " " + f.q(f.query));
  CHECK(r.exit_code == kExitOk);
  REQUIRE(r.lines().size() == 1);
  CHECK(contains(r.out, "\"status\":\"ok\""));
}

TEST_CASE("build refuses meshes that won't load, empty or degenerate meshes and mesh-less directories") {
  const Fixture& f = fx();
  TempDir dir("cli-bad-mesh");
  for (const BadInput& b : kBadInputs) {
    CAPTURE(b.name);
    const std::string input = make_bad_input(dir, b);
    const std::string out = dir.file("new.shdb");
    const Run r = f.run("build --quiet --no-calibration -o " + f.q(out) + " " + f.q(input));
    CHECK(r.exit_code == kExitError);
    CHECK(contains(r.err, fs::path(b.name).stem().string()));  // the file or the model it names
    CHECK_FALSE(fs::exists(out));
  }
  const Run missing = f.run("build --quiet --no-calibration -o " + f.q(dir.file("x.shdb")) + " " +
                            f.q(dir.file("missing.obj")));
  CHECK(missing.exit_code == kExitError);
  CHECK(contains(missing.err, "missing.obj"));
}

TEST_CASE("a failed build never clobbers an existing good database") {
  const Fixture& f = fx();
  TempDir dir("cli-clobber");
  const std::string target = dir.file("db.shdb");
  for (const BadInput& b : kBadInputs) {
    CAPTURE(b.name);
    write_bytes(target, f.good_bytes);
    const std::string input = make_bad_input(dir, b);
    // The good meshes first, so loading gets going before the bad input fails.
    const Run r =
        f.run("build --quiet --no-calibration -o " + f.q(target) + " " + f.q(f.meshes) + " " + f.q(input));
    CHECK(r.exit_code == kExitError);
    CHECK(read_bytes(target) == f.good_bytes);
  }
  for (const auto& e : fs::directory_iterator(dir.path()))  // no temporaries left behind
    CHECK_FALSE(contains(e.path().filename().string(), ".tmp"));
}

TEST_CASE("outputs that cannot be written are errors with a message") {
  const Fixture& f = fx();
  TempDir dir("cli-unwritable");
  const std::string file = dir.file("plain-file");
  write_bytes(file, "x");
  const std::string under_file = file + "/out";  // a path through a regular file
  struct Case {
    const char* what;
    std::string args;
  };
  const Case cases[] = {
      {"build into a missing directory",
       "build --quiet --no-calibration -o " + f.q(dir.file("no/such/dir/db.shdb")) + " " + f.q(f.meshes)},
      {"build under a file",
       "build --quiet --no-calibration -o " + f.q(under_file + ".shdb") + " " + f.q(f.meshes)},
      {"build onto a directory",
       "build --quiet --no-calibration -o " + f.q(dir.path().string()) + " " + f.q(f.meshes)},
      {"scan under a file",
       "scan " + f.q(fs::directory_iterator(f.meshes)->path().string()) + " -o " + f.q(under_file + ".ply")},
      {"generate under a file", "generate --count 1 -o " + f.q(under_file)},
  };
  for (const Case& k : cases) {
    CAPTURE(k.what);
    const Run r = f.run(k.args);
    CHECK(r.exit_code == kExitError);
    CHECK_FALSE(r.err.empty());
  }
  CHECK(read_bytes(file) == "x");
}

TEST_CASE("recognize: malformed query files give an 'unreadable' JSON line each and exit 3") {
  const Fixture& f = fx();
  TempDir dir("cli-bad-ply");
  const std::string xyz3 = "property float x\nproperty float y\nproperty float z\n";
  struct Case {
    const char* name;
    std::string content;
  };
  const Case cases[] = {
      {"truncated.ply", "ply\nformat binary_little_endian 1.0\nelement vertex 4\n" + xyz3 + "end_header\n" +
                            std::string("\x00\x00\x80\x3f\x00\x00", 6)},
      {"fewer.ply", "ply\nformat ascii 1.0\nelement vertex 5\n" + xyz3 + "end_header\n1 2 3\n4 5 6\n"},
      {"more.ply", "ply\nformat ascii 1.0\nelement vertex 1\n" + xyz3 + "end_header\n1 2 3\n4 5 6\n"},
      {"negative.ply", "ply\nformat ascii 1.0\nelement vertex -3\n" + xyz3 + "end_header\n"},
      {"huge.ply",
       "ply\nformat binary_big_endian 1.0\nelement vertex 18446744073709551615\n" + xyz3 + "end_header\n"},
      {"type.ply",
       "ply\nformat ascii 1.0\nelement vertex 1\nproperty float128 x\nproperty float y\n"
       "property float z\nend_header\n1 2 3\n"},
      {"noz.ply",
       "ply\nformat ascii 1.0\nelement vertex 1\nproperty float x\nproperty float y\nend_header\n1 2\n"},
      {"format.ply", "ply\nformat binary_middle_endian 1.0\nelement vertex 0\n" + xyz3 + "end_header\n"},
      {"noend.ply", "ply\nformat ascii 1.0\nelement vertex 1\n" + xyz3},
      {"short.xyz", "1 2\n3 4 5\n"},
      {"empty.xyz", ""},
  };
  for (const Case& k : cases) {
    CAPTURE(k.name);
    const std::string path = dir.file(k.name);
    write_bytes(path, k.content);
    const Run r = f.run("recognize --db " + f.q(f.good_db) + " " + f.q(path));
    CHECK(r.exit_code == kExitCheckFailed);
    REQUIRE(r.lines().size() == 1);
    const std::string stem = fs::path(k.name).stem().string();
    CHECK(contains(r.out, "{\"query\":\"" + stem + "\",\"status\":\"unreadable\""));
    CHECK(contains(r.err, k.name));
  }
}

TEST_CASE("recognize: a missing query among good ones keeps one line per query and exits 3") {
  const Fixture& f = fx();
  const Run r = f.run("recognize --db " + f.q(f.good_db) + " " + f.q(f.query) + " " +
                      f.q(f.dir.file("absent.ply")) + " " + f.q(f.query));
  CHECK(r.exit_code == kExitCheckFailed);
  const std::vector<std::string> lines = r.lines();
  REQUIRE(lines.size() == 3);
  CHECK(contains(lines[0], "\"status\":\"ok\""));
  CHECK(contains(lines[1], "{\"query\":\"absent\",\"status\":\"unreadable\""));
  CHECK(contains(lines[2], "\"status\":\"ok\""));
  CHECK(contains(r.err, "absent.ply"));
}

TEST_CASE("recognize: empty and all-NaN clouds are reported in JSON and exit 3") {
  const Fixture& f = fx();
  TempDir dir("cli-empty-cloud");
  const std::string header = "ply\nformat ascii 1.0\nelement vertex ";
  const std::string xyz3 = "\nproperty float x\nproperty float y\nproperty float z\nend_header\n";
  write_bytes(dir.file("none.ply"), header + "0" + xyz3);
  write_bytes(dir.file("nan.ply"), header + "2" + xyz3 + "nan 2 3\n1 inf 3\n");
  const Run none = f.run("recognize --db " + f.q(f.good_db) + " " + f.q(dir.file("none.ply")));
  CHECK(none.exit_code == kExitCheckFailed);
  CHECK(contains(none.out, "\"status\":\"empty_cloud\""));
  const Run nan = f.run("recognize --db " + f.q(f.good_db) + " " + f.q(dir.file("nan.ply")));
  CHECK(nan.exit_code == kExitCheckFailed);
  CHECK(contains(nan.out, "\"status\":\"empty_cloud\""));
  CHECK(contains(nan.out, "\"points_nonfinite\":2"));
}

TEST_CASE("verify, info and recognize on a corrupt database fail with the status name") {
  const Fixture& f = fx();
  TempDir dir("cli-corrupt");
  using spinhash::Status;
  std::string flipped = f.good_bytes;
  flipped[flipped.size() - 10] ^= 0x01;  // inside the last section: its CRC no longer matches
  std::string magic = f.good_bytes;
  magic[0] = 'X';
  // A format-1 header: the version is checked before the header CRC. The
  // fixture's blob is in native byte order.
  std::string v1 = f.good_bytes;
  const uint32_t format1 = 1;
  std::memcpy(&v1[offsetof(spinhash::blob::Header, version)], &format1, sizeof format1);
  // A format-4 header: a blob without the calibration section.
  std::string v4 = f.good_bytes;
  const uint32_t format4 = 4;
  std::memcpy(&v4[offsetof(spinhash::blob::Header, version)], &format4, sizeof format4);
  struct Case {
    const char* name;
    std::string bytes;
    Status status;
  };
  const Case cases[] = {
      {"flipped.shdb", flipped, Status::kBlobSectionChecksum},
      {"truncated.shdb", f.good_bytes.substr(0, f.good_bytes.size() / 2), Status::kBlobTruncated},
      {"magic.shdb", magic, Status::kBlobBadMagic},
      {"format1.shdb", v1, Status::kBlobUnsupportedVersion},
      {"format4.shdb", v4, Status::kBlobUnsupportedVersion},
  };
  for (const Case& k : cases) {
    CAPTURE(k.name);
    const std::string path = dir.file(k.name);
    write_bytes(path, k.bytes);
    for (const std::string& cmd :
         {"verify " + f.q(path), "info " + f.q(path), "recognize --db " + f.q(path) + " " + f.q(f.query)}) {
      CAPTURE(cmd);
      const Run r = f.run(cmd);
      CHECK(r.exit_code == kExitError);
      CHECK(contains(r.err, spinhash::status_name(k.status)));
      CHECK(r.out.find("\"status\":\"ok\"") == std::string::npos);
    }
  }
  // The older format says which it is and how to get the current one.
  const Run old = f.run("info " + f.q(dir.file("format1.shdb")));
  CHECK(contains(old.err,
                 "format 1; this spinhash reads format 5: rebuild it from its meshes with `spinhash build`"));
  const Run uncalibrated = f.run("recognize --db " + f.q(dir.file("format4.shdb")) + " " + f.q(f.query));
  CHECK(contains(uncalibrated.err,
                 "format 4; this spinhash reads format 5: rebuild it from its meshes with `spinhash build`"));
  write_bytes(dir.file("empty.shdb"), "");
  const Run empty = f.run("verify " + f.q(dir.file("empty.shdb")));
  CHECK(empty.exit_code == kExitError);
  CHECK_FALSE(empty.err.empty());
}

namespace {

// Offsets of single bytes that Database::open refuses by its zero checks
// (docs/blob-format.md, "Alignment and padding"): every byte between the
// section table and the first payload (none when the table ends on a
// 64-byte boundary), the first and last padding bytes after each payload
// that has padding, and reserved fields.
std::vector<size_t> zero_fill_offsets(const std::string& blob) {
  using spinhash::blob::Header;
  using spinhash::blob::SectionEntry;
  Header h;
  std::memcpy(&h, blob.data(), sizeof h);
  std::vector<SectionEntry> table(h.section_count);
  std::memcpy(table.data(), blob.data() + sizeof h, table.size() * sizeof(SectionEntry));
  const size_t table_end = sizeof h + table.size() * sizeof(SectionEntry);
  size_t first = blob.size();
  for (const SectionEntry& e : table) first = e.offset < first ? static_cast<size_t>(e.offset) : first;
  std::vector<size_t> at;
  for (size_t i = table_end; i < first; ++i) at.push_back(i);
  for (const SectionEntry& e : table)  // the last payload ends the blob: no padding after it
    if (e.size % spinhash::blob::kSectionAlignment != 0u && e.offset + e.size < blob.size()) {
      const size_t end = static_cast<size_t>(e.offset + e.size), aligned = (end / 64u + 1u) * 64u;
      at.push_back(end);
      at.push_back(aligned - 1u);
    }
  at.push_back(offsetof(Header, reserved));
  at.push_back(sizeof h + offsetof(SectionEntry, reserved2));
  return at;
}

}  // namespace

TEST_CASE("verify refuses a changed padding or reserved byte, as Database::open does") {
  const Fixture& f = fx();
  TempDir dir("cli-zero-fill");
  const std::vector<size_t> offsets = zero_fill_offsets(f.good_bytes);
  REQUIRE(offsets.size() >= 12u);
  const std::string path = dir.file("changed.shdb");
  for (size_t at : offsets) {
    CAPTURE(at);
    std::string changed = f.good_bytes;
    changed[at] ^= 0x01;
    write_bytes(path, changed);
    const Run r = f.run("verify " + f.q(path));
    CHECK(r.exit_code == kExitError);
    // The header's reserved bytes are under its CRC, which is checked first.
    const bool in_header = at < sizeof(spinhash::blob::Header) + sizeof(spinhash::blob::SectionEntry);
    CHECK(contains(r.err, spinhash::status_name(in_header ? spinhash::Status::kBlobHeaderChecksum
                                                          : spinhash::Status::kBlobNotZeroed)));
  }
  // The first padding byte: recognize and info refuse it too.
  std::string changed = f.good_bytes;
  changed[offsets[0]] ^= 0x80;
  write_bytes(path, changed);
  for (const std::string& cmd : {"info " + f.q(path), "recognize --db " + f.q(path) + " " + f.q(f.query)}) {
    CAPTURE(cmd);
    const Run r = f.run(cmd);
    CHECK(r.exit_code == kExitError);
    CHECK(contains(r.err, spinhash::status_name(spinhash::Status::kBlobNotZeroed)));
  }
}

TEST_CASE("bad command lines are refused with a message and exit 2; --help and --version exit 0") {
  const Fixture& f = fx();
  for (const std::string& args :
       {std::string("recognize ") + f.q(f.query), std::string("frobnicate"),
        "recognize --db " + f.q(f.good_db) + " --mode fastest " + f.q(f.query),
        "generate --count 0 -o " + f.q(f.dir.file("g")),
        "scene --db " + f.q(f.good_db) + " --picture-out " + f.q(f.dir.file("none")) + " " + f.q(f.query),
        "recognize --db " + f.q(f.good_db) + " --frobnicate " + f.q(f.query)}) {
    CAPTURE(args);
    const Run r = f.run(args);
    CHECK(r.exit_code == kExitUsage);  // one code, whatever CLI11's kind of parse error
    CHECK_FALSE(r.err.empty());
    CHECK(r.out.empty());
  }
  for (const char* args : {"--help", "--version", "scene --help"}) {
    CAPTURE(args);
    const Run r = f.run(args);
    CHECK(r.exit_code == kExitOk);
    CHECK_FALSE(r.out.empty());
  }
}
