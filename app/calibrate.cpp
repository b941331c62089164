#include "calibrate.hpp"

#include <fmt/core.h>
#include <fmt/ranges.h>

#include <filesystem>
#include <nlohmann/json.hpp>

#include "calibrate_trial.hpp"
#include "commands.hpp"
#include "talus/core/error.hpp"
#include "talus/run/output_folder.hpp"

namespace fs = std::filesystem;

namespace talus::app {

using namespace calibration;

namespace {

// The grid form: one run per trial value of one parameter.
int sweep(const CalibrateOptions& opt) {
  if (opt.parameter.empty() || opt.values.empty())
    throw InputError(
        "talus calibrate: give -p KEY --values v1,v2,... (grid sweep) or --param "
        "KEY=LO:HI[:START] (optimiser)");
  const auto targets = parse_targets(opt.targets);
  // Every trial must be valid before anything runs.
  for (double v : opt.values) validate_trial(opt, {{opt.parameter, v}});
  const fs::path out = output_path(opt);
  // Held to the end: the lock, then the record of what talus wrote there.
  const auto folder = run::OutputFolder::claim(out, opt.force);

  std::vector<std::vector<double>> measured(opt.values.size());
  std::vector<double> deviation(opt.values.size(), 0.0);
  for (std::size_t k = 0; k < opt.values.size(); ++k) {
    if (!opt.quiet)
      fmt::print(stderr, "talus calibrate: {} = {} ...\n", opt.parameter, opt.values[k]);
    measured[k] = run_trial(opt, out, k, {{opt.parameter, opt.values[k]}}, targets);
    deviation[k] = objective(measured[k], targets, false);
  }
  std::size_t best = 0;
  for (std::size_t k = 1; k < deviation.size(); ++k) {
    if (deviation[k] < deviation[best]) best = k;
  }

  // The table of Kuen's Table 7: one column per trial value.
  std::string md = fmt::format("| {} | target |", opt.parameter);
  for (double v : opt.values) md += fmt::format(" {} |", v);
  md += "\n|---|---|";
  for (std::size_t k = 0; k < opt.values.size(); ++k) md += "---|";
  md += "\n";
  for (std::size_t i = 0; i < targets.size(); ++i) {
    md += fmt::format("| {} | {} |", targets[i].metric, targets[i].value);
    for (std::size_t k = 0; k < opt.values.size(); ++k)
      md += fmt::format(" {:.3f} |", measured[k][i]);
    md += "\n";
  }
  md += "| sum of abs. deviations | 0 |";
  for (double d : deviation) md += fmt::format(" {:.3f} |", d);
  md += fmt::format("\n\nBest of the trial values: {} = {} (sum of deviations {:.3f}).\n",
                    opt.parameter, opt.values[best], deviation[best]);

  nlohmann::json j = {{"scenario", opt.file},           {"parameter", opt.parameter},
                      {"values", opt.values},           {"deviation_sum", deviation},
                      {"best_value", opt.values[best]}, {"best_deviation_sum", deviation[best]}};
  for (std::size_t i = 0; i < targets.size(); ++i) {
    std::vector<double> column;
    for (const auto& m : measured) column.push_back(m[i]);
    j["targets"][targets[i].metric] = {{"target", targets[i].value}, {"measured", column}};
  }
  // Between trial values: the vertex of the parabola through the best value and
  // its neighbours, when it lies between them. Not run; a hint for a finer sweep.
  if (best > 0 && best + 1 < opt.values.size()) {
    const double x0 = opt.values[best - 1], x1 = opt.values[best], x2 = opt.values[best + 1];
    const double y0 = deviation[best - 1], y1 = deviation[best], y2 = deviation[best + 1];
    const double den = (x0 - x1) * (x0 - x2) * (x1 - x2);
    const double a = (x2 * (y1 - y0) + x1 * (y0 - y2) + x0 * (y2 - y1)) / den;
    const double b = (x2 * x2 * (y0 - y1) + x1 * x1 * (y2 - y0) + x0 * x0 * (y1 - y2)) / den;
    if (a > 0) {
      const double vertex = -b / (2 * a);
      if (vertex > std::min(x0, x2) && vertex < std::max(x0, x2)) {
        j["parabola_vertex"] = vertex;
        md += fmt::format(
            "Parabola through the best value and its neighbours: minimum near {:.3f} "
            "(not run).\n",
            vertex);
      }
    }
  }
  write_results(out, md, j.dump(2));
  return 0;
}

}  // namespace

int calibrate_command(const CalibrateOptions& given) {
  CalibrateOptions opt = given;
  opt.file = resolve_scenario(given.file);
  if (opt.params.empty()) {
    if (!opt.optimizer.empty() || !opt.objective.empty() || opt.max_evals > 0 || opt.xtol > 0)
      throw InputError(
          "talus calibrate: --optimizer, --objective, --max-evals and --xtol are for the "
          "optimiser (--param); the grid sweep reports the sum of absolute deviations");
    return sweep(opt);
  }
  if (!opt.parameter.empty() || !opt.values.empty())
    throw InputError(
        "talus calibrate: -p/--values (grid sweep) and --param (optimiser) are two forms; give "
        "one");
  return optimize(opt);
}

}  // namespace talus::app
