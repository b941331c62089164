#pragma once
// Time series as CSV: one header line, then one row of numbers per sample.
// Numbers are written as the shortest text that reads back to the same double,
// so nothing is lost between a run and its post-processing.
#include <cstdio>
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

namespace talus::io {

class CsvSeries {
 public:
  // append = false starts a new file. append = true continues an existing one
  // (resume): its header must equal `columns`, and a torn last row left by an
  // interrupted run is dropped. A missing or empty file gets a header either way.
  // Throws talus::RunError on I/O failure or a header mismatch.
  CsvSeries(std::filesystem::path path, std::vector<std::string> columns, bool append);
  // A table written once, at the end of a run or for one frame: the rows go
  // to a temporary file that close() renames into place, so a full disk
  // leaves no cut file (the error names the file). Without close() (an
  // exception on the way) the temporary file is removed.
  static CsvSeries whole(std::filesystem::path path, std::vector<std::string> columns);
  CsvSeries(CsvSeries&&) = default;
  ~CsvSeries();

  // One value per column. Throws talus::RunError on I/O failure.
  void row(const std::vector<double>& values);
  // Pushes buffered rows to the file. Throws talus::RunError on I/O failure.
  void flush();
  // Flushes and closes the file (a whole table: renames it into place).
  // Throws talus::RunError on I/O failure. No rows after it.
  void close();

  const std::filesystem::path& path() const { return path_; }
  const std::vector<std::string>& columns() const { return columns_; }

  // For resume: keeps the header and the complete rows whose first column
  // (time) is <= time. A missing file is left missing. Throws talus::RunError
  // on I/O failure and talus::InputError on a row whose time is not a number.
  static void truncate_after(const std::filesystem::path& path, double time);

 private:
  struct FileCloser {
    void operator()(std::FILE* file) const { std::fclose(file); }
  };

  CsvSeries(std::filesystem::path path, std::vector<std::string> columns, bool append,
            std::filesystem::path temp);
  [[noreturn]] void fail(const char* step) const;

  std::filesystem::path path_;
  std::filesystem::path temp_;  // a whole table's temporary name; empty for a series
  std::vector<std::string> columns_;
  std::unique_ptr<std::FILE, FileCloser> file_;
  std::string line_;  // reused buffer for one formatted row
};

}  // namespace talus::io
