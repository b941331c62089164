#include "talus/run/run.hpp"

#include <fmt/core.h>
#include <omp.h>

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
#include "talus/run/session.hpp"
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
  auto file = req.text.empty() ? io::load_scenario_file(req.file, req.sets)
                               : io::load_scenario_text(req.text, req.file, req.sets);
  const std::string name = file.table["name"].value_or(std::string());
  if (file.table.contains("name")) check_run_name(name, where_name(file));
  out = !req.out.empty() ? req.out : fs::path("runs") / (name.empty() ? "run" : name);
  return file;
}

}  // namespace

RunSession::RunSession(const RunRequest& req) : request_(req), resume_(!req.resume.empty()) {
  const auto t0 = std::chrono::steady_clock::now();
  // The team of every OpenMP loop that names none (sums, maps): the run's, in
  // whatever process drives it (the command line, Python), so that the same
  // scenario and thread count give the same bits.
  threads_ = std::max(1, req.threads);
  if (resume_) {
    const int recorded = OutputFolder::recorded_threads(req.resume);
    if (req.threads == 0 && recorded > 0) threads_ = recorded;
    if (req.threads > 0 && recorded > 0 && req.threads != recorded)
      warnings_.push_back(fmt::format(
          "resumed on {} thread{} where the run ran on {}: its results now differ in their last "
          "bits from an uninterrupted run's",
          req.threads, req.threads == 1 ? "" : "s", recorded));
  }
  omp_set_num_threads(threads_);
  const auto file = load(req, out_);
  if (file.method == "compare")
    throw InputError(file.path + ": a comparison file; run it with `talus compare " + file.path +
                     "`");
  const Method& method = method_for(file);
  ctx_ = RunContext{out_, threads_, resume_};
  // Under mpirun: a method that spreads over ranks gets them (rank 0 writes,
  // the others compute); the others are refused (docs/mpi.md).
  if (const auto& world = comm::Comm::world(); world.size() > 1) {
    if (!method.spreads_over_ranks)
      throw InputError(fmt::format(
          "{}: the {} method runs on one rank, and this is {} MPI ranks; only fv2d runs on "
          "several (docs/mpi.md): start it without mpirun",
          file.path, method.name, world.size()));
    ctx_.ranks = &world;
    summary_.mpi_ranks = world.size();
  }
  // Held until the session ends: the lock, then the record of talus's files.
  if (resume_ && ctx_.writes())
    folder_.emplace(OutputFolder::reopen(out_, threads_));
  else
    ctx_.prepare = [this] { folder_.emplace(OutputFolder::claim(out_, request_.force, threads_)); };
  try {
    sim_ = method.create(file, ctx_);
    check_step_count(file.path, sim_->estimated_steps(), sim_->end_time() - sim_->time(),
                     req.allow_long_run);
  } catch (const InputError&) {
    // Refused while building: a fresh run's folder goes again.
    if (!resume_ && folder_) folder_->discard();
    throw;
  }
  if (!resume_ && folder_) folder_->scenario_written();
  experiments_ = attach_experiments(*sim_, ctx_);
  std::vector<Observer*> observers;
  for (auto& e : experiments_) observers.push_back(e.get());
  loop_ = std::make_unique<RunLoop>(*sim_, observers);
  // Rank 0 of an MPI job alone writes the log (and the summary).
  log_ = std::make_unique<RunLog>(ctx_.writes() ? out_ : fs::path(), req.log_seconds,
                                  req.log_to_stderr && ctx_.writes());
  const double steps = sim_->estimated_steps();
  const std::string ranks =
      ctx_.ranks ? fmt::format(" on each of {} MPI ranks", ctx_.ranks->size()) : "";
  log_->started(fmt::format("talus {} {} {} ({}, {} thread{}{}{})", version(),
                            resume_ ? "resumed" : "started", file.path, method.name, threads_,
                            threads_ == 1 ? "" : "s", ranks,
                            steps >= 0.0 ? ", about " + step_count(steps) + " steps" : ""));
  loop_->progress_seconds = std::min(loop_->progress_seconds, req.log_seconds);
  loop_->progress = [this](const Progress& p) {
    if (summary_.estimated_wall_seconds < 0.0 && p.steps_per_s > 0.0 && p.time_step > 0.0) {
      const double left = (p.end - p.time) / p.time_step / p.steps_per_s;
      summary_.estimated_wall_seconds = seconds_since(loop_t0_) + left;
      log_->note(
          fmt::format("estimated wall time: about {:.0f} s ({:.0f} s left at {:.0f} steps/s)",
                      summary_.estimated_wall_seconds, left, p.steps_per_s));
    }
    log_->progress(p);
    if (request_.progress && ctx_.writes()) request_.progress(p);
  };
  summary_.setup_seconds = seconds_since(t0);
  if (steps >= 0.0) summary_.estimated_steps = steps;
  first_step_ = sim_->steps();
}

RunSession::~RunSession() {
  if (finished_ || !sim_) return;
  try {
    finish();
  } catch (const std::exception&) {
    // Nothing to report to: the caller has gone.
  }
}

void RunSession::fill(const char* status, const std::string& error) {
  summary_.status = status;
  summary_.error = error;
  summary_.report = sim_->report();
  summary_.report.warnings.insert(summary_.report.warnings.begin(), warnings_.begin(),
                                  warnings_.end());
  summary_.steps = sim_->steps() - first_step_;
  summary_.simulated_time = sim_->time();
  summary_.loop_seconds = loop_->stats().wall_seconds;
}

void RunSession::fail(const std::exception& e) {
  // Whatever stopped it (a RunError, a full disk): a summary that says so.
  finished_ = true;
  fill("failed", e.what());
  try {
    if (folder_) folder_->free_reserve();
    if (ctx_.writes()) write_summary(out_, summary_);
  } catch (const std::exception&) {
    // On a full disk it may not fit either: the failure's own message is what counts.
  }
  log_->ended(fmt::format("failed at t = {:.6g} s: {}", sim_->time(), e.what()));
  folder_.reset();  // the lock: another run (a resume) may use the folder now
}

RunStats RunSession::advance(double until, std::int64_t steps) {
  if (finished_) throw InputError(out_.string() + ": this run is finished; it cannot be advanced");
  const Claim claim(*this);
  try {
    begin();
    return loop_->advance(std::min(until, sim_->end_time()), steps);
  } catch (const std::exception& e) {
    fail(e);
    throw;
  }
}

RunSession::Claim::Claim(RunSession& s) : s_(s) {
  const auto me = std::this_thread::get_id();
  if (s_.owner_.load() == me) {
    ++s_.depth_;
    return;
  }
  std::thread::id none;
  if (!s_.owner_.compare_exchange_strong(none, me))
    throw InputError(s_.out_.string() +
                     ": the run is stepping in another thread; wait for that call to return");
  s_.depth_ = 1;
}

RunSession::Claim::~Claim() {
  if (--s_.depth_ == 0) s_.owner_.store(std::thread::id());
}

void RunSession::begin() {
  if (started_) return;
  started_ = true;
  loop_t0_ = std::chrono::steady_clock::now();
  loop_->start(!resume_);
}

RunStats RunSession::run_to_end() { return advance(sim_->end_time(), -1); }

void RunSession::checkpoint() {
  if (finished_) throw InputError(out_.string() + ": this run is finished");
  const Claim claim(*this);
  try {
    begin();
    if (loop_->done())
      throw InputError(out_.string() + ": the run is complete; a checkpoint would resume nothing");
    loop_->checkpoint();
  } catch (const InputError&) {
    throw;
  } catch (const std::exception& e) {
    fail(e);
    throw;
  }
  log_->note(fmt::format("t = {:.6g} s: checkpoint written (asked by the caller)", sim_->time()));
}

nlohmann::json RunSession::resolved() {
  const Claim claim(*this);
  if (!finished_) {
    try {
      begin();
    } catch (const std::exception& e) {
      fail(e);
      throw;
    }
  }
  return sim_->report().resolved;
}

WallControl& RunSession::walls_of_method() const {
  WallControl* w = sim_->wall_control();
  if (!w) throw InputError(out_.string() + ": this method has no walls to read or drive");
  return *w;
}

std::size_t RunSession::wall_index(const std::string& name) const {
  const auto walls = walls_of_method().walls();
  std::string names;
  for (std::size_t k = 0; k < walls.size(); ++k) {
    if (walls[k].name == name) return k;
    names += (k ? ", '" : "'") + walls[k].name + "'";
  }
  throw InputError(fmt::format("no wall '{}' (the run's walls: {})", name, names));
}

std::vector<WallReading> RunSession::walls() const {
  return sim_->wall_control() ? sim_->wall_control()->walls() : std::vector<WallReading>{};
}

void RunSession::set_wall_velocity(const std::string& name, const Vec3& v) {
  if (finished_) throw InputError(out_.string() + ": this run is finished");
  const Claim claim(*this);
  walls_of_method().set_velocity(wall_index(name), v);
  log_->note(
      fmt::format("t = {:.6g} s: wall '{}' translates at ({:.6g}, {:.6g}, {:.6g}) m/s "
                  "(set by the caller)",
                  sim_->time(), name, v.x(), v.y(), v.z()));
}

void RunSession::set_wall_servo(const std::string& name, double pressure, double speed,
                                double area) {
  if (finished_) throw InputError(out_.string() + ": this run is finished");
  const Claim claim(*this);
  const std::size_t k = wall_index(name);
  const auto before = walls_of_method().walls()[k];
  walls_of_method().set_servo(k, pressure, speed, area);
  // A servo turned on, off or to another pressure or speed; not an area that
  // follows the sample (which a script may change every few steps).
  if (before.servo_pressure == pressure && (pressure == 0.0 || before.servo_speed == speed)) return;
  log_->note(pressure == 0.0 ? fmt::format("t = {:.6g} s: wall '{}': servo off (set by the caller)",
                                           sim_->time(), name)
                             : fmt::format("t = {:.6g} s: wall '{}': servo holds {:.6g} Pa over "
                                           "{:.6g} m^2 at up to {:.6g} m/s (set by the caller)",
                                           sim_->time(), name, pressure, area, speed));
}

RunResult RunSession::finish() {
  if (finished_) throw InputError(out_.string() + ": this run is already finished");
  const Claim claim(*this);
  bool done = false;
  try {
    // A run finished before its first step starts all the same: the methods
    // set up their report there, and its outputs then hold the start state.
    begin();
    done = loop_->done();
    if (done)
      for (auto& e : experiments_) summary_.experiments[e->name()] = e->finish();
    else
      loop_->flush();  // a completed run's files are complete already
    fill(done ? "completed" : "stopped", "");
    if (ctx_.writes()) write_summary(out_, summary_);
  } catch (const std::exception& e) {
    fail(e);
    throw;
  }
  finished_ = true;
  folder_.reset();  // the lock: another run (a resume) may use the folder now
  if (done)
    log_->ended(fmt::format("completed: {} steps to t = {:.6g} s in {:.1f} s of wall time",
                            summary_.steps, summary_.simulated_time, summary_.loop_seconds));
  else
    log_->ended(fmt::format("stopped by the caller at t = {:.6g} s after {} steps",
                            summary_.simulated_time, summary_.steps));
  RunResult result;
  result.out = out_;
  result.stats = loop_->stats();
  if (!summary_.report.headline.empty()) result.headline.push_back(summary_.report.headline);
  if (done)
    for (auto& e : experiments_) {
      const auto line = e->headline(summary_.experiments[e->name()]);
      if (!line.empty()) result.headline.push_back(line);
    }
  for (const auto& text : result.headline) log_->headline(text);
  result.warnings = summary_.report.warnings;
  for (const auto& text : result.warnings) log_->headline("warning: " + text);
  return result;
}

RunResult execute(const RunRequest& req) {
  RunSession session(req);
  session.run_to_end();
  return session.finish();
}

namespace {

std::string validate_file(const io::ScenarioFile& file, bool allow_long_run) {
  const std::string& path = file.path;
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

}  // namespace

std::string validate(const std::string& path, const std::vector<std::string>& sets,
                     bool allow_long_run) {
  return validate_file(io::load_scenario_file(path, sets), allow_long_run);
}

std::string validate_text(const std::string& text, const std::string& path,
                          const std::vector<std::string>& sets, bool allow_long_run) {
  return validate_file(io::load_scenario_text(text, path, sets), allow_long_run);
}

}  // namespace talus::run
