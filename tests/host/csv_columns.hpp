// A CSV file read by column name, for tests: a test that reads a column by
// its position keeps passing when a column is added or moved and it reads
// the neighbour instead. The experiments' and simulators' CSVs have a header
// row and no quoted fields.
#pragma once
#include <cstdlib>
#include <sstream>
#include <string>
#include <vector>

namespace spinhash::host::test {

class CsvColumns {
 public:
  explicit CsvColumns(const std::string& text) {
    std::istringstream in(text);
    std::string line;
    if (std::getline(in, line)) header_ = split(line);
    while (std::getline(in, line))
      if (!line.empty()) rows_.push_back(split(line));
  }

  const std::vector<std::string>& header() const { return header_; }
  size_t rows() const { return rows_.size(); }
  bool has(const std::string& column) const { return index(column) >= 0; }

  // The cell of `column` in data row `row` (0: the first after the header);
  // empty when the column or the cell is missing.
  std::string cell(size_t row, const std::string& column) const {
    const int i = index(column);
    if (row >= rows_.size() || i < 0 || static_cast<size_t>(i) >= rows_[row].size()) return "";
    return rows_[row][static_cast<size_t>(i)];
  }
  double number(size_t row, const std::string& column) const { return std::atof(cell(row, column).c_str()); }

 private:
  static std::vector<std::string> split(const std::string& line) {
    std::vector<std::string> cells;
    std::istringstream ls(line);
    for (std::string c; std::getline(ls, c, ',');) cells.push_back(c);
    if (!line.empty() && line.back() == ',') cells.emplace_back();  // a last empty cell
    return cells;
  }
  int index(const std::string& column) const {
    for (size_t i = 0; i < header_.size(); ++i)
      if (header_[i] == column) return static_cast<int>(i);
    return -1;
  }

  std::vector<std::string> header_;
  std::vector<std::vector<std::string>> rows_;
};

}  // namespace spinhash::host::test
