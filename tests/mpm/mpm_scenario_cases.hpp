#pragma once
// Helpers of the MPM scenario-file tests: edit a valid scenario text and expect
// the parser to refuse it with a message containing a given piece (file, line,
// key).
#include <gtest/gtest.h>

#include <string>

#include "talus/core/error.hpp"
#include "talus/scenario/scenario_mpm.hpp"

namespace talus::io::mpm_cases {

// `text` with the first `from` replaced by `to` (the test fails if `from` is absent).
inline std::string edit(std::string text, const std::string& from, const std::string& to) {
  const auto at = text.find(from);
  EXPECT_NE(at, std::string::npos) << from;
  if (at == std::string::npos) return text;
  return text.replace(at, from.size(), to);
}

inline void expect_error(const std::string& text, const std::string& needle) {
  try {
    parse_mpm_scenario(load_scenario_text(text, "bad.toml"));
    FAIL() << "no error for: " << needle;
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find(needle), std::string::npos) << e.what();
  }
}

}  // namespace talus::io::mpm_cases
