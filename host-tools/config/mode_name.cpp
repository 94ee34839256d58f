#include "config/mode_name.hpp"

namespace spinhash::host {

const std::map<std::string, Mode>& mode_names() {
  static const std::map<std::string, Mode> names{
      {"bran", Mode::kBran}, {"sran", Mode::kSran}, {"sind", Mode::kSind}};
  return names;
}

const char* mode_name(Mode m) {
  for (const auto& [name, mode] : mode_names())
    if (mode == m) return name.c_str();
  return "?";
}

}  // namespace spinhash::host
