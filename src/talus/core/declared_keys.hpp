#pragma once
// How a law (contact law, material model, basal rheology) declares itself next
// to its physics: its name, the numeric keys it reads from its table, which of
// them are required, their defaults and ranges. The scenario reader and writer
// work from these declarations, so a new law is a new type plus one entry in
// its family's LawList; nothing else names it.
#include <array>
#include <cstddef>
#include <limits>
#include <string>
#include <string_view>
#include <utility>
#include <variant>

namespace talus {

// An interval a number must lie in.
struct Interval {
  double low = -std::numeric_limits<double>::infinity();
  double high = std::numeric_limits<double>::infinity();
  bool low_open = false, high_open = false;
  constexpr bool contains(double x) const {
    const bool above = low_open ? x > low : x >= low;
    const bool below = high_open ? x < high : x <= high;
    return above && below;
  }
};
constexpr Interval positive() { return {0.0, std::numeric_limits<double>::infinity(), true, true}; }
constexpr Interval non_negative() {
  return {0.0, std::numeric_limits<double>::infinity(), false, true};
}
constexpr Interval between(double low, double high, bool low_open, bool high_open) {
  return {low, high, low_open, high_open};
}

// How the file writes a value that the parameters hold in SI radians.
enum class KeyUnit {
  Plain,         // as stored
  Degrees,       // an angle in degrees, stored in radians
  TanOfDegrees,  // an angle in degrees, stored as its tangent (a friction coefficient)
};

// One numeric key of a law's table, read into P::*field.
template <class P>
struct DeclaredKey {
  std::string_view name;
  double P::*field;
  bool required = false;
  double fallback = 0.0;  // when absent and not required (in stored units)
  Interval range{};       // in the file's units (degrees for angles)
  KeyUnit unit = KeyUnit::Plain;
  // When absent: the value of this other key instead of `fallback`.
  std::string_view fallback_key{};
};

template <class P>
constexpr DeclaredKey<P> required_key(std::string_view name, double P::*field, Interval range,
                                      KeyUnit unit = KeyUnit::Plain) {
  return {name, field, true, 0.0, range, unit, {}};
}
template <class P>
constexpr DeclaredKey<P> optional_key(std::string_view name, double P::*field, double fallback,
                                      Interval range, KeyUnit unit = KeyUnit::Plain) {
  return {name, field, false, fallback, range, unit, {}};
}

// Concatenates key lists (a family's shared keys and a law's own).
template <class T, std::size_t N, std::size_t M>
constexpr std::array<T, N + M> join(const std::array<T, N>& a, const std::array<T, M>& b) {
  std::array<T, N + M> out{};
  for (std::size_t i = 0; i < N; ++i) out[i] = a[i];
  for (std::size_t i = 0; i < M; ++i) out[N + i] = b[i];
  return out;
}

// A check across keys that a law makes after reading (dilatancy below
// friction, two exclusive forms): the key to blame and what was expected.
struct KeyProblem {
  std::string_view key;
  std::string message;  // empty: no problem
  explicit operator bool() const { return !message.empty(); }
};

// A family of laws: each Law has `static constexpr std::string_view name`.
template <class... Laws>
struct LawList {
  static constexpr std::size_t size = sizeof...(Laws);
  static constexpr std::array<std::string_view, size> names{Laws::name...};
  // One value of any of the laws (for families held per material).
  using Variant = std::variant<Laws...>;

  // Index of the law called `name`, or size when there is none.
  static constexpr std::size_t index_of(std::string_view name) {
    for (std::size_t i = 0; i < size; ++i)
      if (names[i] == name) return i;
    return size;
  }

  // Calls f.template operator()<Law>() for the law at `index` and returns its
  // result (the index must be valid).
  template <class F>
  static decltype(auto) visit(std::size_t index, F&& f) {
    return visit_from<0, Laws...>(index, std::forward<F>(f));
  }

  // Calls f.template operator()<Law>() for every law in order.
  template <class F>
  static void for_each(F&& f) {
    (f.template operator()<Laws>(), ...);
  }

 private:
  template <std::size_t I, class First, class... Rest, class F>
  static decltype(auto) visit_from(std::size_t index, F&& f) {
    if constexpr (sizeof...(Rest) == 0) {
      return f.template operator()<First>();
    } else {
      if (index == I) return f.template operator()<First>();
      return visit_from<I + 1, Rest...>(index, std::forward<F>(f));
    }
  }
};

}  // namespace talus
