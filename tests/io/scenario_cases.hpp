#pragma once
// The bad-input harness of the scenario tests: each case edits a small valid
// scenario and marks the line the error must name with "# <-" (no mark: the
// message names no line, e.g. a missing top-level key).
#include <gtest/gtest.h>

#include <fstream>
#include <ostream>
#include <sstream>
#include <string>

#include "talus/core/error.hpp"
#include "talus/scenario/scenario.hpp"

namespace talus::io::cases {

// base with `from` replaced by `to`; from must occur exactly once.
inline std::string edit(const std::string& base, const std::string& from, const std::string& to) {
  const auto at = base.find(from);
  EXPECT_NE(at, std::string::npos) << from;
  EXPECT_EQ(base.find(from, at + 1), std::string::npos) << from;
  std::string out = base;
  return at == std::string::npos ? out : out.replace(at, from.size(), to);
}

// 1-based line of the "# <-" mark, 0 if there is none.
inline int marked_line(const std::string& text) {
  int line = 1;
  for (std::size_t i = 0; i < text.size(); ++i) {
    if (text.compare(i, 4, "# <-") == 0) return line;
    if (text[i] == '\n') ++line;
  }
  return 0;
}

// The text of a bundled scenario (scenarios/PATH, e.g. "dem/membrane_sheet_drop.toml").
inline std::string bundled(const std::string& path) {
  std::ifstream in(std::string(TALUS_SOURCE_DIR) + "/scenarios/" + path);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

inline std::string write_temp(const std::string& name, const std::string& text) {
  const std::string path = testing::TempDir() + "talus_" + name + ".toml";
  std::ofstream(path) << text;
  return path;
}

// The message of the InputError that f() throws; a test failure and "" when
// it throws none.
template <typename F>
std::string error_of(F&& f) {
  try {
    f();
  } catch (const InputError& e) {
    return e.what();
  }
  ADD_FAILURE() << "no InputError";
  return "";
}

struct BadCase {
  std::string name;  // also the file name, so messages can be checked for it
  std::string text;
  std::string key;       // must appear quoted: 'key' (or after --set); "" for none
  std::string expected;  // a fragment of the message
};

inline std::ostream& operator<<(std::ostream& out, const BadCase& c) { return out << c.name; }

// Parsing the case's text from a file named talus_<file_prefix><name>.toml
// throws an InputError that starts with "file:line:" (the marked line), quotes
// the key and contains the expected fragment.
inline void expect_input_error(const BadCase& c, const std::string& file_prefix = "") {
  const std::string path = write_temp(file_prefix + c.name, c.text);
  try {
    parse_dem_scenario(load_scenario_file(path, {}));
    FAIL() << "no error for:\n" << c.text;
  } catch (const InputError& e) {
    const std::string message = e.what();
    const int line = marked_line(c.text);
    const std::string head = line > 0 ? path + ":" + std::to_string(line) + ":" : path + ":";
    EXPECT_EQ(message.rfind(head, 0), 0u) << message << "\nexpected to start with " << head;
    if (!c.key.empty()) {
      EXPECT_NE(message.find("'" + c.key + "'"), std::string::npos) << message;
    }
    EXPECT_NE(message.find(c.expected), std::string::npos) << message;
  }
}

}  // namespace talus::io::cases
