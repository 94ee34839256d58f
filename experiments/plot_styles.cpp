#include "plot_styles.hpp"

namespace spinhash::experiment {

std::string plot_style_lines() {
  return "set style line 1 lc rgb '#1f5fa8' lw 2 pt 7 ps 1.0\n"  // BRAN: blue, discs
         "set style line 2 lc rgb '#c8281e' lw 2 pt 5 ps 0.9\n"  // SRAN: red, squares
         "set style line 3 lc rgb '#2e8b3a' lw 2 pt 9 ps 1.1\n"  // SIND: green, triangles
         "set style line 4 lc rgb '#7f3fbf' lw 2 pt 11 ps 1.0\n"
         "set style line 5 lc rgb '#e08a00' lw 2 pt 13 ps 1.0\n"
         "set style line 6 lc rgb '#555555' lw 2 pt 3 ps 1.0\n"
         "set style line 9 lc rgb '#999999' lw 1 dt 2\n"  // reference lines
         "set grid lc rgb '#dddddd'\n"
         "set datafile separator ','\n"
         "set datafile columnheaders\n";  // every CSV starts with a header
}

int mode_style(Mode m) { return m == Mode::kBran ? 1 : m == Mode::kSran ? 2 : 3; }

std::string mode_title(Mode m) { return m == Mode::kBran ? "BRAN" : m == Mode::kSran ? "SRAN" : "SIND"; }

}  // namespace spinhash::experiment
