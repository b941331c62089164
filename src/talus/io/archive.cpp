#include "talus/io/archive.hpp"

#include <fmt/format.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <fstream>
#include <iterator>
#include <system_error>

#include "talus/core/error.hpp"

namespace talus::io {

namespace {

constexpr char kMagic[8] = {'T', 'A', 'L', 'U', 'S', 'C', 'K', 'P'};
constexpr uint32_t kFormatVersion = 1;
// magic, version, reserved, payload size, checksum
constexpr std::size_t kFileHeaderSize = 8 + 4 + 4 + 8 + 8;
// kind, type category, element size, count
constexpr std::size_t kItemHeaderSize = 1 + 1 + 8 + 8;

// FNV-1a, 64 bit: enough to catch torn or bit-flipped files, not an attacker.
uint64_t checksum(std::string_view bytes) {
  uint64_t hash = 14695981039346656037ull;
  for (unsigned char c : bytes) {
    hash ^= c;
    hash *= 1099511628211ull;
  }
  return hash;
}

template <class T>
void append_raw(std::string& out, const T& value) {
  out.append(reinterpret_cast<const char*>(&value), sizeof(T));
}

template <class T>
T load_raw(const char* at) {
  T value;
  std::memcpy(&value, at, sizeof(T));
  return value;
}

const char* category_name(char category) {
  switch (category) {
    case 'f':
      return "float";
    case 'i':
      return "signed integer";
    case 'u':
      return "unsigned integer";
    case 'n':
      return "enum";
    case 'E':
      return "Eigen matrix";
    case 'c':
      return "char";
    case 'r':
      return "record";
  }
  return "unknown type";
}

const char* kind_name(uint8_t kind) {
  switch (static_cast<detail::ItemKind>(kind)) {
    case detail::ItemKind::kScalar:
      return "scalar";
    case detail::ItemKind::kVector:
      return "vector";
    case detail::ItemKind::kString:
      return "string";
  }
  return "unknown item";
}

}  // namespace

void write_file_atomically(const std::filesystem::path& path,
                           std::span<const std::string_view> pieces, bool sync_to_disk) {
  std::filesystem::path temp = path;
  temp += ".tmp";
  auto fail = [&](const char* step, int error) {
    std::error_code ignored;
    std::filesystem::remove(temp, ignored);
    throw RunError(fmt::format("cannot write '{}' ({}): {}", path.string(), step,
                               std::generic_category().message(error)));
  };
  std::FILE* file = std::fopen(temp.c_str(), "wb");
  if (file == nullptr) fail("open", errno);
  bool written = true;
  for (std::string_view piece : pieces) {
    if (piece.empty()) continue;
    written = written && std::fwrite(piece.data(), 1, piece.size(), file) == piece.size();
  }
  written = written && std::fflush(file) == 0 && (!sync_to_disk || ::fsync(fileno(file)) == 0);
  const int write_error = errno;
  if (std::fclose(file) != 0 || !written) fail("write", written ? errno : write_error);
  rename_into_place(temp, path);
}

void rename_into_place(const std::filesystem::path& temp, const std::filesystem::path& path) {
  std::error_code error;
  std::filesystem::rename(temp, path, error);
  if (!error) return;
  std::error_code ignored;
  std::filesystem::remove(temp, ignored);
  throw RunError(fmt::format("cannot write '{}' (rename): {}", path.string(), error.message()));
}

void ArchiveWriter::begin_item(detail::ItemKind kind, char category, uint64_t element_size,
                               uint64_t count) {
  append_raw(payload_, static_cast<uint8_t>(kind));
  append_raw(payload_, category);
  append_raw(payload_, element_size);
  append_raw(payload_, count);
}

void ArchiveWriter::append(const void* data, std::size_t size) {
  if (size == 0) return;  // data may be null for an empty vector
  payload_.append(static_cast<const char*>(data), size);
}

void ArchiveWriter::put(const std::string& text) {
  begin_item(detail::ItemKind::kString, 'c', 1, text.size());
  payload_.append(text);
}

void ArchiveWriter::save(const std::filesystem::path& path) const {
  std::string file;
  file.reserve(kFileHeaderSize + payload_.size());
  file.append(kMagic, sizeof(kMagic));
  append_raw(file, kFormatVersion);
  append_raw(file, uint32_t{0});
  append_raw(file, static_cast<uint64_t>(payload_.size()));
  append_raw(file, checksum(payload_));
  file.append(payload_);
  // A checkpoint is what a resume trusts, so it goes to disk before the rename.
  write_file_atomically(path, file, /*sync_to_disk=*/true);
}

ArchiveReader::ArchiveReader(const std::filesystem::path& path) : path_(path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) fail("cannot open the file (missing or unreadable)");
  std::string file((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  if (in.bad()) fail("cannot read the file");
  if (file.size() < kFileHeaderSize || std::memcmp(file.data(), kMagic, sizeof(kMagic)) != 0) {
    fail("not a talus checkpoint (bad header)");
  }
  const auto version = load_raw<uint32_t>(file.data() + 8);
  if (version != kFormatVersion) {
    fail(
        fmt::format("format version {}, but this build reads version {}", version, kFormatVersion));
  }
  const auto payload_size = load_raw<uint64_t>(file.data() + 16);
  const auto expected_checksum = load_raw<uint64_t>(file.data() + 24);
  const uint64_t actual_size = file.size() - kFileHeaderSize;
  if (actual_size != payload_size) {
    fail(fmt::format("{} ({} payload bytes, header says {})",
                     actual_size < payload_size ? "truncated" : "trailing bytes", actual_size,
                     payload_size));
  }
  payload_ = file.substr(kFileHeaderSize);
  if (checksum(payload_) != expected_checksum) fail("checksum mismatch (corrupt file)");
}

void ArchiveReader::fail(const std::string& what) const {
  throw InputError(fmt::format("checkpoint '{}': {}", path_.string(), what));
}

uint64_t ArchiveReader::expect_item(detail::ItemKind kind, char category, uint64_t element_size) {
  const std::size_t index = item_index_++;
  if (payload_.size() - cursor_ < kItemHeaderSize) {
    fail(fmt::format("item {}: read past the end of the archive", index));
  }
  const char* at = payload_.data() + cursor_;
  const auto stored_kind = load_raw<uint8_t>(at);
  const auto stored_category = load_raw<char>(at + 1);
  const auto stored_element_size = load_raw<uint64_t>(at + 2);
  const auto count = load_raw<uint64_t>(at + 10);
  if (stored_kind != static_cast<uint8_t>(kind) || stored_category != category ||
      stored_element_size != element_size || (kind == detail::ItemKind::kScalar && count != 1)) {
    fail(fmt::format("item {}: stored as {} of {}-byte {}, read as {} of {}-byte {}", index,
                     kind_name(stored_kind), stored_element_size, category_name(stored_category),
                     kind_name(static_cast<uint8_t>(kind)), element_size, category_name(category)));
  }
  cursor_ += kItemHeaderSize;
  check_remaining(count, element_size);
  return count;
}

void ArchiveReader::check_remaining(uint64_t count, uint64_t element_size) const {
  // Compare by division: count * element_size may overflow on a corrupt count.
  const uint64_t remaining = payload_.size() - cursor_;
  if (element_size != 0 && count > remaining / element_size) {
    fail(fmt::format("item {}: {} elements do not fit in the {} bytes left", item_index_ - 1, count,
                     remaining));
  }
}

void ArchiveReader::read(void* data, std::size_t size) {
  if (size == 0) return;  // data may be null for an empty vector
  if (payload_.size() - cursor_ < size) fail("read past the end of the archive");
  std::memcpy(data, payload_.data() + cursor_, size);
  cursor_ += size;
}

void ArchiveReader::get(std::string& text) {
  const uint64_t length = expect_item(detail::ItemKind::kString, 'c', 1);
  text.assign(payload_.data() + cursor_, length);
  cursor_ += length;
}

}  // namespace talus::io
