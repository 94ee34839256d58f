// Plots through Debian's gnuplot (gnuplot-nox): the first terminal that
// works of pngcairo, png (libgd), svg. Every plot's script is kept beside
// the CSVs (NAME.gp), so a person can re-run or restyle it.
#pragma once
#include <string>

namespace spinhash::experiment {

struct PlotFormat {
  std::string terminal;   // "pngcairo", "png", "svg"; empty: no gnuplot
  std::string extension;  // "png" or "svg"
  bool available() const { return !terminal.empty(); }
};

// Probes gnuplot once per process.
const PlotFormat& plot_format();

// Writes DIR/NAME.gp (terminal and output lines, then `body`, which reads
// data files relative to DIR) and runs gnuplot in DIR. Image: DIR/NAME.<ext>.
// Without gnuplot the script is still written and false is returned.
bool render_plot(const std::string& dir, const std::string& name, const std::string& body, int width,
                 int height, std::string* error);

// "NAME.png" / "NAME.svg" for the current format (what render_plot writes).
std::string plot_file(const std::string& name);

}  // namespace spinhash::experiment
