#include "talus/io/csv_writer.hpp"

#include <fmt/format.h>

#include <cerrno>
#include <charconv>
#include <cstring>
#include <fstream>
#include <iterator>
#include <optional>
#include <stdexcept>
#include <string_view>
#include <system_error>

#include "talus/core/error.hpp"
#include "talus/io/archive.hpp"

namespace talus::io {

namespace {

std::string header_line(const std::vector<std::string>& columns) {
  return fmt::format("{}\n", fmt::join(columns, ","));
}

// The whole file, or nothing when it does not exist.
std::optional<std::string> read_whole_file(const std::filesystem::path& path) {
  std::error_code error;
  if (!std::filesystem::exists(path, error)) return std::nullopt;
  std::ifstream in(path, std::ios::binary);
  std::string content((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  if (!in.good() && !in.eof()) {
    throw RunError(fmt::format("cannot read '{}': {}", path.string(), std::strerror(errno)));
  }
  return content;
}

// Everything up to and including the last newline: a row without its newline
// was torn by an interrupted write and cannot be trusted.
std::string_view complete_lines(std::string_view content) {
  const auto last_newline = content.rfind('\n');
  return last_newline == std::string_view::npos ? std::string_view{}
                                                : content.substr(0, last_newline + 1);
}

}  // namespace

CsvSeries::CsvSeries(std::filesystem::path path, std::vector<std::string> columns, bool append)
    : CsvSeries(std::move(path), std::move(columns), append, {}) {}

CsvSeries::CsvSeries(std::filesystem::path path, std::vector<std::string> columns, bool append,
                     std::filesystem::path temp)
    : path_(std::move(path)), temp_(std::move(temp)), columns_(std::move(columns)) {
  if (columns_.empty()) throw std::invalid_argument("CsvSeries: no columns");
  for (const auto& name : columns_) {
    if (name.find_first_of(",\"\r\n") != std::string::npos) {
      throw std::invalid_argument(fmt::format("CsvSeries: column name '{}' needs quoting", name));
    }
  }
  const std::string header = header_line(columns_);
  bool continue_file = false;
  if (append) {
    const auto content = read_whole_file(path_);
    const std::string_view complete = content ? complete_lines(*content) : std::string_view{};
    if (!complete.empty()) {
      if (!complete.starts_with(header)) {
        throw RunError(fmt::format("cannot append to '{}': its header is not '{}'", path_.string(),
                                   header.substr(0, header.size() - 1)));
      }
      std::error_code error;
      if (complete.size() != content->size())
        std::filesystem::resize_file(path_, complete.size(), error);
      if (error) {
        throw RunError(fmt::format("cannot repair '{}': {}", path_.string(), error.message()));
      }
      continue_file = true;
    }
  }
  const auto& target = temp_.empty() ? path_ : temp_;
  file_.reset(std::fopen(target.c_str(), continue_file ? "ab" : "wb"));
  if (!file_) fail("open");
  if (!continue_file &&
      std::fwrite(header.data(), 1, header.size(), file_.get()) != header.size()) {
    fail("header");
  }
}

CsvSeries CsvSeries::whole(std::filesystem::path path, std::vector<std::string> columns) {
  auto temp = path;
  temp += ".tmp";
  return CsvSeries(std::move(path), std::move(columns), false, std::move(temp));
}

CsvSeries::~CsvSeries() {
  if (file_ && !temp_.empty()) {
    file_.reset();
    std::error_code ignored;
    std::filesystem::remove(temp_, ignored);
  }
}

void CsvSeries::close() {
  if (!file_) return;
  flush();  // on failure the destructor removes a temporary file
  std::error_code error;
  if (std::fclose(file_.release()) != 0) {
    const int close_error = errno;
    if (!temp_.empty()) std::filesystem::remove(temp_, error);
    errno = close_error;
    fail("close");
  }
  if (!temp_.empty()) rename_into_place(temp_, path_);
}

void CsvSeries::fail(const char* step) const {
  throw RunError(
      fmt::format("cannot write '{}' ({}): {}", path_.string(), step, std::strerror(errno)));
}

void CsvSeries::row(const std::vector<double>& values) {
  if (values.size() != columns_.size()) {
    throw std::invalid_argument(fmt::format("CsvSeries '{}': {} values for {} columns",
                                            path_.string(), values.size(), columns_.size()));
  }
  line_.clear();
  auto out = std::back_inserter(line_);
  for (std::size_t i = 0; i < values.size(); ++i) {
    // "{}" is the shortest text that parses back to the identical double.
    if (i > 0) line_.push_back(',');
    fmt::format_to(out, "{}", values[i]);
  }
  line_.push_back('\n');
  if (std::fwrite(line_.data(), 1, line_.size(), file_.get()) != line_.size()) fail("row");
}

void CsvSeries::flush() {
  if (std::fflush(file_.get()) != 0) fail("flush");
}

void CsvSeries::truncate_after(const std::filesystem::path& path, double time) {
  const auto content = read_whole_file(path);
  if (!content) return;
  const std::string_view complete = complete_lines(*content);
  std::string kept;
  kept.reserve(complete.size());
  std::size_t line_start = 0;
  for (int line_number = 1; line_start < complete.size(); ++line_number) {
    const std::size_t line_end = complete.find('\n', line_start) + 1;
    const std::string_view line = complete.substr(line_start, line_end - line_start);
    line_start = line_end;
    if (line_number == 1) {
      kept.append(line);  // the header
      continue;
    }
    const std::string_view field = line.substr(0, line.find_first_of(",\n"));
    double row_time = 0.0;
    const auto [end, error] = std::from_chars(field.data(), field.data() + field.size(), row_time);
    if (error != std::errc{} || end != field.data() + field.size()) {
      throw InputError(
          fmt::format("{}:{}: time '{}' is not a number", path.string(), line_number, field));
    }
    if (row_time <= time) kept.append(line);
  }
  write_file_atomically(path, kept);
}

}  // namespace talus::io
