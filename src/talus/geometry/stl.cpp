#include "talus/geometry/stl.hpp"

#include <fmt/format.h>

#include <bit>
#include <cctype>
#include <charconv>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <iterator>
#include <sstream>
#include <string_view>

#include "talus/core/error.hpp"

namespace talus::geometry {

static_assert(std::endian::native == std::endian::little, "binary STL is little-endian");

namespace {

constexpr std::size_t kHeaderBytes = 84;  // 80-byte header + uint32 facet count
constexpr std::size_t kFacetBytes = 50;   // 12 floats + uint16 attribute

struct Token {
  std::string_view text;
  int line;
};

// Collects facets and applies the scale and offset.
struct Collector {
  double scale;
  Vec3 offset;
  std::vector<Primitive> triangles;
  std::size_t degenerate = 0;

  void add(const Vec3& a, const Vec3& b, const Vec3& c) {
    Primitive p;
    if (make_triangle(scale * a + offset, scale * b + offset, scale * c + offset, p)) {
      triangles.push_back(p);
    } else {
      ++degenerate;
    }
  }
};

bool equals_nocase(std::string_view a, std::string_view b) {
  if (a.size() != b.size()) return false;
  for (std::size_t i = 0; i < a.size(); ++i) {
    if (std::tolower(static_cast<unsigned char>(a[i])) != b[i]) return false;
  }
  return true;
}

std::vector<Token> tokenize(std::string_view text) {
  std::vector<Token> tokens;
  int line = 1;
  std::size_t i = 0;
  while (i < text.size()) {
    const char c = text[i];
    if (c == '\n') ++line;
    if (std::isspace(static_cast<unsigned char>(c))) {
      ++i;
      continue;
    }
    const std::size_t start = i;
    while (i < text.size() && !std::isspace(static_cast<unsigned char>(text[i]))) ++i;
    tokens.push_back({text.substr(start, i - start), line});
  }
  return tokens;
}

class AsciiParser {
 public:
  AsciiParser(const std::string& path, std::string_view text)
      : path_(path), tokens_(tokenize(text)) {}

  void parse(Collector& out) {
    expect("solid");
    skip_rest_of_line();
    while (true) {
      const Token& t = next("'facet' or 'endsolid'");
      if (equals_nocase(t.text, "facet")) {
        facet(out);
      } else if (equals_nocase(t.text, "endsolid")) {
        skip_rest_of_line();
        if (pos_ == tokens_.size()) return;
        expect("solid");  // several solids in one file
        skip_rest_of_line();
      } else {
        fail(t.line, fmt::format("expected 'facet' or 'endsolid', got '{}'", t.text));
      }
    }
  }

 private:
  void facet(Collector& out) {
    expect("normal");
    number();  // the stored normal is recomputed from the vertices
    number();
    number();
    expect("outer");
    expect("loop");
    Vec3 v[3];
    for (Vec3& vertex : v) {
      expect("vertex");
      for (int k = 0; k < 3; ++k) vertex[k] = number();
    }
    expect("endloop");
    expect("endfacet");
    out.add(v[0], v[1], v[2]);
  }

  [[noreturn]] void fail(int line, const std::string& what) const {
    throw InputError(fmt::format("{}:{}: {}", path_, line, what));
  }

  const Token& next(std::string_view wanted) {
    if (pos_ == tokens_.size()) {
      const int last = tokens_.empty() ? 1 : tokens_.back().line;
      fail(last, fmt::format("unexpected end of file, expected {}", wanted));
    }
    return tokens_[pos_++];
  }

  void expect(std::string_view keyword) {
    const Token& t = next(fmt::format("'{}'", keyword));
    if (!equals_nocase(t.text, keyword))
      fail(t.line, fmt::format("expected '{}', got '{}'", keyword, t.text));
  }

  double number() {
    const Token& t = next("a number");
    double value = 0;
    const char* end = t.text.data() + t.text.size();
    const auto [ptr, ec] = std::from_chars(t.text.data(), end, value);
    if (ec != std::errc() || ptr != end || !std::isfinite(value))
      fail(t.line, fmt::format("expected a number, got '{}'", t.text));
    return value;
  }

  // The solid's name runs to the end of its line.
  void skip_rest_of_line() {
    const int line = tokens_[pos_ - 1].line;
    while (pos_ < tokens_.size() && tokens_[pos_].line == line) ++pos_;
  }

  const std::string& path_;
  std::vector<Token> tokens_;
  std::size_t pos_ = 0;
};

float read_float(const char* p) {
  float f;
  std::memcpy(&f, p, sizeof f);
  return f;
}

void parse_binary(const std::string& path, const std::string& data, std::uint32_t count,
                  Collector& out) {
  for (std::uint32_t i = 0; i < count; ++i) {
    const char* facet = data.data() + kHeaderBytes + i * kFacetBytes;
    Vec3 v[3];
    for (int k = 0; k < 3; ++k) {
      for (int c = 0; c < 3; ++c) v[k][c] = read_float(facet + 12 + 12 * k + 4 * c);
    }
    if (!v[0].allFinite() || !v[1].allFinite() || !v[2].allFinite())
      throw InputError(fmt::format("{}: facet {} has a non-finite vertex", path, i + 1));
    out.add(v[0], v[1], v[2]);
  }
}

bool starts_with_solid(const std::string& data) {
  std::size_t i = 0;
  while (i < data.size() && std::isspace(static_cast<unsigned char>(data[i]))) ++i;
  return equals_nocase(std::string_view(data).substr(i, 5), "solid");
}

}  // namespace

std::vector<Primitive> read_stl(const std::string& path, double scale, const Vec3& offset,
                                std::size_t* degenerate) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(fmt::format("{}: cannot open STL file", path));
  const std::string data((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  Collector out{scale, offset, {}, 0};

  // A binary file's size is fixed by its facet count; an ASCII file that
  // happens to match it exactly would be a remarkable coincidence.
  std::uint32_t count = 0;
  if (data.size() >= kHeaderBytes) std::memcpy(&count, data.data() + 80, sizeof count);
  const bool binary_size =
      data.size() >= kHeaderBytes && data.size() == kHeaderBytes + std::size_t{count} * kFacetBytes;
  if (binary_size) {
    parse_binary(path, data, count, out);
  } else if (starts_with_solid(data)) {
    AsciiParser(path, data).parse(out);
  } else if (data.size() < kHeaderBytes) {
    throw InputError(
        fmt::format("{}: not an STL file ({} bytes, no 'solid' keyword)", path, data.size()));
  } else {
    throw InputError(fmt::format(
        "{}: binary STL header announces {} facets ({} bytes) but the file has {} bytes", path,
        count, kHeaderBytes + std::size_t{count} * kFacetBytes, data.size()));
  }
  if (degenerate) *degenerate = out.degenerate;
  return std::move(out.triangles);
}

void write_stl(const std::string& path, const std::vector<Primitive>& triangles, bool binary,
               const std::string& solid_name) {
  std::ofstream os(path, std::ios::binary);
  if (!os) throw RunError(fmt::format("{}: cannot write STL file", path));
  if (binary) {
    char header[80] = {};
    std::strncpy(header, solid_name.c_str(), sizeof header - 1);
    os.write(header, sizeof header);
    const auto count = static_cast<std::uint32_t>(triangles.size());
    os.write(reinterpret_cast<const char*>(&count), sizeof count);
    for (const Primitive& t : triangles) {
      float values[12];
      const Vec3* vectors[4] = {&t.n, &t.p0, &t.p1, &t.p2};
      for (int k = 0; k < 4; ++k) {
        for (int c = 0; c < 3; ++c) values[3 * k + c] = static_cast<float>((*vectors[k])[c]);
      }
      os.write(reinterpret_cast<const char*>(values), sizeof values);
      const std::uint16_t attribute = 0;
      os.write(reinterpret_cast<const char*>(&attribute), sizeof attribute);
    }
  } else {
    os << "solid " << solid_name << '\n';
    for (const Primitive& t : triangles) {
      os << fmt::format("  facet normal {:.17g} {:.17g} {:.17g}\n    outer loop\n", t.n.x(),
                        t.n.y(), t.n.z());
      for (const Vec3* v : {&t.p0, &t.p1, &t.p2})
        os << fmt::format("      vertex {:.17g} {:.17g} {:.17g}\n", v->x(), v->y(), v->z());
      os << "    endloop\n  endfacet\n";
    }
    os << "endsolid " << solid_name << '\n';
  }
  if (!os) throw RunError(fmt::format("{}: error while writing STL file", path));
}

}  // namespace talus::geometry
