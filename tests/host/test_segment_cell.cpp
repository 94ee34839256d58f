// The segmentation cell a tile's density asks for (pipeline/segment_cell.hpp):
// the finest cell on dense tiles, doubled to the mean point spacing on
// sparse ones, at most twice, and never to a cell the window core is not a
// whole number of.
#include <doctest/doctest.h>

#include "pipeline/segment_cell.hpp"

using spinhash::pipeline::segment_cell_for_density;
using spinhash::pipeline::tile_density;

TEST_CASE("segment cell: the finest on dense tiles, the spacing on sparse ones, at most 4 times the finest") {
  constexpr double kCore = 32.0;  // the default window core
  CHECK(segment_cell_for_density(0.25f, 100.0, kCore) == 0.25f);
  CHECK(segment_cell_for_density(0.25f, 16.0, kCore) == 0.25f);  // spacing 0.25 m: the cell reaches it
  CHECK(segment_cell_for_density(0.25f, 15.0, kCore) == 0.5f);
  CHECK(segment_cell_for_density(0.25f, 8.0, kCore) == 0.5f);
  CHECK(segment_cell_for_density(0.25f, 4.0, kCore) == 0.5f);  // spacing 0.5 m
  CHECK(segment_cell_for_density(0.25f, 2.0, kCore) == 1.0f);
  CHECK(segment_cell_for_density(0.25f, 1e-6, kCore) == 1.0f);  // two doublings at most
  CHECK(segment_cell_for_density(0.5f, 1.0, kCore) == 1.0f);    // from a coarser finest cell
  CHECK(segment_cell_for_density(0.25f, 0.0, kCore) == 0.25f);  // unknown: kept
  CHECK(segment_cell_for_density(0.25f, -1.0, kCore) == 0.25f);
  // 32 m is not a whole number of 0.6 m cells: the doubling is not taken.
  CHECK(segment_cell_for_density(0.3f, 1.0, kCore) == 0.3f);
  CHECK(segment_cell_for_density(0.25f, 1.0, 32.5) == 0.5f);  // 65 cells of 0.5 m; not 32.5 of 1 m
}

TEST_CASE("tile density: points over the bounding box, 0 without one") {
  CHECK(tile_density(100, 25.0) == 4.0);
  CHECK(tile_density(100, 0.0) == 0.0);
  CHECK(tile_density(0, 25.0) == 0.0);
}
