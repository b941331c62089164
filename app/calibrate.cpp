#include "calibrate.hpp"

#include <fmt/core.h>
#include <fmt/ranges.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>

#include "commands.hpp"
#include "talus/core/error.hpp"
#include "talus/run/output_folder.hpp"
#include "talus/scenario/scenario.hpp"

namespace fs = std::filesystem;

namespace talus::app {

namespace {

struct Target {
  std::string metric;
  double value = 0.0;
};

Target parse_target(const std::string& text) {
  const auto eq = text.find('=');
  Target t;
  if (eq == std::string::npos || eq == 0)
    throw InputError(
        fmt::format("--target '{}': expected metric=value, e.g. dam_break.gamma_3=21.562", text));
  t.metric = text.substr(0, eq);
  try {
    std::size_t used = 0;
    t.value = std::stod(text.substr(eq + 1), &used);
    if (used != text.size() - eq - 1) throw std::invalid_argument("trailing");
  } catch (const std::exception&) {
    throw InputError(fmt::format("--target '{}': '{}' is not a number", text, text.substr(eq + 1)));
  }
  return t;
}

// A dotted path ("dam_break.gamma_3") into summary.json.
double metric(const nlohmann::json& summary, const std::string& path, const fs::path& file) {
  std::string pointer = "/" + path;
  for (char& c : pointer) c = c == '.' ? '/' : c;
  const nlohmann::json::json_pointer p(pointer);
  if (!summary.contains(p) || !summary.at(p).is_number())
    throw RunError(
        fmt::format("{}: no number at '{}' (a metric is a dotted path to a number in "
                    "summary.json)",
                    file.string(), path));
  return summary.at(p).get<double>();
}

}  // namespace

int calibrate_command(const CalibrateOptions& given) {
  CalibrateOptions opt = given;
  opt.file = resolve_scenario(given.file);
  if (opt.values.empty()) throw InputError("talus calibrate: --values needs at least one value");
  if (opt.targets.empty())
    throw InputError("talus calibrate: --target needs at least one metric=value");
  std::vector<Target> targets;
  for (const auto& t : opt.targets) targets.push_back(parse_target(t));
  // Every trial must be valid before anything runs.
  for (double v : opt.values) {
    auto sets = opt.sets;
    sets.push_back(fmt::format("{}={}", opt.parameter, v));
    const auto file = io::load_scenario_file(opt.file, sets);
    if (file.method == "dem") io::parse_dem_scenario(file);
  }
  const fs::path out = opt.out.empty()
                           ? fs::path("runs") / ("calibrate-" + fs::path(opt.file).stem().string())
                           : fs::path(opt.out);
  // Held to the end: the lock, then the record of what talus wrote there.
  const auto folder = run::OutputFolder::claim(out, opt.force);

  std::vector<std::vector<double>> measured(opt.values.size());
  std::vector<double> deviation(opt.values.size(), 0.0);
  for (std::size_t k = 0; k < opt.values.size(); ++k) {
    RunOptions run;
    run.file = opt.file;
    run.out = (out / fmt::format("run_{:02d}", k)).string();
    run.sets = opt.sets;
    run.sets.push_back(fmt::format("{}={}", opt.parameter, opt.values[k]));
    run.threads = opt.threads;
    run.force = true;
    run.quiet = true;
    if (!opt.quiet)
      fmt::print(stderr, "talus calibrate: {} = {} ...\n", opt.parameter, opt.values[k]);
    run_command(run);
    nlohmann::json summary;
    std::ifstream(fs::path(run.out) / "summary.json") >> summary;
    for (const auto& t : targets) {
      measured[k].push_back(metric(summary, t.metric, fs::path(run.out) / "summary.json"));
      deviation[k] += std::abs(measured[k].back() - t.value);
    }
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
  std::ofstream(out / "calibration.md") << md;
  std::ofstream(out / "calibration.json") << j.dump(2) << "\n";
  fmt::print("{}\nresults: {}\n", md, (out / "calibration.md").string());
  return 0;
}

}  // namespace talus::app
