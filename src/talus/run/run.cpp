#include "talus/run/run.hpp"

#include <fmt/core.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <optional>

#include "talus/core/error.hpp"
#include "talus/core/version.hpp"
#include "talus/run/experiment.hpp"
#include "talus/run/method.hpp"
#include "talus/run/run_log.hpp"
#include "talus/run/step_limit.hpp"
#include "talus/run/summary.hpp"
#include "talus/scenario/compare_file.hpp"
#include "talus/scenario/scenario.hpp"

namespace fs = std::filesystem;

namespace talus::run {

namespace {

double seconds_since(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

// "file:line:" of the scenario's name.
std::string where_name(const io::ScenarioFile& file) {
  const auto* node = file.table.get("name");
  const int line = node ? static_cast<int>(node->source().begin.line) : 0;
  return line > 0 ? fmt::format("{}:{}:", file.path, line) : file.path + ":";
}

// A resumed run continues the run in its folder exactly as it was set up, so
// whatever would change it is refused rather than ignored.
void check_resumable(const RunRequest& req) {
  const fs::path& dir = req.resume;
  if (!req.file.empty() || !req.sets.empty() || !req.out.empty() || req.force)
    throw InputError(dir.string() +
                     ": --resume continues the run in this folder as it was set up; a scenario "
                     "file, --set, --out or --force cannot be honoured with it (start a new run "
                     "for those)");
  const fs::path checkpoint = dir / "checkpoint.bin";
  if (!fs::exists(checkpoint))
    throw InputError(dir.string() +
                     ": no checkpoint.bin to resume from (set "
                     "output.checkpoint_interval to write checkpoints)");
  if (!fs::is_regular_file(checkpoint))
    throw InputError(checkpoint.string() + ": not a file; it must be the checkpoint a run wrote");
  std::ifstream summary(dir / "summary.json");
  if (summary) {
    const auto j = nlohmann::json::parse(summary, nullptr, false);
    if (!j.is_discarded() && j.value("status", std::string()) == "completed")
      throw InputError(dir.string() +
                       ": this run completed; there is nothing to resume (its summary.json is "
                       "the run's)");
  }
}

// "20000", or "3.116e+155" when too large to read as a whole number.
std::string step_count(double steps) {
  return steps < 1e12 ? fmt::format("{:.0f}", std::ceil(steps)) : fmt::format("{:.4g}", steps);
}

io::ScenarioFile load(const RunRequest& req, fs::path& out) {
  if (!req.resume.empty()) {
    out = req.resume;
    check_resumable(req);
    return io::load_scenario_file((out / "scenario.toml").string(), {});
  }
  if (req.file.empty()) throw InputError("talus run: a scenario file is required");
  auto file = io::load_scenario_file(req.file, req.sets);
  const std::string name = file.table["name"].value_or(std::string());
  if (file.table.contains("name")) check_run_name(name, where_name(file));
  out = !req.out.empty() ? req.out : fs::path("runs") / (name.empty() ? "run" : name);
  return file;
}

}  // namespace

RunResult execute(const RunRequest& req) {
  const auto t0 = std::chrono::steady_clock::now();
  const bool resume = !req.resume.empty();
  fs::path out;
  const auto file = load(req, out);
  if (file.method == "compare")
    throw InputError(file.path + ": a comparison file; run it with `talus compare " + file.path +
                     "`");
  const Method& method = method_for(file);
  if (resume && !method.checkpoints)
    throw InputError(out.string() + ": " + method.name + " runs write no checkpoints to resume");
  RunContext ctx{out, req.threads, resume};
  // Held until the run is over: the lock, then the record of talus's files.
  std::optional<OutputFolder> folder;
  if (resume)
    folder.emplace(OutputFolder::reopen(out));
  else
    ctx.prepare = [&] { folder.emplace(OutputFolder::claim(out, req.force)); };
  std::unique_ptr<Simulation> sim;
  try {
    sim = method.create(file, ctx);
    check_step_count(file.path, sim->estimated_steps(), sim->end_time() - sim->time(),
                     req.allow_long_run);
  } catch (const InputError&) {
    // Refused while building: a fresh run's folder goes again.
    if (!resume && folder) folder->discard();
    throw;
  }
  if (!resume && folder) folder->scenario_written();
  auto experiments = attach_experiments(*sim, ctx);
  std::vector<Observer*> observers;
  for (auto& e : experiments) observers.push_back(e.get());
  RunLoop loop(*sim, observers);
  RunLog log(out, req.log_seconds, req.log_to_stderr);
  const double steps = sim->estimated_steps();
  log.started(fmt::format("talus {} {} {} ({}, {} thread{}{})", version(),
                          resume ? "resumed" : "started", file.path, method.name, req.threads,
                          req.threads == 1 ? "" : "s",
                          steps >= 0.0 ? ", about " + step_count(steps) + " steps" : ""));
  loop.progress_seconds = std::min(loop.progress_seconds, req.log_seconds);
  SummaryInput summary;
  std::chrono::steady_clock::time_point loop_t0;  // set as the loop starts
  loop.progress = [&](const Progress& p) {
    if (summary.estimated_wall_seconds < 0.0 && p.steps_per_s > 0.0 && p.time_step > 0.0) {
      const double left = (p.end - p.time) / p.time_step / p.steps_per_s;
      summary.estimated_wall_seconds = seconds_since(loop_t0) + left;
      log.note(fmt::format("estimated wall time: about {:.0f} s ({:.0f} s left at {:.0f} steps/s)",
                           summary.estimated_wall_seconds, left, p.steps_per_s));
    }
    log.progress(p);
    if (req.progress) req.progress(p);
  };
  summary.setup_seconds = seconds_since(t0);
  if (steps >= 0.0) summary.estimated_steps = steps;
  const std::int64_t first_step = sim->steps();
  RunResult result;
  result.out = out;
  auto fill = [&](const char* status, const std::string& error) {
    summary.status = status;
    summary.error = error;
    summary.report = sim->report();
    summary.steps = sim->steps() - first_step;
    summary.simulated_time = sim->time();
    summary.loop_seconds = loop.stats().wall_seconds;
  };
  try {
    loop_t0 = std::chrono::steady_clock::now();
    loop.start(!resume);
    loop.run();
    for (auto& e : experiments) summary.experiments[e->name()] = e->finish();
    fill("completed", "");
    write_summary(out, summary);
  } catch (const std::exception& e) {
    // Whatever stopped it (a RunError, a full disk): a summary that says so.
    fill("failed", e.what());
    try {
      write_summary(out, summary);
    } catch (const std::exception&) {
      // On a full disk it may not fit either: the failure's own message is what counts.
    }
    log.ended(fmt::format("failed at t = {:.6g} s: {}", sim->time(), e.what()));
    throw;
  }
  log.ended(fmt::format("completed: {} steps to t = {:.6g} s in {:.1f} s of wall time",
                        summary.steps, summary.simulated_time, summary.loop_seconds));
  result.stats = loop.stats();
  if (!summary.report.headline.empty()) result.headline.push_back(summary.report.headline);
  for (auto& e : experiments) {
    const auto line = e->headline(summary.experiments[e->name()]);
    if (!line.empty()) result.headline.push_back(line);
  }
  for (const auto& text : result.headline) log.headline(text);
  result.warnings = summary.report.warnings;
  for (const auto& text : result.warnings) log.headline("warning: " + text);
  return result;
}

std::string validate(const std::string& path, const std::vector<std::string>& sets,
                     bool allow_long_run) {
  const auto file = io::load_scenario_file(path, sets);
  if (file.table.contains("name"))
    check_run_name(file.table["name"].value_or(std::string()), where_name(file));
  if (file.method == "compare") {
    const auto c = io::read_compare_file(path);
    for (const auto& [name, method_file] : c.methods) validate(method_file, {}, allow_long_run);
    return fmt::format("valid comparison of {} methods", c.methods.size());
  }
  const Validation v = method_for(file).validate(file);
  check_step_count(file.path, v.steps, v.duration, allow_long_run);
  return "valid (" + v.description +
         (v.steps >= 0.0 ? ", about " + step_count(v.steps) + " steps" : std::string()) + ")";
}

}  // namespace talus::run
