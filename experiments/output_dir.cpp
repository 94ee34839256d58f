#include "output_dir.hpp"

#include <filesystem>
#include <fstream>
#include <iterator>

namespace spinhash::experiment {

std::string default_output_dir(const std::string& experiment) { return "out/" + experiment; }

bool make_output_dir(const std::string& dir, std::string* error) {
  std::error_code ec;
  std::filesystem::create_directories(dir, ec);
  if (ec) {
    *error = dir + ": " + ec.message();
    return false;
  }
  return true;
}

bool write_text(const std::string& path, const std::string& text, std::string* error) {
  std::ofstream f(path);
  f << text;
  f.close();
  if (!f) {
    *error = path + ": cannot write";
    return false;
  }
  return true;
}

std::string invoked_command_line() {
  std::ifstream f("/proc/self/cmdline", std::ios::binary);
  std::string raw((std::istreambuf_iterator<char>(f)), std::istreambuf_iterator<char>());
  std::string out, arg;
  bool first = true;
  for (char c : raw) {
    if (c != '\0') {
      arg += c;
      continue;
    }
    if (first) arg = std::filesystem::path(arg).filename().string();  // "spinhash", not the build path
    if (!first) out += ' ';
    out += arg.find_first_of(" \t'\"") == std::string::npos ? arg : "'" + arg + "'";
    arg.clear();
    first = false;
  }
  return out;
}

}  // namespace spinhash::experiment
