#include "calibrate_trial.hpp"

#include <fmt/core.h>

#include <cmath>
#include <fstream>
#include <nlohmann/json.hpp>

#include "commands.hpp"
#include "talus/core/error.hpp"
#include "talus/run/run.hpp"

namespace fs = std::filesystem;

namespace talus::app::calibration {

namespace {

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

std::vector<std::string> trial_sets(const CalibrateOptions& opt, const Assignment& values) {
  auto sets = opt.sets;
  for (const auto& [key, value] : values) sets.push_back(fmt::format("{}={}", key, value));
  return sets;
}

}  // namespace

bool parse_number(const std::string& text, double& value) {
  try {
    std::size_t used = 0;
    value = std::stod(text, &used);
    return used == text.size() && std::isfinite(value);
  } catch (const std::exception&) {
    return false;
  }
}

std::vector<Target> parse_targets(const std::vector<std::string>& texts) {
  if (texts.empty()) throw InputError("talus calibrate: --target needs at least one metric=value");
  std::vector<Target> targets;
  for (const auto& text : texts) {
    const auto eq = text.find('=');
    if (eq == std::string::npos || eq == 0)
      throw InputError(
          fmt::format("--target '{}': expected metric=value, e.g. dam_break.gamma_3=21.562", text));
    Target t{text.substr(0, eq), 0.0};
    if (!parse_number(text.substr(eq + 1), t.value))
      throw InputError(
          fmt::format("--target '{}': '{}' is not a number", text, text.substr(eq + 1)));
    targets.push_back(t);
  }
  return targets;
}

void validate_trial(const CalibrateOptions& opt, const Assignment& values) {
  run::validate(opt.file, trial_sets(opt, values));
}

fs::path output_path(const CalibrateOptions& opt) {
  return opt.out.empty() ? fs::path("runs") / ("calibrate-" + fs::path(opt.file).stem().string())
                         : fs::path(opt.out);
}

fs::path trial_folder(const fs::path& out, std::size_t k) {
  return out / fmt::format("run_{:02d}", k);
}

std::vector<double> run_trial(const CalibrateOptions& opt, const fs::path& out, std::size_t k,
                              const Assignment& values, const std::vector<Target>& targets) {
  RunOptions run;
  run.file = opt.file;
  run.out = trial_folder(out, k).string();
  run.sets = trial_sets(opt, values);
  run.threads = opt.threads;
  run.force = true;
  run.quiet = true;
  try {
    run_command(run);
  } catch (const RunError& e) {
    throw RunError(fmt::format("calibration run {}: {}", run.out, e.what()));
  }
  const fs::path file = fs::path(run.out) / "summary.json";
  nlohmann::json summary;
  std::ifstream(file) >> summary;
  std::vector<double> measured;
  for (const auto& t : targets) measured.push_back(metric(summary, t.metric, file));
  return measured;
}

double objective(const std::vector<double>& measured, const std::vector<Target>& targets,
                 bool squares) {
  double sum = 0.0;
  for (std::size_t i = 0; i < targets.size(); ++i) {
    const double d = measured[i] - targets[i].value;
    sum += squares ? d * d : std::abs(d);
  }
  return sum;
}

void write_results(const fs::path& out, const std::string& md, const std::string& json) {
  std::ofstream(out / "calibration.md") << md;
  std::ofstream(out / "calibration.json") << json << "\n";
  fmt::print("{}\nresults: {}\n", md, (out / "calibration.md").string());
}

}  // namespace talus::app::calibration
