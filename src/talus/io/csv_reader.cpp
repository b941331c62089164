#include "talus/io/csv_reader.hpp"

#include <fmt/format.h>

#include <charconv>
#include <fstream>
#include <sstream>

#include "talus/core/error.hpp"

namespace talus::io {

namespace {

std::vector<std::string> split(const std::string& line) {
  std::vector<std::string> cells;
  std::stringstream in(line);
  std::string cell;
  while (std::getline(in, cell, ',')) cells.push_back(cell);
  return cells;
}

}  // namespace

std::size_t CsvTable::column(const std::string& name) const {
  for (std::size_t k = 0; k < columns.size(); ++k) {
    if (columns[k] == name) return k;
  }
  throw RunError(fmt::format("{}: no column '{}'", path.string(), name));
}

CsvTable read_csv(const std::filesystem::path& path) {
  std::ifstream in(path);
  if (!in) throw RunError(fmt::format("{}: cannot open for reading", path.string()));
  CsvTable table;
  table.path = path;
  std::string line;
  if (!std::getline(in, line)) return table;
  table.columns = split(line);
  int line_number = 1;
  while (std::getline(in, line)) {
    ++line_number;
    if (line.empty()) continue;
    const auto cells = split(line);
    if (cells.size() != table.columns.size()) {
      throw InputError(fmt::format("{}:{}: {} values, expected {}", path.string(), line_number,
                                   cells.size(), table.columns.size()));
    }
    std::vector<double> row(cells.size());
    for (std::size_t k = 0; k < cells.size(); ++k) {
      const char* end = cells[k].data() + cells[k].size();
      const auto [ptr, ec] = std::from_chars(cells[k].data(), end, row[k]);
      if (ec != std::errc() || ptr != end) {
        throw InputError(fmt::format("{}:{}: column '{}': '{}' is not a number", path.string(),
                                     line_number, table.columns[k], cells[k]));
      }
    }
    table.rows.push_back(std::move(row));
  }
  return table;
}

}  // namespace talus::io
