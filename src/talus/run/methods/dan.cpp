// DAN (1D depth-averaged runout along a path) on the run loop.
#include <fmt/core.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>

#include "talus/core/error.hpp"
#include "talus/run/loop.hpp"
#include "talus/run/methods/methods.hpp"
#include "talus/run/methods/runout.hpp"
#include "talus/runout/checkpoint.hpp"
#include "talus/scenario/scenario_runout.hpp"

namespace talus::run {

namespace {

// The front is sampled at the series times, whether or not files are written.
class DanSeries final : public Observer {
 public:
  DanSeries(runout::RunoutTracker& tracker, const runout::DanModel& model,
            runout::DanOutputs* files, std::function<void()> save = {})
      : tracker_(tracker), model_(model), files_(files), save_(std::move(save)) {}
  void on_series() override {
    tracker_.sample_front(model_);
    if (files_) files_->on_series(model_);
  }
  void on_snapshot() override {
    if (files_) files_->on_snapshot(model_);
  }
  void on_progress() override {
    if (files_) files_->flush();
  }
  void on_checkpoint() override {
    if (files_) files_->flush();
    if (save_) save_();
  }

 private:
  runout::RunoutTracker& tracker_;
  const runout::DanModel& model_;
  runout::DanOutputs* files_;
  std::function<void()> save_;  // writes checkpoint.bin
};

}  // namespace

DanSimulation::DanSimulation(runout::RunoutScenario scenario)
    : scenario_(std::move(scenario)),
      setup_(runout::build_dan(scenario_)),
      tracker_(setup_.barrier_start_s, scenario_.tail_fraction),
      outputs_(std::make_unique<DanSeries>(tracker_, setup_.model, nullptr)) {}

void DanSimulation::write_to(const std::filesystem::path& out, bool resume) {
  checkpoint_ = out / "checkpoint.bin";
  if (resume) {
    const auto count = runout::load_checkpoint(setup_.model, tracker_, checkpoint_);
    steps_ = count.steps, last_dt_ = count.last_time_step;
  }
  files_ = std::make_unique<runout::DanOutputs>(out, resume, time());
  outputs_ = std::make_unique<DanSeries>(tracker_, setup_.model, files_.get(), [this] {
    runout::save_checkpoint(setup_.model, tracker_, {steps_, last_dt_}, checkpoint_);
  });
}

Schedules DanSimulation::schedules() const {
  Schedules s;
  s.series = OutputSchedule(std::max(scenario_.control.series_interval, 1e-12));
  s.snapshots = OutputSchedule(scenario_.control.snapshot_interval);
  const double every = scenario_.control.checkpoint_interval;
  s.checkpoints = OutputSchedule(every > 0.0 && !checkpoint_.empty() ? every : -1.0);
  return s;
}

// A resumed run's state was observed by the interrupted run.
void DanSimulation::start(bool fresh) {
  if (fresh) tracker_.observe_step(setup_.model);
}

void DanSimulation::advance(double target, double tolerance, std::int64_t max_steps) {
  auto& model = setup_.model;
  const auto& c = scenario_.control;
  const double end = end_time();
  for (std::int64_t taken = 0; taken < max_steps && !stopped_; ++taken) {
    const double t = model.blocks().time;
    if (t >= target - tolerance || t >= end - tolerance) break;
    double dt = c.time_step > 0 ? c.time_step : model.stable_time_step(c.courant);
    dt = std::min(dt, end - t);
    model.step(dt);
    last_dt_ = dt;
    ++steps_;
    tracker_.observe_step(model);
    stopped_ = c.stop_at_rest && model.at_rest();
  }
}

void DanSimulation::finish() {
  tracker_.finish(setup_.model);
  if (files_) files_->write_results(tracker_.results());
}

double DanSimulation::estimated_steps() const {
  const double dt = scenario_.control.time_step;
  return dt > 0 ? (end_time() - time()) / dt : std::numeric_limits<double>::quiet_NaN();
}

MethodReport DanSimulation::report() const {
  using nlohmann::json;
  const auto& model = setup_.model;
  const auto& r = tracker_.results();
  MethodReport rep;
  rep.method = "runout";
  rep.model = "dan";
  rep.dimension = 1;
  rep.scenario = io::runout_scenario_to_json(scenario_);
  rep.rate_key = "block_steps_per_s";
  rep.items = static_cast<double>(model.size());
  const auto& c = scenario_.control;
  rep.resolved = {{"boundary_blocks", model.size()},
                  {"time_step_s", c.time_step > 0 ? json(c.time_step) : json("auto")},
                  {"path_s_begin_m", model.path().s_begin()},
                  {"path_s_end_m", model.path().s_end()}};
  rep.metrics = {{"mass_kg", model.total_mass()},
                 {"volume_m3", model.deformed_volume()},
                 {"front_s_m", model.blocks().s.back()},
                 {"tail_s_m", r.tail_s},
                 {"tail_s_absolute_m", r.tail_s_absolute},
                 {"barrier_arrival_time_s", r.barrier_arrival_time},
                 {"rest_time_s", r.rest_time},
                 {"runup_max", runup_json(r.runup_max)},
                 {"runup_final", runup_json(r.runup_final)},
                 {"max_speed_m_s", r.max_speed},
                 {"max_depth_m", r.max_depth},
                 {"kinetic_energy_J", model.kinetic_energy()}};
  // "dan: front at s = 12.3 m, tail at s = 4.1 m; max speed 3.2 m/s, max depth
  // 0.21 m; run-up 0.8 m on the barrier; at rest at t = 6.1 s".
  rep.headline = fmt::format("dan: front at s = {:.4g} m", model.blocks().s.back());
  if (std::isfinite(r.tail_s)) rep.headline += fmt::format(", tail at s = {:.4g} m", r.tail_s);
  rep.headline +=
      fmt::format("; max speed {:.3g} m/s, max depth {:.3g} m", r.max_speed, r.max_depth);
  if (std::isfinite(r.runup_max.distance_on_barrier))
    rep.headline += fmt::format("; run-up {:.3g} m along the barrier (to y = {:.4g} m)",
                                r.runup_max.distance_on_barrier, r.runup_max.elevation);
  rep.headline += std::isfinite(r.rest_time) ? fmt::format("; at rest at t = {:.4g} s", r.rest_time)
                                             : std::string("; still moving at the end");
  if (!std::isfinite(r.rest_time) && !stopped_)
    rep.warnings.push_back(still_moving(time(), model.max_speed()));
  return rep;
}

runout::RunoutResults simulate_dan(const runout::RunoutScenario& scenario) {
  DanSimulation sim(scenario);
  RunLoop loop(sim, {});
  loop.start(true);
  loop.run();
  return sim.results();
}

namespace {

// A fixed step above the stable one at the start (block length over the
// wave speed sqrt(k g h), Courant number 1) blows up within a few steps; the
// speeds of the flow only lower that limit. Refused before the run.
void check_fixed_step(const runout::RunoutScenario& sc, const runout::DanModel& model,
                      const std::string& where) {
  const double fixed = sc.control.time_step, limit = model.stable_time_step(1.0);
  if (fixed > 0.0 && fixed > limit)
    throw InputError(fmt::format(
        "{}: {:.3g} s is above the stable step {:.3g} s of this path at the start (block length "
        "/ wave speed sqrt(k g h)); use time_step = \"auto\" or a step below {:.3g} s",
        where, fixed, limit, limit));
}

}  // namespace

Method dan_method() {
  Method m;
  m.name = "dan";
  m.accepts = [](const io::ScenarioFile& f) {
    return f.method == "runout" && f.table["run"]["model"].value_or(std::string("dan")) == "dan";
  };
  m.validate = [](const io::ScenarioFile& f) {
    const auto sc = io::parse_runout_scenario(f);
    const auto setup = runout::build_dan(sc);
    check_fixed_step(sc, setup.model, where_key(f, "run", "time_step"));
    Validation v{fmt::format("1D DAN runout, {} boundary blocks, {:.4g} m^3 released",
                             setup.model.size(), setup.model.total_mass() / sc.params.density)};
    const double dt = sc.control.time_step;
    if (dt > 0) v.steps = sc.control.duration / dt, v.duration = sc.control.duration;
    return v;
  };
  m.create = [](const io::ScenarioFile& f, const RunContext& ctx) -> std::unique_ptr<Simulation> {
    const auto sc = io::parse_runout_scenario(f);
    // Built before the folder is made: bad input leaves nothing behind.
    auto sim = std::make_unique<DanSimulation>(sc);
    check_fixed_step(sc, sim->model(), where_key(f, "run", "time_step"));
    if (!ctx.resume) {
      ctx.prepare();
      sim = std::make_unique<DanSimulation>(write_resolved_runout(sc, ctx.out));
    }
    sim->write_to(ctx.out, ctx.resume);
    return sim;
  };
  return m;
}

}  // namespace talus::run
