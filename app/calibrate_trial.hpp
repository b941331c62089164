#pragma once
// What the two forms of `talus calibrate` share (calibrate.cpp: the grid
// sweep of one parameter; calibrate_optimize.cpp: the bounded optimiser):
// the targets, validating and running one trial, its metrics, the objective.
#include <cstddef>
#include <filesystem>
#include <string>
#include <utility>
#include <vector>

#include "calibrate.hpp"

namespace talus::app::calibration {

struct Target {
  std::string metric;  // a dotted path in summary.json
  double value = 0.0;
};
// InputError unless there is at least one --target and each is metric=value.
std::vector<Target> parse_targets(const std::vector<std::string>& texts);

// A finite number filling all of `text`, or false.
bool parse_number(const std::string& text, double& value);

// The values of one trial: key=value overrides added after --set.
using Assignment = std::vector<std::pair<std::string, double>>;
// InputError (before anything runs) unless the scenario with these values is
// valid: run::validate, the check of `talus validate`, for every method.
void validate_trial(const CalibrateOptions& opt, const Assignment& values);

// The calibration's output folder: --out, or runs/calibrate-<scenario name>.
std::filesystem::path output_path(const CalibrateOptions& opt);

// Runs trial `k` into OUT/run_KK (quietly) and reads the targets' metrics from
// its summary.json. A failed run is a RunError naming its folder.
std::vector<double> run_trial(const CalibrateOptions& opt, const std::filesystem::path& out,
                              std::size_t k, const Assignment& values,
                              const std::vector<Target>& targets);
std::filesystem::path trial_folder(const std::filesystem::path& out, std::size_t k);

// Sum of |measured - target| over the targets, or of (measured - target)^2.
double objective(const std::vector<double>& measured, const std::vector<Target>& targets,
                 bool squares);

// Writes calibration.md and calibration.json into `out` and prints the table.
void write_results(const std::filesystem::path& out, const std::string& md,
                   const std::string& json);

// The optimiser form (--param): calibrate_optimize.cpp.
int optimize(const CalibrateOptions& opt);

}  // namespace talus::app::calibration
