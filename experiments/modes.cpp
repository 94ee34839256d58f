#include "modes.hpp"

#include <algorithm>

#include "config/mode_name.hpp"

namespace spinhash::experiment {

bool parse_modes(const std::vector<std::string>& names, std::vector<Mode>* out, std::string* error) {
  const Mode all[] = {Mode::kBran, Mode::kSran, Mode::kSind};
  out->clear();
  for (const std::string& n : names) {
    auto it = std::find_if(std::begin(all), std::end(all), [&](Mode m) { return n == host::mode_name(m); });
    if (it == std::end(all)) {
      *error = "unknown mode '" + n + "' (bran, sran, sind)";
      return false;
    }
    if (std::find(out->begin(), out->end(), *it) == out->end()) out->push_back(*it);
  }
  if (out->empty()) {
    *error = "no mode given";
    return false;
  }
  return true;
}

}  // namespace spinhash::experiment
