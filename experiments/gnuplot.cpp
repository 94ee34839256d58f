#include "gnuplot.hpp"

#include <cstdlib>
#include <fstream>
#include <sstream>

namespace spinhash::experiment {
namespace {

constexpr const char* kFont = "sans,11";

// Single-quoted for /bin/sh.
std::string shell_quote(const std::string& s) {
  std::string out = "'";
  for (char c : s) out += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return out + "'";
}

bool terminal_works(const char* terminal) {
  std::string cmd = std::string("gnuplot -e 'set terminal ") + terminal + "' >/dev/null 2>&1";
  return std::system(cmd.c_str()) == 0;
}

PlotFormat probe() {
  const char* const candidates[][2] = {{"pngcairo", "png"}, {"png", "png"}, {"svg", "svg"}};
  for (const auto& c : candidates)
    if (terminal_works(c[0])) return PlotFormat{c[0], c[1]};
  return PlotFormat{};
}

std::string terminal_line(const PlotFormat& f, int width, int height) {
  std::ostringstream s;
  s << "set terminal " << f.terminal << " size " << width << "," << height;
  if (f.terminal == "svg") s << " dynamic";
  if (f.terminal != "png") s << " font '" << kFont << "'";
  s << " noenhanced";  // underscores in labels stay underscores
  return s.str();
}

}  // namespace

const PlotFormat& plot_format() {
  static const PlotFormat format = probe();
  return format;
}

std::string plot_file(const std::string& name) {
  const PlotFormat& f = plot_format();
  return name + "." + (f.available() ? f.extension : std::string("png"));
}

bool render_plot(const std::string& dir, const std::string& name, const std::string& body, int width,
                 int height, std::string* error) {
  const PlotFormat& f = plot_format();
  const std::string script = dir + "/" + name + ".gp";
  {
    std::ofstream out(script);
    out << "# " << name << ": run `gnuplot " << name << ".gp` in this folder\n";
    if (f.available()) out << terminal_line(f, width, height) << "\nset output '" << plot_file(name) << "'\n";
    out << body;
    if (!out) {
      *error = script + ": cannot write";
      return false;
    }
  }
  if (!f.available()) {
    *error = "gnuplot not found (scripts/install-deps.sh installs gnuplot-nox); wrote " + script;
    return false;
  }
  std::string cmd = "cd " + shell_quote(dir) + " && gnuplot " + shell_quote(name + ".gp") + " 2>&1";
  if (std::system(cmd.c_str()) != 0) {
    *error = "gnuplot failed on " + script;
    return false;
  }
  return true;
}

}  // namespace spinhash::experiment
