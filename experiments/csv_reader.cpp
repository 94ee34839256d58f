#include "csv_reader.hpp"

#include <fstream>
#include <sstream>

namespace spinhash::experiment {
namespace {

std::vector<std::string> split(std::string line) {
  if (!line.empty() && line.back() == '\r') line.pop_back();
  std::vector<std::string> out;
  std::istringstream in(line);
  for (std::string f; std::getline(in, f, ',');) out.push_back(f);
  if (!line.empty() && line.back() == ',') out.emplace_back();
  return out;
}

}  // namespace

bool CsvReader::read(const std::string& path, std::string* error) {
  std::ifstream in(path);
  if (!in) {
    *error = path + ": cannot read";
    return false;
  }
  std::string line;
  if (!std::getline(in, line) || (header_ = split(line)).empty()) {
    *error = path + ": no header row";
    return false;
  }
  rows_.clear();
  for (size_t n = 2; std::getline(in, line); ++n) {
    if (line.empty() || line == "\r") continue;
    rows_.push_back(split(line));
    if (rows_.back().size() != header_.size()) {
      *error = path + ": line " + std::to_string(n) + " has " + std::to_string(rows_.back().size()) +
               " fields, the header " + std::to_string(header_.size());
      return false;
    }
  }
  return true;
}

int CsvReader::column(const std::string& name) const {
  for (size_t i = 0; i < header_.size(); ++i)
    if (header_[i] == name) return static_cast<int>(i);
  return -1;
}

}  // namespace spinhash::experiment
