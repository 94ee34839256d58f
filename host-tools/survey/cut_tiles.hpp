// Cuts a cloud into square tiles on the absolute lattice of `size` m (a
// survey's usual tiling), each written as LAS: DIR/PREFIX_I_J.las with I, J
// the tile's column and row (floor(x / size), floor(y / size)). For demos
// and tests: `spinhash scan-scene --tiles-out DIR --tile-size M`.
#pragma once
#include <cstdint>
#include <string>
#include <vector>

namespace spinhash::survey {

constexpr double kMinTileSize = 1.0, kMaxTileSize = 10000.0;  // m

// Points outside [keep_min, keep_max) (x, y) are left out: a simulated
// scene's few stray hits beyond its square would make slivers of tiles.
struct CutOptions {
  double size = 40.0;
  double keep_min[2] = {-1e300, -1e300}, keep_max[2] = {1e300, 1e300};
};

// Returns the number of tiles written; -1 with *error.
int cut_into_tiles(const std::vector<double>& xyz, const std::vector<uint8_t>& classification,
                   const CutOptions& o, const std::string& dir, const std::string& prefix,
                   std::string* error);

}  // namespace spinhash::survey
