#pragma once
#include <string>
#include <vector>

namespace talus::app {

struct RunOptions {
  std::string file, out, resume;
  std::string backend;  // "cpu" | "gpu": sets run.backend (DEM)
  std::vector<std::string> sets;
  int threads = 0;  // 0: one, or for --resume the run's own
  bool force = false, quiet = false;
  bool allow_long_run = false;
  double log_seconds = 10.0;
};
struct ValidateOptions {
  std::string file;
  std::string backend;
  std::vector<std::string> sets;
  bool allow_long_run = false;
};

int run_command(const RunOptions& options);
int validate_command(const ValidateOptions& options);
int list_command();

// A scenario argument: a file as given, or the name of a bundled scenario
// ("column_collapse" for scenarios/dem/column_collapse.toml). InputError if
// neither, or if files in two sub-folders share the name.
std::string resolve_scenario(const std::string& arg);

// Folder of the bundled scenarios: $TALUS_SCENARIOS, else the source tree's.
std::string scenarios_folder();

}  // namespace talus::app
