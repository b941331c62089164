#pragma once
// talus calibrate: fits free parameters of a scenario to measured numbers by
// running the scenario once per trial and comparing metrics of its
// summary.json with the targets (as Kuen calibrated the grain friction on the
// dam break by hand, Table 7). Two forms: a grid sweep of one parameter
// (-p KEY --values ...) and a bounded optimiser over several (--param, NLopt).
#include <string>
#include <vector>

namespace talus::app {

struct CalibrateOptions {
  std::string file, out;
  std::string parameter;             // grid: a --set key, e.g. materials.0.friction_angle
  std::vector<double> values;        // grid: trial values
  std::vector<std::string> params;   // optimiser: KEY=LO:HI[:START], one per parameter
  std::string optimizer;             // optimiser: bobyqa (default), sbplx, neldermead, cobyla
  std::string objective;             // optimiser: squares (default) or abs
  int max_evals = 0;                 // optimiser: most runs; 0: the default (40)
  double xtol = 0.0;                 // optimiser: step tolerance, fraction of a range; 0: 1e-3
  std::vector<std::string> targets;  // metric=value; metric is a dotted path in summary.json
  std::vector<std::string> sets;
  int threads = 1;
  bool force = false, quiet = false;
};

int calibrate_command(const CalibrateOptions& options);

}  // namespace talus::app
