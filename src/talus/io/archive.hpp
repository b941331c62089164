#pragma once
// A small binary checkpoint archive. Values are read back in the order they
// were written; every item carries its kind, a type tag and its element size
// so that a reader that drifts out of step fails loudly instead of returning
// garbage.
//
// File layout: magic "TALUSCKP", u32 format version, u32 reserved, u64 payload
// size, u64 FNV-1a checksum of the payload, then the payload. The file is
// written to a temporary name and renamed, so a crash never leaves a torn
// checkpoint behind. Data are stored in native byte order: checkpoints are
// for resuming on the same kind of machine, not for exchange.
#include <Eigen/Core>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <span>
#include <string>
#include <string_view>
#include <type_traits>
#include <vector>

namespace talus::io {

namespace detail {

// Fixed-size Eigen matrices own a plain array of scalars, but Eigen declares a
// copy constructor, so std::is_trivially_copyable says no. They are stored
// through data() instead of as raw objects.
template <class T>
struct IsFixedEigen : std::false_type {};
template <class S, int R, int C, int O, int MR, int MC>
struct IsFixedEigen<Eigen::Matrix<S, R, C, O, MR, MC>>
    : std::bool_constant<R != Eigen::Dynamic && C != Eigen::Dynamic &&
                         std::is_trivially_copyable_v<S>> {};

template <class T>
constexpr std::size_t stored_size() {
  if constexpr (IsFixedEigen<T>::value) {
    return sizeof(typename T::Scalar) * T::RowsAtCompileTime * T::ColsAtCompileTime;
  } else {
    return sizeof(T);
  }
}

template <class T>
const void* bytes_of(const T& value) {
  if constexpr (IsFixedEigen<T>::value) {
    return value.data();
  } else {
    return &value;
  }
}

template <class T>
void* bytes_of(T& value) {
  if constexpr (IsFixedEigen<T>::value) {
    return value.data();
  } else {
    return &value;
  }
}

enum class ItemKind : uint8_t { kScalar = 1, kVector = 2, kString = 3 };

// A coarse type tag stored with each item, so that reading a double where an
// int64_t was written fails even though both are eight bytes.
template <class T>
constexpr char type_category() {
  if constexpr (IsFixedEigen<T>::value)
    return 'E';
  else if constexpr (std::is_floating_point_v<T>)
    return 'f';
  else if constexpr (std::is_enum_v<T>)
    return 'n';
  else if constexpr (std::is_integral_v<T>)
    return std::is_signed_v<T> ? 'i' : 'u';
  else
    return 'r';  // a record (struct, std::array, ...)
}

}  // namespace detail

// Types that go into an archive as raw bytes. std::vector<bool> has no data(),
// so bool is left out to keep put(std::vector<T>) uniform.
template <class T>
concept Archivable = (std::is_trivially_copyable_v<T> || detail::IsFixedEigen<T>::value) &&
                     !std::is_pointer_v<T> && !std::is_array_v<T> && !std::is_same_v<T, bool>;

class ArchiveWriter {
 public:
  template <Archivable T>
  void put(const T& value) {
    begin_item(detail::ItemKind::kScalar, detail::type_category<T>(), detail::stored_size<T>(), 1);
    append(detail::bytes_of(value), detail::stored_size<T>());
  }

  template <Archivable T>
  void put(const std::vector<T>& values) {
    begin_item(detail::ItemKind::kVector, detail::type_category<T>(), detail::stored_size<T>(),
               values.size());
    if constexpr (std::is_trivially_copyable_v<T>) {
      append(values.data(), values.size() * sizeof(T));
    } else {
      for (const T& v : values) append(detail::bytes_of(v), detail::stored_size<T>());
    }
  }

  void put(const std::string& text);
  void put(const char* text) { put(std::string(text)); }

  // Writes the archive atomically; throws talus::RunError when it cannot.
  void save(const std::filesystem::path& path) const;

  std::size_t payload_size() const { return payload_.size(); }

 private:
  void begin_item(detail::ItemKind kind, char category, uint64_t element_size, uint64_t count);
  void append(const void* data, std::size_t size);

  std::string payload_;
};

class ArchiveReader {
 public:
  // Throws talus::InputError when the file is missing, truncated, corrupt or
  // written by another format version.
  explicit ArchiveReader(const std::filesystem::path& path);

  template <Archivable T>
  void get(T& value) {
    expect_item(detail::ItemKind::kScalar, detail::type_category<T>(), detail::stored_size<T>());
    read(detail::bytes_of(value), detail::stored_size<T>());
  }

  template <Archivable T>
  void get(std::vector<T>& values) {
    const uint64_t count = expect_item(detail::ItemKind::kVector, detail::type_category<T>(),
                                       detail::stored_size<T>());
    values.resize(count);
    if constexpr (std::is_trivially_copyable_v<T>) {
      read(values.data(), count * sizeof(T));
    } else {
      for (T& v : values) read(detail::bytes_of(v), detail::stored_size<T>());
    }
  }

  void get(std::string& text);

  // Convenience for `auto n = reader.get<int64_t>();`.
  template <class T>
  T get() {
    T value{};
    get(value);
    return value;
  }

  // True when every item has been read.
  bool at_end() const { return cursor_ == payload_.size(); }

 private:
  uint64_t expect_item(detail::ItemKind kind, char category, uint64_t element_size);
  void check_remaining(uint64_t count, uint64_t element_size) const;
  void read(void* data, std::size_t size);
  [[noreturn]] void fail(const std::string& what) const;

  std::filesystem::path path_;
  std::string payload_;
  std::size_t cursor_ = 0;
  std::size_t item_index_ = 0;
};

// Replaces `path` by the concatenation of `pieces` through a temporary file
// and a rename, so that readers see either the old or the new file, never a
// partial one. Pieces let large binary arrays be written without first being
// copied into one buffer. Shared by the io writers; throws talus::RunError.
void write_file_atomically(const std::filesystem::path& path,
                           std::span<const std::string_view> pieces, bool sync_to_disk = false);
inline void write_file_atomically(const std::filesystem::path& path, std::string_view content,
                                  bool sync_to_disk = false) {
  write_file_atomically(path, std::span<const std::string_view>(&content, 1), sync_to_disk);
}
// The two directions of one `transfer(ar, state...)` function that lists a
// checkpoint's fields once, so that what is saved and what is loaded cannot
// drift apart: ar(x) puts x (ArchiveSaver) or gets it (ArchiveLoader).
struct ArchiveSaver {
  ArchiveWriter& w;
  template <class T>
  void operator()(const T& v) {
    w.put(v);
  }
};

struct ArchiveLoader {
  ArchiveReader& r;
  template <class T>
  void operator()(T& v) {
    r.get(v);
  }
};

// The last step of such a write, for writers that fill the temporary file
// themselves (GDAL, a table of rows): renames `temp` to `path`; when that
// fails, removes `temp` and throws talus::RunError naming `path`.
void rename_into_place(const std::filesystem::path& temp, const std::filesystem::path& path);

}  // namespace talus::io
