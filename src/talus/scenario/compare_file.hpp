#pragma once
// A comparison file (method = "compare"): one flume, one scenario file per
// method, run side by side by `talus compare`.
//
//   method = "compare"
//   name = "flume_A"
//   [methods]
//   dem = "../dem/flume_A_model3.toml"   (relative to this file)
//   dan = "../runout/runout_flume_A.toml"
#include <map>
#include <string>

namespace talus::io {

struct CompareFile {
  std::string path, name, description;
  std::map<std::string, std::string> methods;  // method -> scenario path (resolved)
};

// Throws InputError (file:line:key) for unknown keys or methods, missing
// files; the scenarios themselves are checked by the caller.
CompareFile read_compare_file(const std::string& path);

// The method names a comparison knows, in report order.
inline constexpr const char* kCompareMethods[] = {"dem", "dan", "fv2d", "two_phase", "mpm"};

}  // namespace talus::io
