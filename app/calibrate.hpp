#pragma once
// talus calibrate: fits one free parameter of a scenario to measured numbers by
// running the scenario once per trial value and comparing metrics of its
// summary.json with the targets (as Kuen calibrated the grain friction on the
// dam break by hand, Table 7).
#include <string>
#include <vector>

namespace talus::app {

struct CalibrateOptions {
  std::string file, out;
  std::string parameter;             // a --set key, e.g. materials.0.friction_angle
  std::vector<double> values;        // trial values
  std::vector<std::string> targets;  // metric=value; metric is a dotted path in summary.json
  std::vector<std::string> sets;
  int threads = 1;
  bool force = false, quiet = false;
};

int calibrate_command(const CalibrateOptions& options);

}  // namespace talus::app
