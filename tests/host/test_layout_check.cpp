// scripts/check_layout.sh on a scratch repository: it passes a clean tree
// and fails, naming the file, on each kind of line or file it exists to keep
// out (development history, tuning-round citations, files over 1 MB), while
// a measure that merely looks like one passes. The planted words are put
// together at run time, so that this file passes the check itself.
#include <doctest/doctest.h>

#include <cstdlib>
#include <filesystem>
#include <string>

#include "cli_runner.hpp"

namespace {

namespace fs = std::filesystem;
using spinhash::host::test::contains;
using spinhash::host::test::read_bytes;
using spinhash::host::test::shell_quoted;
using spinhash::host::test::TempDir;
using spinhash::host::test::write_bytes;

struct Check {
  int exit_code = -1;
  std::string out;
};

// A git repository holding a copy of the check, the repository's
// .clang-format and one formatted source file.
class ScratchTree {
 public:
  ScratchTree() : dir_("layout-check") {
    fs::create_directories(dir_.path() / "scripts");
    fs::copy_file(SPINHASH_SOURCE_DIR "/scripts/check_layout.sh", dir_.path() / "scripts/check_layout.sh");
    fs::copy_file(SPINHASH_SOURCE_DIR "/.clang-format", dir_.path() / ".clang-format");
    write_bytes(dir_.file("main.cpp"), "int main() { return 0; }\n");
    REQUIRE(git("init -q") == 0);
    add("main.cpp");
  }
  // Writes `text` to `name` and has git track it.
  void put(const std::string& name, const std::string& text) {
    fs::create_directories((dir_.path() / name).parent_path());
    write_bytes(dir_.file(name), text);
    add(name);
  }
  Check run() const {
    const std::string out = dir_.file("check.txt");
    const std::string cmd = "bash " + shell_quoted(dir_.file("scripts/check_layout.sh")) + " </dev/null > " +
                            shell_quoted(out) + " 2>&1";
    const int raw = std::system(cmd.c_str());
    return Check{WIFEXITED(raw) ? WEXITSTATUS(raw) : -1, read_bytes(out)};
  }

 private:
  int git(const std::string& args) const {
    return std::system(
        ("git -C " + shell_quoted(dir_.path().string()) + " " + args + " >/dev/null 2>&1").c_str());
  }
  void add(const std::string& name) { REQUIRE(git("add -- " + shell_quoted(name)) == 0); }
  TempDir dir_;
};

const std::string kIssue = std::string("iss") + "ue";
const std::string kStop = std::string("st") + "op";

}  // namespace

TEST_CASE("check_layout passes a clean tree, and a measure that looks like a stop number") {
  ScratchTree tree;
  tree.put("docs/guide.md", "# Guide\n\nThe scan " + kStop + "s 0.4 m short of the box's front.\n");
  const Check c = tree.run();
  INFO(c.out);
  CHECK(c.exit_code == 0);
}

TEST_CASE("check_layout fails on an issue or stop number, naming the file and line") {
  for (const std::string& line :
       {"Fixed in " + kIssue + " 28.", "Tuned in " + kStop + " 31 (and later).",
        "See results/accuracy-" + kStop + "26/summary.md.", "Kept from " + kIssue + "28-cars."}) {
    ScratchTree tree;
    tree.put("docs/guide.md", "# Guide\n\n" + line + "\n");
    const Check c = tree.run();
    INFO(line, "\n", c.out);
    CHECK(c.exit_code != 0);
    CHECK(contains(c.out, "development history"));
    CHECK(contains(c.out, "docs/guide.md:3:"));
  }
}

TEST_CASE("check_layout fails on a citation of a results tuning round") {
  for (const std::string& line : {"// the margin (docs/results" + std::string(".md 11k)."),
                                  "// measured in section 9" + std::string("q.")}) {
    ScratchTree tree;
    tree.put("src/margin.hpp", line + "\n");
    const Check c = tree.run();
    INFO(line, "\n", c.out);
    CHECK(c.exit_code != 0);
    CHECK(contains(c.out, "src/margin.hpp:1:"));
  }
}

TEST_CASE("check_layout fails on a file named after a stop or an issue") {
  ScratchTree tree;
  tree.put("docs/results/accuracy-" + kStop + "26/summary.md", "# Accuracy\n");
  const Check c = tree.run();
  INFO(c.out);
  CHECK(c.exit_code != 0);
  CHECK(contains(c.out, "docs/results/accuracy-" + kStop + "26/summary.md"));
}

TEST_CASE("check_layout fails on a tracked file over 1 MB, and not on one of 1 MB") {
  ScratchTree tree;
  tree.put("data/fits.bin", std::string(1000000, '\x01'));
  const Check fits = tree.run();
  INFO(fits.out);
  CHECK(fits.exit_code == 0);
  tree.put("data/large.bin", std::string(1000001, '\x01'));
  const Check large = tree.run();
  INFO(large.out);
  CHECK(large.exit_code != 0);
  CHECK(contains(large.out, "1000001 data/large.bin"));
  CHECK_FALSE(contains(large.out, "data/fits.bin"));
}
