// Runs the built spinhash command (SPINHASH_TEST_BINARY) with its output
// captured in a temporary folder, for the host tests of the command line.
#pragma once
#include <sys/wait.h>

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
