#pragma once
// Reading TOML input tables with error messages that name the file, the line
// and the key. A TomlReader wraps one table, remembers which keys were asked
// for, and reports every key nobody asked for as unknown (with a "did you
// mean" suggestion), so typos never pass silently. Shared by all solvers.
#include <toml++/toml.h>

#include <cstdint>
#include <optional>
#include <set>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "talus/core/space.hpp"

namespace talus::io {

// Names and values of an enumerated option, in the order shown to users.
template <typename E>
using EnumNames = std::vector<std::pair<std::string_view, E>>;

class TomlReader {
 public:
  // file: shown in messages. section: the table's name as in the file
  // ("run", "walls.motion"; "" for the root). path: the dotted key that --set
  // would use ("materials.0"). array_element: shown as [[section]].
  TomlReader(const toml::table& table, std::string file, std::string section = "",
             std::string path = "", bool array_element = false);

  const toml::table& table() const { return *table_; }
  const std::string& file() const { return file_; }
  // "[run]", "[[materials]]", or "" for the root table.
  std::string label() const;
  // Line of the table's header (0 when unknown, e.g. created by --set).
  int line() const;

  // Present in the table; does not count as reading it.
  bool has(std::string_view key) const;
  bool is_number(std::string_view key) const;
  bool is_string(std::string_view key) const;

  // Numbers: integers are accepted; NaN and infinities are not.
  double required_number(std::string_view key);
  std::optional<double> optional_number(std::string_view key);
  double number(std::string_view key, double fallback);

  std::int64_t required_integer(std::string_view key);
  std::optional<std::int64_t> optional_integer(std::string_view key);
  std::int64_t integer(std::string_view key, std::int64_t fallback);

  std::string required_string(std::string_view key);
  std::optional<std::string> optional_string(std::string_view key);
  std::string string(std::string_view key, std::string fallback);

  std::optional<bool> optional_bool(std::string_view key);
  bool boolean(std::string_view key, bool fallback);

  // An array of 2 or 3 numbers; with 2 numbers z = 0.
  Vec3 required_vec3(std::string_view key);
  std::optional<Vec3> optional_vec3(std::string_view key);
  Vec3 vec3(std::string_view key, const Vec3& fallback);
  // An array of such arrays (polygon, triangle vertices); empty when absent.
  // size 2: every point must be [x, y] (a third number is an error).
  std::vector<Vec3> vec3_list(std::string_view key, std::size_t size = 0);
  // An array of exactly `size` numbers that is not a point (what: "[start,
  // end] in s"): a missing or an extra number is an error.
  std::vector<double> required_numbers(std::string_view key, std::size_t size,
                                       std::string_view what);
  std::vector<std::string> string_list(std::string_view key);

  // Angles are written in degrees and returned in radians.
  double required_angle(std::string_view key);
  std::optional<double> optional_angle(std::string_view key);
  double angle(std::string_view key, double fallback_radians);

  // One of a list of names.
  template <typename E>
  E required_enum(std::string_view key, const EnumNames<E>& names) {
    return names[*choose(key, names_of(names), true)].second;
  }
  template <typename E>
  E enumeration(std::string_view key, const EnumNames<E>& names, E fallback) {
    auto index = choose(key, names_of(names), false);
    return index ? names[*index].second : fallback;
  }

  // Sub-tables (inline or not) and arrays of tables; each child reader must be
  // finished by the caller.
  std::optional<TomlReader> optional_table(std::string_view key);
  TomlReader required_table(std::string_view key);
  std::vector<TomlReader> tables(std::string_view key);

  // "file:line: [section] 'key'" for messages; the line of the key when
  // present, else of the table.
  std::string file_of(const toml::node* node) const;
  std::string where(std::string_view key) const;
  // The value as written in the file ("-3", "\"abc\"", "[1, 2]").
  std::string text(std::string_view key) const;
  [[noreturn]] void fail(std::string_view key, std::string_view message) const;
  // For a required key that is absent: when an unread key looks like a typo
  // of it ("duraton"), reports that key instead; else fails with message.
  [[noreturn]] void missing(std::string_view key, std::string_view message) const;
  // Fails with "expected <expected>, got <value>" unless ok.
  void expect(bool ok, std::string_view key, std::string_view expected) const;
  // Fails for each of these keys that is present: they belong to another
  // variant of this table (why: "is not used by walls of type 'plane'").
  void reject(const std::vector<std::string_view>& keys, std::string_view why);
  // Marks a key as read without reading it (kept for later checks).
  void mark_read(std::string_view key) { read_.insert(std::string(key)); }
  // Throws for the first key that was never read.
  void finish() const;

 private:
  const toml::node* get(std::string_view key);  // marks the key as read
  double to_number(std::string_view key, const toml::node& node) const;
  Vec3 to_vec3(std::string_view key, const toml::node& node, std::string_view what,
               std::size_t size = 0) const;
  // Exactly size numbers, or (size 0) 2 or 3.
  std::vector<double> to_numbers(std::string_view key, const toml::node& node,
                                 std::string_view what, std::size_t size) const;
  std::optional<std::size_t> choose(std::string_view key,
                                    const std::vector<std::string_view>& names, bool required);
  template <typename E>
  static std::vector<std::string_view> names_of(const EnumNames<E>& names) {
    std::vector<std::string_view> out;
    for (const auto& entry : names) out.push_back(entry.first);
    return out;
  }
  TomlReader child(const toml::table& table, std::string_view key, std::string path,
                   bool array_element) const;

  const toml::table* table_;
  std::string file_, section_, path_;
  bool array_element_;
  std::set<std::string> read_;
};

// The candidate closest to word when it is close enough to be a likely typo,
// else "".
std::string closest_name(std::string_view word, const std::vector<std::string>& candidates);

// The value of a node as written in TOML, shortened for messages.
std::string node_text(const toml::node& node);

// Applies "--set key=value" overrides: dotted keys, integer components index
// arrays ("materials.0.friction=0.3"); the value is parsed as TOML and taken
// as a string when that fails. Missing tables on the way are created; values
// set here carry no source line, so readers report them as coming from --set.
void apply_overrides(toml::table& table, const std::vector<std::string>& sets);

// The name that ends the path of a scenario built from a Python dict (its
// folder resolves relative paths; python/talus/__init__.py): its values come
// as overrides without lines, and messages name them by their dotted path
// in the dict rather than as --set.
inline constexpr std::string_view kDictScenario = "(dict)";
inline bool is_dict_scenario(std::string_view path) { return path.ends_with(kDictScenario); }

}  // namespace talus::io
