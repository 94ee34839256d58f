// A CellGrid over a point set, with its memory, for the core's geometry tests.
#pragma once
#include <doctest/doctest.h>

#include <cstdint>
#include <vector>

#include "geometry/cell_grid.hpp"
#include "spinhash/arena.hpp"

namespace spinhash {
namespace test {

struct GridFixture {
  std::vector<unsigned char> memory;
  CellGrid grid;
  GridFixture(const std::vector<float>& pts, float cell) {
    const uint32_t n = static_cast<uint32_t>(pts.size() / 3);
    Arena counter;
    CellGrid sizing;
    sizing.carve(counter, n);
    memory.resize(counter.used() + 64);
    Arena arena(memory.data(), memory.size());
    REQUIRE(grid.carve(arena, n));
    grid.build(pts.data(), n, cell);
  }
};

}  // namespace test
}  // namespace spinhash
