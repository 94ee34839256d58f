// A CSV file read by column name (the catalogs the prepare-* commands
// write): a header row, then rows of plain fields (no quoting).
#pragma once
#include <string>
#include <vector>

namespace spinhash::experiment {

class CsvReader {
 public:
  // false with *error naming the file when it cannot be read, has no header
  // or a row has another number of fields than the header.
  bool read(const std::string& path, std::string* error);
  // The column's index, or -1.
  int column(const std::string& name) const;
  size_t rows() const { return rows_.size(); }
  // The field of `column` (an index from column()) in data row `row`.
  const std::string& cell(size_t row, int column) const { return rows_[row][static_cast<size_t>(column)]; }

 private:
  std::vector<std::string> header_;
  std::vector<std::vector<std::string>> rows_;
};

}  // namespace spinhash::experiment
