#pragma once
// Reading back a numeric CSV written by CsvSeries (a header line, then rows of
// numbers): post-processing works from the files, so a resumed run is
// analysed whole.
#include <filesystem>
#include <string>
#include <vector>

namespace talus::io {

struct CsvTable {
  std::vector<std::string> columns;
  std::vector<std::vector<double>> rows;
  // Index of a column; throws talus::RunError naming the file when absent.
  std::size_t column(const std::string& name) const;
  std::filesystem::path path;
};

// Throws talus::RunError when the file cannot be read, and talus::InputError
// (file:line) on a cell that is not a number or a row of the wrong length.
CsvTable read_csv(const std::filesystem::path& path);

}  // namespace talus::io
