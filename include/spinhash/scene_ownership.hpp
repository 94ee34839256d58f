// Which area reports an object: the one ownership rule of every scene path
// (a stream's windows, a tile's bands, a survey's tiles), the catalogue rule
// of lidR. An area is a half-open rectangle [min, max) on both axes; the
// object's centre decides. Areas that tile the plane (a lattice of window
// cores) give each centre exactly one owner; where a caller's areas overlap
// or leave gaps (tiles cut from the points' own bounds), the tie rule is the
// caller's order, and a centre in a gap goes to the nearest area within a
// tolerance.
#pragma once
#include <cstdint>

namespace spinhash {

struct OwnedArea {
  double min[2] = {0.0, 0.0};  // x (or s along track), y (or t across)
  double max[2] = {0.0, 0.0};
};

constexpr uint32_t kNoOwner = 0xFFFFFFFFu;

// true when min <= v < max on both axes.
bool area_holds(const OwnedArea& area, double x, double y) noexcept;

// The owner of the centre (x, y) among n areas in the caller's order: the
// first that holds it; else the nearest (distance to its closed rectangle)
// within `tolerance`, the first of equals; else kNoOwner.
uint32_t owner_of(const OwnedArea* areas, uint32_t n, double x, double y, double tolerance) noexcept;

}  // namespace spinhash
