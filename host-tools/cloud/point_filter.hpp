// Which points of a LAS or LAZ file the readers leave out (one rule for
// `scene`, `recognize`, the survey and Python). Always: ASPRS classes 7
// (low point, noise) and 18 (high noise) and withheld points ("to be
// considered deleted"): a low noise point under the ground would pull the
// terrain down around it. Besides, the classes the user names
// (--drop-class): producers that put their artefacts, overlap or noise in a
// class of their own. Formats 0-5 hold classes 0-31, formats 6-10 0-255.
// PLY and text carry no class: nothing is left out of them.
#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <vector>

namespace spinhash::host {

constexpr uint8_t kLowNoiseClass = 7, kHighNoiseClass = 18;  // ASPRS, always left out
constexpr int kMaxLasClass = 255;

struct PointFilter {
  std::array<bool, kMaxLasClass + 1> named{};  // classes the user names

  bool drops(uint8_t c) const { return c == kLowNoiseClass || c == kHighNoiseClass || named[c]; }
  // The named classes besides 7 and 18, ascending.
  std::vector<int> extra_classes() const;
  // Every class left out, ascending (7 and 18 included).
  std::vector<int> classes() const;
};

// "65" or "65,66": adds the classes to *filter. False with *error for a
// value that is not a whole number in [0, 255].
bool add_drop_classes(const std::string& text, PointFilter* filter, std::string* error);

// The same from numbers (Python's drop_classes).
bool add_drop_classes(const std::vector<int>& classes, PointFilter* filter, std::string* error);

// "7,18,65": the classes a filter leaves out, for keys and task text.
std::string classes_text(const PointFilter& filter);

// What the commands say of the points left out (empty: none): the count
// and why ("the file marks as noise (ASPRS classes 7 and 18) or withheld",
// and the named classes).
std::string dropped_note(uint64_t points, const PointFilter& filter);

}  // namespace spinhash::host
