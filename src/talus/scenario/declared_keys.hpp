#pragma once
// Reading and writing the keys that laws declare (core/declared_keys.hpp):
// the reader knows no law by name; it asks the family's LawList.
#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <nlohmann/json.hpp>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "talus/core/declared_keys.hpp"
#include "talus/scenario/scenario_detail.hpp"

namespace talus::io::detail {

// "a positive number", "an angle in [0, 90) degrees".
std::string describe_key(const Interval& range, KeyUnit unit);
// From the file's units to the stored ones and back.
double to_stored(double value, KeyUnit unit);
double to_file(double value, KeyUnit unit);

// The names of a family's laws, for TomlReader::enumeration; the value is the
// law's index in the family.
template <class Laws>
EnumNames<std::size_t> law_names() {
  EnumNames<std::size_t> names;
  for (std::size_t i = 0; i < Laws::size; ++i) names.emplace_back(Laws::names[i], i);
  return names;
}

template <class P>
bool declares(std::span<const DeclaredKey<P>> keys, std::string_view name) {
  return std::any_of(keys.begin(), keys.end(), [&](const auto& k) { return k.name == name; });
}

// Reads keys into p in order: a required key must be present; an absent
// optional one takes its fallback (or the value of its fallback_key, read
// before it). With keep_absent, an absent key of any kind leaves p as it is.
// needed_by says who requires the keys in the message for a missing one.
template <class P>
void read_keys(TomlReader& r, std::span<const DeclaredKey<P>> keys, P& p, bool keep_absent = false,
               std::string_view needed_by = {}) {
  for (const DeclaredKey<P>& key : keys) {
    const std::string expected = describe_key(key.range, key.unit);
    if (r.has(key.name) && !r.is_number(key.name)) r.expect(false, key.name, expected);
    if (const auto value = r.optional_number(key.name)) {
      r.expect(key.range.contains(*value), key.name, expected);
      p.*key.field = to_stored(*value, key.unit);
    } else if (keep_absent) {
      continue;
    } else if (key.required) {
      r.missing(key.name, needed_by.empty() ? fmt::format("missing (expected {})", expected)
                                            : fmt::format("missing: {} needs it (expected {})",
                                                          needed_by, expected));
    } else if (!key.fallback_key.empty()) {
      const auto other = std::find_if(keys.begin(), keys.end(),
                                      [&](const auto& k) { return k.name == key.fallback_key; });
      p.*key.field = p.*other->field;
    } else {
      p.*key.field = key.fallback;
    }
  }
}

// What a table does with keys that only other laws of its family declare.
enum class OtherLaws {
  Refuse,  // "is not used by <what> '<name>'" (a material has one law)
  Accept,  // read when present, else left as they are (DEM materials serve
           // whichever contact law the run names, and a --set may switch it)
};

// Reads the keys of the family's law number `law` into p, then the law's own
// check across keys.
template <class Laws, class P>
void read_law(TomlReader& r, std::size_t law, P& p, std::string_view what, OtherLaws others) {
  Laws::visit(law, [&]<class Law>() {
    const std::span<const DeclaredKey<P>> own(Law::keys);
    read_keys(r, own, p, false, fmt::format("{} = \"{}\"", what, Law::name));
    std::vector<std::string_view> foreign;
    Laws::for_each([&]<class Other>() {
      for (const DeclaredKey<P>& key : Other::keys)
        if (!declares(own, key.name) &&
            std::find(foreign.begin(), foreign.end(), key.name) == foreign.end()) {
          foreign.push_back(key.name);
          if (others == OtherLaws::Accept) read_keys(r, std::span(&key, 1), p, true);
        }
    });
    if (others == OtherLaws::Refuse)
      r.reject(foreign, fmt::format("is not used by {} '{}'", what, Law::name));
    if (const KeyProblem problem = Law::check(p)) r.fail(problem.key, problem.message);
  });
}

// Writes every key of the law whose value is finite (an infinite default,
// such as no tension cut-off, stays out), in the file's units.
template <class Laws, class P>
void write_law(nlohmann::ordered_json& j, std::size_t law, const P& p) {
  Laws::visit(law, [&]<class Law>() {
    for (const DeclaredKey<P>& key : Law::keys)
      if (std::isfinite(p.*key.field)) j[std::string(key.name)] = to_file(p.*key.field, key.unit);
  });
}

}  // namespace talus::io::detail
