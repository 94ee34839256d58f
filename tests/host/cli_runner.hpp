// Runs the built spinhash command (SPINHASH_TEST_BINARY) with its output
// captured in a temporary folder, for the host tests of the command line.
#pragma once
#include <sys/wait.h>

#include <doctest/doctest.h>

#include <cstdlib>
#include <string>
#include <vector>

#include "geometry_test_support.hpp"

namespace spinhash::host::test {

struct CliRun {
  int exit_code = -1;
  std::string out;
  std::string err;
  std::vector<std::string> lines() const {
    std::vector<std::string> v;
    size_t start = 0;
    for (size_t nl; (nl = out.find('\n', start)) != std::string::npos; start = nl + 1)
      v.push_back(out.substr(start, nl - start));
    return v;
  }
};

inline std::string shell_quoted(const std::string& path) { return "'" + path + "'"; }

// `args` are passed through the shell: quote paths with shell_quoted().
inline CliRun run_spinhash(const TempDir& dir, const std::string& args) {
  const std::string out = dir.file("stdout.txt"), err = dir.file("stderr.txt");
  const std::string cmd =
      "'" SPINHASH_TEST_BINARY "' " + args + " > " + shell_quoted(out) + " 2> " + shell_quoted(err);
  const int raw = std::system(cmd.c_str());
  CliRun r;
  r.exit_code = WIFEXITED(raw) ? WEXITSTATUS(raw) : -1;
  r.out = read_bytes(out);
  r.err = read_bytes(err);
  return r;
}

// `count` procedural vehicles (dir/fleet), their database without
// calibration (dir/fleet.shdb: built in seconds) and a tile of them
// (dir/scene.las, by `scan-scene` with `scan_args`); each command REQUIREd.
struct FleetScene {
  std::string fleet, db, scene;
};
inline FleetScene fleet_scene(const TempDir& dir, int count, const std::string& scan_args) {
  FleetScene f{dir.file("fleet"), dir.file("fleet.shdb"), dir.file("scene.las")};
  REQUIRE(run_spinhash(dir, "generate --count " + std::to_string(count) + " -o " + shell_quoted(f.fleet))
              .exit_code == 0);
  REQUIRE(run_spinhash(
              dir, "build --quiet --no-calibration -o " + shell_quoted(f.db) + " " + shell_quoted(f.fleet))
              .exit_code == 0);
  const CliRun s = run_spinhash(
      dir, "scan-scene " + shell_quoted(f.fleet) + " -o " + shell_quoted(f.scene) + " " + scan_args);
  REQUIRE_MESSAGE(s.exit_code == 0, s.err);
  return f;
}

inline bool contains(const std::string& text, const std::string& part) {
  return text.find(part) != std::string::npos;
}

// True when every line of `text` is one strict JSON object: valid UTF-8, no
// NaN or Infinity (Python's json module, told to refuse those constants).
inline bool strict_json_lines(const TempDir& dir, const std::string& text) {
  const std::string path = dir.file("json-lines.txt");
  write_bytes(path, text);
  const std::string cmd =
      "python3 -c 'import json,sys\n"
      "def bad(c): raise ValueError(c)\n"
      "lines = [l for l in open(sys.argv[1], \"rb\").read().split(b\"\\n\") if l]\n"
      "assert lines\n"
      "for l in lines: assert isinstance(json.loads(l.decode(\"utf-8\"), parse_constant=bad), dict)' " +
      shell_quoted(path) + " 2>&1";
  return std::system(cmd.c_str()) == 0;
}

}  // namespace spinhash::host::test
