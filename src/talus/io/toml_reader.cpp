#include "talus/io/toml_reader.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <sstream>

#include "talus/core/error.hpp"

namespace talus::io {
namespace {

std::string join_quoted(const std::vector<std::string_view>& names) {
  std::string out;
  for (std::size_t i = 0; i < names.size(); ++i) {
    out += (i == 0 ? "" : (i + 1 == names.size() ? " or " : ", "));
    out += fmt::format("\"{}\"", names[i]);
  }
  return out;
}

// Optimal string alignment distance: Levenshtein plus swapped neighbours
// ("desnity"), the most common typos.
std::size_t edit_distance(std::string_view a, std::string_view b) {
  std::vector<std::vector<std::size_t>> d(a.size() + 1, std::vector<std::size_t>(b.size() + 1));
  for (std::size_t i = 0; i <= a.size(); ++i) d[i][0] = i;
  for (std::size_t j = 0; j <= b.size(); ++j) d[0][j] = j;
  for (std::size_t i = 1; i <= a.size(); ++i) {
    for (std::size_t j = 1; j <= b.size(); ++j) {
      const std::size_t cost = a[i - 1] == b[j - 1] ? 0 : 1;
      d[i][j] = std::min({d[i - 1][j] + 1, d[i][j - 1] + 1, d[i - 1][j - 1] + cost});
      if (i > 1 && j > 1 && a[i - 1] == b[j - 2] && a[i - 2] == b[j - 1]) {
        d[i][j] = std::min(d[i][j], d[i - 2][j - 2] + 1);
      }
    }
  }
  return d[a.size()][b.size()];
}

std::string_view trim(std::string_view s) {
  const auto first = s.find_first_not_of(" \t");
  if (first == std::string_view::npos) return {};
  return s.substr(first, s.find_last_not_of(" \t") - first + 1);
}

std::optional<std::size_t> parse_index(std::string_view s) {
  std::size_t index = 0;
  const auto [end, error] = std::from_chars(s.data(), s.data() + s.size(), index);
  if (error != std::errc() || end != s.data() + s.size()) return std::nullopt;
  return index;
}

// The value of an override: TOML when it parses as such, else a plain string.
// Well-formed UTF-8 (RFC 3629: no overlong forms, surrogates or code points
// above U+10FFFF), as TOML requires of a file: a --set value that is not
// would be written into the run's scenario.toml, which then could not be read.
bool is_utf8(std::string_view text) {
  for (std::size_t i = 0; i < text.size();) {
    const auto c = static_cast<unsigned char>(text[i]);
    const std::size_t n = c < 0x80           ? 1
                          : (c >> 5) == 0x6  ? 2
                          : (c >> 4) == 0xE  ? 3
                          : (c >> 3) == 0x1E ? 4
                                             : 0;
    if (n == 0 || i + n > text.size()) return false;
    std::uint32_t code = n == 1 ? c : c & (0x7F >> n);
    for (std::size_t k = 1; k < n; ++k) {
      const auto b = static_cast<unsigned char>(text[i + k]);
      if ((b >> 6) != 0x2) return false;
      code = (code << 6) | (b & 0x3F);
    }
    static constexpr std::uint32_t kSmallest[] = {0, 0, 0x80, 0x800, 0x10000};
    if (code < kSmallest[n] || code > 0x10FFFF || (code >= 0xD800 && code <= 0xDFFF)) return false;
    i += n;
  }
  return true;
}

toml::table parse_override_value(std::string_view value) {
  try {
    return toml::parse(fmt::format("value = {}", value));
  } catch (const toml::parse_error&) {
    toml::table table;
    table.insert("value", std::string(value));
    return table;
  }
}

}  // namespace

std::string closest_name(std::string_view word, const std::vector<std::string>& candidates) {
  std::string best;
  if (word.size() < 3) return best;  // "n" is one edit from any one-letter name
  std::size_t best_distance = std::max<std::size_t>(1, word.size() / 3) + 1;
  for (const std::string& candidate : candidates) {
    std::size_t distance = edit_distance(word, candidate);
    // "poisson" for "poisson_ratio": a prefix of a long name counts as close.
    const bool prefix =
        word.size() >= 4 && (candidate.starts_with(word) || word.starts_with(candidate));
    if (prefix) distance = std::min<std::size_t>(distance, 1);
    if (distance < best_distance) {
      best = candidate;
      best_distance = distance;
    }
  }
  return best;
}

std::string node_text(const toml::node& node) {
  if (node.is_table()) return "a table";
  // As typed in a file: shortest round-trip digits, strings in double quotes.
  if (node.is_floating_point()) return fmt::format("{}", *node.value<double>());
  if (node.is_string()) return fmt::format("\"{}\"", *node.value<std::string>());
  if (const toml::array* array = node.as_array()) {
    std::string text = "[";
    for (std::size_t i = 0; i < array->size(); ++i) {
      text += (i == 0 ? "" : ", ") + node_text((*array)[i]);
    }
    text += "]";
    return text.size() > 60 ? text.substr(0, 56) + "...]" : text;
  }
  std::ostringstream out;
  node.visit([&](const auto& value) { out << value; });
  return out.str();
}

TomlReader::TomlReader(const toml::table& table, std::string file, std::string section,
                       std::string path, bool array_element)
    : table_(&table),
      file_(std::move(file)),
      section_(std::move(section)),
      path_(std::move(path)),
      array_element_(array_element) {}

std::string TomlReader::label() const {
  if (section_.empty()) return "";
  return array_element_ ? "[[" + section_ + "]]" : "[" + section_ + "]";
}

int TomlReader::line() const {
  return section_.empty() ? 0 : static_cast<int>(table_->source().begin.line);
}

bool TomlReader::has(std::string_view key) const { return table_->contains(key); }
bool TomlReader::is_number(std::string_view key) const {
  const toml::node* node = table_->get(key);
  return node && (node->is_integer() || node->is_floating_point());
}
bool TomlReader::is_string(std::string_view key) const {
  const toml::node* node = table_->get(key);
  return node && node->is_string();
}

// A value read from a base scenario (extends = ...) names the base file.
std::string TomlReader::file_of(const toml::node* node) const {
  if (node && node->source().path && !node->source().path->empty()) return *node->source().path;
  return file_;
}

std::string TomlReader::where(std::string_view key) const {
  const toml::node* node = table_->get(key);
  const std::string file = file_of(node ? node : table_);
  const std::string dotted = path_.empty() ? std::string(key) : fmt::format("{}.{}", path_, key);
  if (node && node->source().begin.line == 0)
    return is_dict_scenario(file_) ? fmt::format("{}: {}", file_, dotted)
                                   : fmt::format("{}: --set {}", file_, dotted);
  const int at = node ? static_cast<int>(node->source().begin.line) : line();
  const std::string head = at > 0 ? fmt::format("{}:{}:", file, at) : file + ":";
  const std::string section = label();
  return fmt::format("{} {}'{}'", head, section.empty() ? "" : section + " ", key);
}

std::string TomlReader::text(std::string_view key) const {
  const toml::node* node = table_->get(key);
  return node ? node_text(*node) : "nothing";
}

void TomlReader::fail(std::string_view key, std::string_view message) const {
  throw InputError(fmt::format("{}: {}", where(key), message));
}

void TomlReader::missing(std::string_view key, std::string_view message) const {
  for (const auto& [present, node] : *table_) {
    const std::string_view name = present.str();
    if (read_.contains(std::string(name)) || name.size() < 4 || key.size() < 4) continue;
    // Stricter than closest_name: the other keys here have not been read yet
    // and may well be right ("radius_max" is two edits from "radius_min").
    if (edit_distance(name, key) <= 1) {
      fail(name, fmt::format("unknown key; did you mean '{}'? ('{}' is required)", key, key));
    }
  }
  fail(key, message);
}

void TomlReader::expect(bool ok, std::string_view key, std::string_view expected) const {
  if (!ok) fail(key, fmt::format("expected {}, got {}", expected, text(key)));
}

const toml::node* TomlReader::get(std::string_view key) {
  read_.insert(std::string(key));
  return table_->get(key);
}

double TomlReader::to_number(std::string_view key, const toml::node& node) const {
  if (node.is_integer()) return static_cast<double>(*node.value<std::int64_t>());
  if (!node.is_floating_point())
    fail(key, fmt::format("expected a number, got {}", node_text(node)));
  const double value = *node.value<double>();
  if (!std::isfinite(value))
    fail(key, fmt::format("expected a finite number, got {}", node_text(node)));
  return value;
}

double TomlReader::required_number(std::string_view key) {
  if (auto value = optional_number(key)) return *value;
  missing(key, "missing (expected a number)");
}
std::optional<double> TomlReader::optional_number(std::string_view key) {
  const toml::node* node = get(key);
  if (!node) return std::nullopt;
  return to_number(key, *node);
}
double TomlReader::number(std::string_view key, double fallback) {
  return optional_number(key).value_or(fallback);
}

std::int64_t TomlReader::required_integer(std::string_view key) {
  if (auto value = optional_integer(key)) return *value;
  missing(key, "missing (expected an integer)");
}
std::optional<std::int64_t> TomlReader::optional_integer(std::string_view key) {
  const toml::node* node = get(key);
  if (!node) return std::nullopt;
  expect(node->is_integer(), key, "an integer");
  return *node->value<std::int64_t>();
}
std::int64_t TomlReader::integer(std::string_view key, std::int64_t fallback) {
  return optional_integer(key).value_or(fallback);
}

std::string TomlReader::required_string(std::string_view key) {
  if (auto value = optional_string(key)) return *value;
  missing(key, "missing (expected a string)");
}
std::optional<std::string> TomlReader::optional_string(std::string_view key) {
  const toml::node* node = get(key);
  if (!node) return std::nullopt;
  expect(node->is_string(), key, "a string");
  return *node->value<std::string>();
}
std::string TomlReader::string(std::string_view key, std::string fallback) {
  return optional_string(key).value_or(std::move(fallback));
}

std::optional<bool> TomlReader::optional_bool(std::string_view key) {
  const toml::node* node = get(key);
  if (!node) return std::nullopt;
  expect(node->is_boolean(), key, "true or false");
  return *node->value<bool>();
}
bool TomlReader::boolean(std::string_view key, bool fallback) {
  return optional_bool(key).value_or(fallback);
}

std::vector<double> TomlReader::to_numbers(std::string_view key, const toml::node& node,
                                           std::string_view what, std::size_t size) const {
  const toml::array* array = node.as_array();
  const auto is_number = [](const toml::node& n) {
    return n.is_integer() || n.is_floating_point();
  };
  const bool size_ok =
      array && (size == 0 ? array->size() == 2 || array->size() == 3 : array->size() == size);
  if (!size_ok || !std::all_of(array->begin(), array->end(), is_number))
    fail(key, fmt::format("expected {}, got {}", what, node_text(node)));
  std::vector<double> out;
  for (const toml::node& element : *array) out.push_back(to_number(key, element));
  return out;
}

Vec3 TomlReader::to_vec3(std::string_view key, const toml::node& node, std::string_view what,
                         std::size_t size) const {
  const std::vector<double> numbers = to_numbers(key, node, what, size);
  Vec3 v = Vec3::Zero();
  for (std::size_t i = 0; i < numbers.size(); ++i) v[i] = numbers[i];
  return v;
}

Vec3 TomlReader::required_vec3(std::string_view key) {
  if (auto value = optional_vec3(key)) return *value;
  missing(key, "missing (expected [x, y] or [x, y, z])");
}
std::optional<Vec3> TomlReader::optional_vec3(std::string_view key) {
  const toml::node* node = get(key);
  if (!node) return std::nullopt;
  return to_vec3(key, *node, "[x, y] or [x, y, z]");
}
Vec3 TomlReader::vec3(std::string_view key, const Vec3& fallback) {
  return optional_vec3(key).value_or(fallback);
}

std::vector<Vec3> TomlReader::vec3_list(std::string_view key, std::size_t size) {
  const toml::node* node = get(key);
  if (!node) return {};
  const toml::array* array = node->as_array();
  expect(array != nullptr, key, "a list of points [[x, y], ...]");
  const std::string_view what = size == 2 ? "a list of points [[x, y], ...]"
                                          : "a list of points [[x, y], ...] or [[x, y, z], ...]";
  std::vector<Vec3> points;
  for (const toml::node& element : *array) points.push_back(to_vec3(key, element, what, size));
  return points;
}

std::vector<double> TomlReader::required_numbers(std::string_view key, std::size_t size,
                                                 std::string_view what) {
  const toml::node* node = get(key);
  if (!node) missing(key, fmt::format("missing (expected {})", what));
  return to_numbers(key, *node, what, size);
}

std::vector<std::string> TomlReader::string_list(std::string_view key) {
  const toml::node* node = get(key);
  if (!node) return {};
  const toml::array* array = node->as_array();
  expect(array && array->is_homogeneous<std::string>(), key, "a list of strings");
  std::vector<std::string> out;
  for (const toml::node& element : *array) out.push_back(*element.value<std::string>());
  return out;
}

double TomlReader::required_angle(std::string_view key) { return deg2rad(required_number(key)); }
std::optional<double> TomlReader::optional_angle(std::string_view key) {
  auto degrees = optional_number(key);
  return degrees ? std::optional<double>(deg2rad(*degrees)) : std::nullopt;
}
double TomlReader::angle(std::string_view key, double fallback_radians) {
  return optional_angle(key).value_or(fallback_radians);
}

std::optional<std::size_t> TomlReader::choose(std::string_view key,
                                              const std::vector<std::string_view>& names,
                                              bool required) {
  const toml::node* node = get(key);
  if (!node) {
    if (required) missing(key, fmt::format("missing (expected one of {})", join_quoted(names)));
    return std::nullopt;
  }
  const auto value = node->value<std::string>();
  if (node->is_string()) {
    for (std::size_t i = 0; i < names.size(); ++i) {
      if (names[i] == *value) return i;
    }
  }
  std::string message =
      fmt::format("expected one of {}, got {}", join_quoted(names), node_text(*node));
  if (node->is_string()) {
    const std::string guess =
        closest_name(*value, std::vector<std::string>(names.begin(), names.end()));
    if (!guess.empty()) message += fmt::format("; did you mean \"{}\"?", guess);
  }
  fail(key, message);
}

TomlReader TomlReader::child(const toml::table& table, std::string_view key, std::string path,
                             bool array_element) const {
  std::string section = section_.empty() ? std::string(key) : fmt::format("{}.{}", section_, key);
  return TomlReader(table, file_, std::move(section), std::move(path), array_element);
}

std::optional<TomlReader> TomlReader::optional_table(std::string_view key) {
  const toml::node* node = get(key);
  if (!node) return std::nullopt;
  expect(node->is_table(), key, "a table");
  return child(*node->as_table(), key,
               path_.empty() ? std::string(key) : path_ + "." + std::string(key), false);
}

TomlReader TomlReader::required_table(std::string_view key) {
  if (auto table = optional_table(key)) return *table;
  missing(key, "missing (expected a table)");
}

std::vector<TomlReader> TomlReader::tables(std::string_view key) {
  const toml::node* node = get(key);
  if (!node) return {};
  const std::string section =
      section_.empty() ? std::string(key) : section_ + "." + std::string(key);
  const toml::array* array = node->as_array();
  expect(array && std::all_of(array->begin(), array->end(), [](auto& n) { return n.is_table(); }),
         key, fmt::format("an array of tables ([[{}]])", section));
  std::vector<TomlReader> out;
  for (std::size_t i = 0; i < array->size(); ++i) {
    const std::string base = path_.empty() ? std::string(key) : path_ + "." + std::string(key);
    out.push_back(child(*(*array)[i].as_table(), key, fmt::format("{}.{}", base, i), true));
  }
  return out;
}

void TomlReader::reject(const std::vector<std::string_view>& keys, std::string_view why) {
  for (std::string_view key : keys) {
    if (has(key) && !read_.contains(std::string(key))) fail(key, why);
  }
}

void TomlReader::finish() const {
  // Report the first unknown key in file order, so fixes go top to bottom.
  const toml::key* first = nullptr;
  std::size_t first_line = 0;
  for (const auto& [key, node] : *table_) {
    if (read_.contains(std::string(key.str()))) continue;
    const std::size_t at = node.source().begin.line;
    if (!first || at < first_line) {
      first = &key;
      first_line = at;
    }
  }
  if (!first) return;
  const std::vector<std::string> known(read_.begin(), read_.end());
  const std::string guess = closest_name(first->str(), known);
  if (!guess.empty()) fail(first->str(), fmt::format("unknown key; did you mean '{}'?", guess));
  std::string list;
  for (const std::string& name : known) list += (list.empty() ? "" : ", ") + name;
  fail(first->str(), fmt::format("unknown key (known keys here: {})", list));
}

void apply_overrides(toml::table& table, const std::vector<std::string>& sets) {
  for (const std::string& set : sets) {
    if (!is_utf8(set)) throw InputError("--set: the value is not valid UTF-8 text");
    const auto equals = set.find('=');
    const std::string_view key =
        trim(std::string_view(set).substr(0, std::min(equals, set.size())));
    if (equals == std::string::npos || key.empty()) {
      throw InputError(fmt::format("--set {}: expected key=value (e.g. run.duration=0.5)", set));
    }
    std::vector<std::string_view> parts;
    for (std::size_t start = 0;;) {
      const auto dot = key.find('.', start);
      parts.push_back(key.substr(start, dot - start));
      if (parts.back().empty()) throw InputError(fmt::format("--set {}: empty key component", set));
      if (dot == std::string_view::npos) break;
      start = dot + 1;
    }
    const toml::table parsed = parse_override_value(trim(std::string_view(set).substr(equals + 1)));
    const toml::node& value = *parsed.get("value");

    toml::node* container = &table;
    std::string prefix;
    for (std::size_t i = 0; i < parts.size(); ++i) {
      const std::string part(parts[i]);
      const bool last = i + 1 == parts.size();
      if (toml::table* tbl = container->as_table()) {
        if (last) {
          // Copies carry no source position: that is how readers know it came from --set.
          value.visit([&](const auto& v) { tbl->insert_or_assign(part, v); });
        } else {
          if (!tbl->contains(part)) tbl->insert(part, toml::table{});
          container = tbl->get(part);
        }
      } else if (toml::array* array = container->as_array()) {
        const auto index = parse_index(part);
        if (!index || *index >= array->size()) {
          throw InputError(fmt::format("--set {}: '{}' has {} entries, there is no entry '{}'", set,
                                       prefix, array->size(), part));
        }
        if (last) {
          value.visit([&](const auto& v) { array->replace(array->cbegin() + *index, v); });
        } else {
          container = array->get(*index);
        }
      } else {
        throw InputError(fmt::format("--set {}: '{}' is a value, not a table", set, prefix));
      }
      prefix += (prefix.empty() ? "" : ".") + part;
    }
  }
}

}  // namespace talus::io
