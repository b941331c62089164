#pragma once
// talus compare: one flume, several methods (DEM, DAN, later MPM), one report.
#include <string>
#include <vector>

namespace talus::app {

struct CompareOptions {
  std::string file, out;
  std::vector<std::string> methods;  // empty: every method the file lists
  int threads = 1;
  bool force = false, quiet = false;
};

int compare_command(const CompareOptions& options);

}  // namespace talus::app
