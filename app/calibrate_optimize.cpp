// talus calibrate --param: several parameters fitted within bounds by a
// derivative-free NLopt algorithm, one run per evaluation of the objective.
#include <fmt/core.h>
#include <nlopt.h>

#include <algorithm>
#include <cmath>
#include <exception>
#include <map>
#include <memory>
#include <nlohmann/json.hpp>

#include "calibrate_trial.hpp"
#include "talus/core/error.hpp"
#include "talus/run/output_folder.hpp"

namespace fs = std::filesystem;

namespace talus::app::calibration {

namespace {

constexpr int default_max_evals = 40;
constexpr double default_xtol = 1e-3;
// The first steps, as a fraction of each parameter's range.
constexpr double initial_step = 0.25;

const std::map<std::string, nlopt_algorithm> algorithms = {{"bobyqa", NLOPT_LN_BOBYQA},
                                                           {"sbplx", NLOPT_LN_SBPLX},
                                                           {"neldermead", NLOPT_LN_NELDERMEAD},
                                                           {"cobyla", NLOPT_LN_COBYLA}};

struct Bound {
  std::string key;
  double low = 0.0, high = 0.0, start = 0.0;
  double value(double scaled) const { return low + std::clamp(scaled, 0.0, 1.0) * (high - low); }
};

// KEY=LO:HI[:START]; START defaults to the middle.
Bound parse_param(const std::string& text) {
  const auto fail = [&](const std::string& why) {
    return InputError(fmt::format("--param '{}': {}", text, why));
  };
  const auto eq = text.find('=');
  if (eq == std::string::npos || eq == 0)
    throw fail("expected KEY=LO:HI or KEY=LO:HI:START, e.g. material.basal_friction=15:30");
  Bound b{text.substr(0, eq)};
  std::vector<std::string> parts;
  for (std::size_t from = eq + 1;;) {
    const auto colon = text.find(':', from);
    parts.push_back(text.substr(from, colon - from));
    if (colon == std::string::npos) break;
    from = colon + 1;
  }
  if (parts.size() != 2 && parts.size() != 3)
    throw fail("expected KEY=LO:HI or KEY=LO:HI:START, e.g. material.basal_friction=15:30");
  double* numbers[] = {&b.low, &b.high, &b.start};
  for (std::size_t i = 0; i < parts.size(); ++i)
    if (!parse_number(parts[i], *numbers[i]))
      throw fail(fmt::format("'{}' is not a number", parts[i]));
  if (!(b.low < b.high)) throw fail("the low bound must be below the high bound");
  if (parts.size() == 2) b.start = 0.5 * (b.low + b.high);
  if (b.start < b.low || b.start > b.high) throw fail("the start lies outside the bounds");
  return b;
}

struct Evaluation {
  std::vector<double> values, measured;
  double objective = 0.0;
};

struct Search {
  const CalibrateOptions& opt;
  const std::vector<Bound>& bounds;
  const std::vector<Target>& targets;
  fs::path out;
  bool squares = true;
  nlopt_opt nl = nullptr;
  std::vector<Evaluation> evaluations;
  std::exception_ptr error;  // a failed run: NLopt is C, so it stops and we rethrow after
};

double evaluate(unsigned n, const double* x, double* /*gradient*/, void* data) {
  auto& s = *static_cast<Search*>(data);
  try {
    Evaluation e;
    Assignment a;
    for (unsigned i = 0; i < n; ++i) {
      e.values.push_back(s.bounds[i].value(x[i]));
      a.emplace_back(s.bounds[i].key, e.values.back());
    }
    const std::size_t k = s.evaluations.size();
    e.measured = run_trial(s.opt, s.out, k, a, s.targets);
    e.objective = objective(e.measured, s.targets, s.squares);
    s.evaluations.push_back(e);
    if (!s.opt.quiet) {
      std::string line;
      for (const auto& [key, value] : a) line += fmt::format("{} = {:.6g}, ", key, value);
      fmt::print(stderr, "talus calibrate: {} ({}): {}objective {:.6g}\n",
                 trial_folder(s.out, k).filename().string(), k + 1, line, e.objective);
    }
    return e.objective;
  } catch (...) {
    s.error = std::current_exception();
    nlopt_force_stop(s.nl);
    return HUGE_VAL;
  }
}

std::string reason(nlopt_result r) {
  switch (r) {
    case NLOPT_SUCCESS:  // BOBYQA: its model foresaw no further decrease
      return "it ended without a more specific reason (BOBYQA: its model foresaw no decrease)";
    case NLOPT_STOPVAL_REACHED:
      return "the objective reached the stop value";
    case NLOPT_FTOL_REACHED:
      return "the objective changed by less than its tolerance";
    case NLOPT_XTOL_REACHED:
      return "the steps became smaller than --xtol of every range";
    case NLOPT_MAXEVAL_REACHED:
      return "--max-evals evaluations were spent";
    case NLOPT_MAXTIME_REACHED:
      return "the time limit was reached";
    case NLOPT_ROUNDOFF_LIMITED:
      return "round-off limited the progress (the objective is noisy at this scale)";
    case NLOPT_FORCED_STOP:
      return "a run failed";
    case NLOPT_OUT_OF_MEMORY:
      return "out of memory";
    case NLOPT_INVALID_ARGS:
      return "invalid arguments";
    default:
      return "failure";
  }
}

// calibration.md: one row per evaluation, the best one marked.
std::string table(const Search& s, std::size_t best, const std::string& objective_name) {
  std::string md = "| run |";
  for (const auto& b : s.bounds) md += fmt::format(" {} |", b.key);
  for (const auto& t : s.targets) md += fmt::format(" {} |", t.metric);
  md += fmt::format(" {} |\n|---|", objective_name);
  for (std::size_t i = 0; i < s.bounds.size() + s.targets.size() + 1; ++i) md += "---|";
  md += "\n| target |";
  for (std::size_t i = 0; i < s.bounds.size(); ++i) md += " |";
  for (const auto& t : s.targets) md += fmt::format(" {} |", t.value);
  md += " 0 |\n";
  for (std::size_t k = 0; k < s.evaluations.size(); ++k) {
    const auto& e = s.evaluations[k];
    const std::string name = trial_folder(s.out, k).filename().string();
    md += k == best ? fmt::format("| **{} (best)** |", name) : fmt::format("| {} |", name);
    for (double v : e.values) md += fmt::format(" {:.6g} |", v);
    for (double m : e.measured) md += fmt::format(" {:.6g} |", m);
    md += fmt::format(" {:.6g} |\n", e.objective);
  }
  return md;
}

}  // namespace

int optimize(const CalibrateOptions& opt) {
  const std::string algorithm = opt.optimizer.empty() ? "bobyqa" : opt.optimizer;
  if (!algorithms.count(algorithm))
    throw InputError(
        fmt::format("--optimizer '{}': one of bobyqa, sbplx, neldermead, cobyla", algorithm));
  const bool squares = opt.objective.empty() || opt.objective == "squares";
  if (!squares && opt.objective != "abs")
    throw InputError(fmt::format("--objective '{}': abs or squares", opt.objective));
  const int max_evals = opt.max_evals > 0 ? opt.max_evals : default_max_evals;
  const double xtol = opt.xtol > 0 ? opt.xtol : default_xtol;
  const auto targets = parse_targets(opt.targets);
  std::vector<Bound> bounds;
  for (const auto& text : opt.params) {
    bounds.push_back(parse_param(text));
    for (std::size_t i = 0; i + 1 < bounds.size(); ++i)
      if (bounds[i].key == bounds.back().key)
        throw InputError(fmt::format("--param {}: given twice", bounds.back().key));
  }
  // Every trial must be valid before anything runs: each parameter at its low
  // bound, its high bound, its start and a point inside that is no round
  // number (an integer-only key is refused here), the others at their starts.
  Assignment starts;
  for (const auto& b : bounds) starts.emplace_back(b.key, b.start);
  validate_trial(opt, starts);
  for (std::size_t i = 0; i < bounds.size(); ++i) {
    for (double v : {bounds[i].low, bounds[i].high, bounds[i].value(0.381966)}) {
      auto a = starts;
      a[i].second = v;
      validate_trial(opt, a);
    }
  }
  const fs::path out = output_path(opt);
  // Held to the end: the lock, then the record of what talus wrote there.
  const auto folder = run::OutputFolder::claim(out, opt.force);

  // NLopt works on each parameter scaled to [0, 1], so that bounds of
  // different magnitudes weigh alike in its steps and in --xtol.
  const unsigned n = static_cast<unsigned>(bounds.size());
  std::unique_ptr<nlopt_opt_s, decltype(&nlopt_destroy)> nl(
      nlopt_create(algorithms.at(algorithm), n), nlopt_destroy);
  Search s{opt, bounds, targets, out, squares, nl.get(), {}, {}};
  std::vector<double> x;
  for (const auto& b : bounds) x.push_back((b.start - b.low) / (b.high - b.low));
  nlopt_set_lower_bounds1(nl.get(), 0.0);
  nlopt_set_upper_bounds1(nl.get(), 1.0);
  nlopt_set_min_objective(nl.get(), evaluate, &s);
  nlopt_set_maxeval(nl.get(), max_evals);
  nlopt_set_xtol_abs1(nl.get(), xtol);
  nlopt_set_initial_step1(nl.get(), initial_step);
  double fmin = 0.0;
  const nlopt_result result = nlopt_optimize(nl.get(), x.data(), &fmin);
  const std::string nlopt_name = nlopt_algorithm_to_string(algorithms.at(algorithm));
  if (s.evaluations.empty() && !s.error)
    throw RunError(fmt::format("NLopt {} did not start: {}", nlopt_name, reason(result)));

  // The best run of those made (NLopt's minimum is one of them).
  std::size_t best = 0;
  for (std::size_t k = 1; k < s.evaluations.size(); ++k)
    if (s.evaluations[k].objective < s.evaluations[best].objective) best = k;
  const std::string objective_name =
      squares ? "sum of squared deviations" : "sum of abs. deviations";
  std::string md = s.evaluations.empty() ? std::string() : table(s, best, objective_name);
  nlohmann::json j = {{"scenario", opt.file},
                      {"method", "optimizer"},
                      {"optimizer", nlopt_name},
                      {"objective", squares ? "squares" : "abs"},
                      {"max_evals", max_evals},
                      {"xtol", xtol},
                      {"evaluation_count", s.evaluations.size()},
                      {"nlopt_result", static_cast<int>(result)},
                      {"nlopt_result_name", nlopt_result_to_string(result)},
                      {"stop_reason", reason(result)}};
  for (const auto& b : bounds)
    j["parameters"].push_back(
        {{"key", b.key}, {"low", b.low}, {"high", b.high}, {"start", b.start}});
  for (const auto& t : targets) j["targets"][t.metric] = t.value;
  j["evaluations"] = nlohmann::json::array();
  for (std::size_t k = 0; k < s.evaluations.size(); ++k) {
    const auto& e = s.evaluations[k];
    nlohmann::json row = {{"run", trial_folder(out, k).filename().string()},
                          {"objective", e.objective}};
    for (std::size_t i = 0; i < n; ++i) row["values"][bounds[i].key] = e.values[i];
    for (std::size_t i = 0; i < targets.size(); ++i)
      row["measured"][targets[i].metric] = e.measured[i];
    j["evaluations"].push_back(row);
  }
  if (!s.evaluations.empty()) {
    const auto& e = s.evaluations[best];
    j["best_run"] = trial_folder(out, best).filename().string();
    j["best_objective"] = e.objective;
    std::string values;
    for (std::size_t i = 0; i < n; ++i) {
      j["best_values"][bounds[i].key] = e.values[i];
      values += fmt::format("{}{} = {:.6g}", i ? ", " : "", bounds[i].key, e.values[i]);
    }
    md += fmt::format("\nBest of {} evaluations: {} ({} {:.6g}, {}).\n", s.evaluations.size(),
                      values, objective_name, e.objective, j["best_run"].get<std::string>());
  }
  md += fmt::format("NLopt {} stopped: {} ({}).\n", nlopt_name, reason(result),
                    nlopt_result_to_string(result));
  write_results(out, md, j.dump(2));
  if (s.error) std::rethrow_exception(s.error);
  return 0;
}

}  // namespace talus::app::calibration
