#include "cloud/point_filter.hpp"

#include <cerrno>
#include <cstdlib>

namespace spinhash::host {

std::vector<int> PointFilter::extra_classes() const {
  std::vector<int> v;
  for (int c = 0; c <= kMaxLasClass; ++c)
    if (named[static_cast<size_t>(c)] && c != kLowNoiseClass && c != kHighNoiseClass) v.push_back(c);
  return v;
}

std::vector<int> PointFilter::classes() const {
  std::vector<int> v;
  for (int c = 0; c <= kMaxLasClass; ++c)
    if (drops(static_cast<uint8_t>(c))) v.push_back(c);
  return v;
}

bool add_drop_classes(const std::string& text, PointFilter* filter, std::string* error) {
  PointFilter f = *filter;
  size_t at = 0;
  do {
    const size_t comma = text.find(',', at);
    const std::string item = text.substr(at, comma == std::string::npos ? std::string::npos : comma - at);
    char* end = nullptr;
    errno = 0;
    const long c = item.empty() ? -1 : std::strtol(item.c_str(), &end, 10);
    if (item.empty() || errno != 0 || *end != '\0' || c < 0 || c > kMaxLasClass) {
      *error = "\"" + item + "\" is not a LAS class: name whole numbers from 0 to " +
               std::to_string(kMaxLasClass) + ", separated by commas";
      return false;
    }
    f.named[static_cast<size_t>(c)] = true;
    at = comma == std::string::npos ? text.size() + 1 : comma + 1;
  } while (at <= text.size());
  *filter = f;
  return true;
}

bool add_drop_classes(const std::vector<int>& classes, PointFilter* filter, std::string* error) {
  for (int c : classes)
    if (c < 0 || c > kMaxLasClass) {
      *error = std::to_string(c) + " is not a LAS class (0 to " + std::to_string(kMaxLasClass) + ")";
      return false;
    }
  for (int c : classes) filter->named[static_cast<size_t>(c)] = true;
  return true;
}

std::string classes_text(const PointFilter& filter) {
  std::string s;
  for (int c : filter.classes()) s += (s.empty() ? "" : ",") + std::to_string(c);
  return s;
}

std::string dropped_note(uint64_t points, const PointFilter& filter) {
  if (points == 0) return {};
  std::string named;
  const std::vector<int> extra = filter.extra_classes();
  for (size_t i = 0; i < extra.size(); ++i)
    named += (i == 0 ? "" : i + 1 == extra.size() ? " or " : ", ") + std::to_string(extra[i]);
  return std::to_string(points) + " points the file marks as noise (ASPRS classes 7 and 18)" +
         (named.empty() ? " or withheld" : ", withheld or of class " + named + ", as asked") + ": left out";
}

}  // namespace spinhash::host
