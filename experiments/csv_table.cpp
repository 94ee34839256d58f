#include "csv_table.hpp"

#include <cstdio>
#include <fstream>

namespace spinhash::experiment {
namespace {

void write_row(std::ofstream& f, const std::vector<std::string>& row) {
  for (size_t i = 0; i < row.size(); ++i) f << (i ? "," : "") << row[i];
  f << '\n';
}

}  // namespace

bool CsvTable::write(const std::string& path, std::string* error) const {
  std::ofstream f(path);
  write_row(f, header_);
  for (const auto& r : rows_) write_row(f, r);
  f.close();
  if (!f) {
    *error = path + ": cannot write";
    return false;
  }
  return true;
}

std::string num(double v, int significant) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.*g", significant, v);
  return buf;
}

}  // namespace spinhash::experiment
