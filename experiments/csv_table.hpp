// A CSV table built row by row (numbers formatted by the caller with num()).
#pragma once
#include <string>
#include <vector>

namespace spinhash::experiment {

class CsvTable {
 public:
  explicit CsvTable(std::vector<std::string> header) : header_(std::move(header)) {}
  void add(std::vector<std::string> row) { rows_.push_back(std::move(row)); }
  bool write(const std::string& path, std::string* error) const;

 private:
  std::vector<std::string> header_;
  std::vector<std::vector<std::string>> rows_;
};

// Shortest round-trippable-enough text for a number (%.*g).
std::string num(double v, int significant = 6);

}  // namespace spinhash::experiment
