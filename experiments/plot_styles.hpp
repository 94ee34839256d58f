// Colours and markers shared by every experiment plot: one per mode, so
// BRAN, SRAN and SIND look the same in every figure.
#pragma once
#include <string>

#include "spinhash/config.hpp"

namespace spinhash::experiment {

// gnuplot lines defining styles 1 (BRAN), 2 (SRAN), 3 (SIND) and 4.. (extra series).
std::string plot_style_lines();
int mode_style(Mode m);
std::string mode_title(Mode m);  // "BRAN", "SRAN", "SIND"

}  // namespace spinhash::experiment
