// The two-phase model (run.model = "two_phase") on the run loop.
#include "talus/run/methods/two_phase.hpp"

#include <fmt/core.h>

#include <algorithm>
#include <cmath>

#include "talus/run/forward.hpp"
#include "talus/run/methods/methods.hpp"
#include "talus/runout/grid/two_phase_builder.hpp"
#include "talus/scenario/scenario_runout.hpp"

namespace talus::run {

TwoPhaseSimulation::TwoPhaseSimulation(runout::RunoutScenario scenario, int threads)
    : scenario_(std::move(scenario)),
      solver_(runout::build_two_phase(scenario_)),
      path_(scenario_),
      outputs_(std::make_unique<Observer>()),
      threads_(threads),
      segments_(threads) {}

void TwoPhaseSimulation::write_to(const std::filesystem::path& out, bool resume) {
  checkpoint_ = out / "checkpoint.bin";
  if (resume) {
    runout::RunoutResults path;
    const auto count = runout::load_checkpoint(solver_, maxima_, released_, path, checkpoint_);
    path_.restore(std::move(path));
    steps_ = count.steps, last_dt_ = count.last_time_step;
  }
  files_ = std::make_unique<runout::TwoPhaseOutputs>(out, scenario_.grid, resume, time(),
                                                     scenario_.control.snapshot_interval > 0.0);
  outputs_ = std::make_unique<FilesWithCheckpoint<runout::TwoPhaseOutputs, runout::TwoPhaseSolver>>(
      *files_, solver_, [this] {
        runout::save_checkpoint(solver_, maxima_, released_, path_.results(), {steps_, last_dt_},
                                checkpoint_);
      });
}

Schedules TwoPhaseSimulation::schedules() const {
  return grid_schedules(scenario_.control, !checkpoint_.empty());
}

void TwoPhaseSimulation::start(bool fresh) {
  if (!fresh) return;
  maxima_.reset(solver_.terrain().shape().cells());
  maxima_.observe(solver_);
  released_ = {solver_.solid_volume(), solver_.fluid_volume()};
}

// In segments with the team or one thread, as fv2d: the same bits either way.
void TwoPhaseSimulation::advance(double target, double tolerance, std::int64_t max_steps) {
  const double end = end_time();
  step_in_segments(threads_, segments_, max_steps, [&] {
    const double t = solver_.state().time;
    if (stopped_ || t >= target - tolerance || t >= end - tolerance) return false;
    const double dt =
        std::min({solver_.stable_time_step(), scenario_.grid.max_time_step, end - t, target - t});
    solver_.step(dt);
    last_dt_ = dt;
    ++steps_;
    maxima_.observe(solver_);
    if (path_.active()) path_.observe_step(time(), normal_heights(), solver_.max_speed());
    // Rain keeps adding water: such a run is never at rest.
    const auto& p = solver_.params();
    const bool raining = p.rainfall > 0.0 || !p.rainfall_map.empty();
    stopped_ = scenario_.control.stop_at_rest && !raining && solver_.at_rest();
    return true;
  });
}

std::vector<double> TwoPhaseSimulation::normal_heights() const {
  std::vector<double> h(solver_.state().hs.size());
  for (std::size_t c = 0; c < h.size(); ++c)
    h[c] = solver_.normal_height(c, runout::Phase::Solid) +
           solver_.normal_height(c, runout::Phase::Fluid);
  return h;
}

void TwoPhaseSimulation::after_series() {
  if (path_.active()) path_.sample_front(time(), normal_heights());
}

void TwoPhaseSimulation::finish() {
  if (files_) files_->write_results(solver_, maxima_);
  if (path_.active())
    path_.finish(checkpoint_.empty() ? std::filesystem::path() : checkpoint_.parent_path(), time(),
                 normal_heights(), solver_.at_rest());
}

double TwoPhaseSimulation::estimated_steps() const {
  const double dt = std::min(solver_.stable_time_step(), scenario_.grid.max_time_step);
  return (end_time() - time()) / dt;
}

MethodReport TwoPhaseSimulation::report() const {
  using nlohmann::json;
  const auto& g = scenario_.grid.shape;
  const auto& m = maxima_;
  double deposit_area = 0.0, affected_area = 0.0, peak_pressure = 0.0, peak_solid_speed = 0.0,
         peak_fluid_speed = 0.0;
  for (std::size_t c = 0; c < g.cells(); ++c) {
    const double deposit = solver_.normal_height(c, runout::Phase::Solid) +
                           solver_.normal_height(c, runout::Phase::Fluid);
    if (deposit > runout::TwoPhaseMaxima::kArrivalHeight) deposit_area += g.cell_area();
    if (m.height[c] > runout::TwoPhaseMaxima::kArrivalHeight) affected_area += g.cell_area();
    peak_pressure = std::max(peak_pressure, m.pressure[c]);
    peak_solid_speed = std::max(peak_solid_speed, m.solid_speed[c]);
    peak_fluid_speed = std::max(peak_fluid_speed, m.fluid_speed[c]);
  }
  const auto t = solver_.totals();
  const double vs = solver_.solid_volume(), vf = solver_.fluid_volume();
  const double vs0 = released_.solid, vf0 = released_.fluid;
  // Each phase's balance: what is left, what left and (fluid) what rain
  // brought and the ground took, against what was released.
  const double solid_in = vs0, fluid_in = vf0 + t.rained;
  const double solid_error =
      solid_in > 0 ? std::abs(vs + t.solid_outflow - solid_in) / solid_in : 0;
  const double fluid_error =
      fluid_in > 0 ? std::abs(vf + t.fluid_outflow + t.infiltrated - fluid_in) / fluid_in : 0;
  MethodReport r;
  r.method = "runout";
  r.model = "two_phase";
  r.dimension = 2;
  r.scenario = io::runout_scenario_to_json(scenario_);
  r.rate_key = "cell_updates_per_s";
  r.items = static_cast<double>(g.cells());
  r.resolved = grid_resolved(scenario_.grid, threads_);
  r.metrics = {{"released_solid_volume_m3", vs0},
               {"released_fluid_volume_m3", vf0},
               {"solid_volume_m3", vs},
               {"fluid_volume_m3", vf},
               {"solid_outflow_volume_m3", t.solid_outflow},
               {"fluid_outflow_volume_m3", t.fluid_outflow},
               {"rained_volume_m3", t.rained},
               {"infiltrated_volume_m3", t.infiltrated},
               {"solid_volume_error_relative", solid_error},
               {"fluid_volume_error_relative", fluid_error},
               {"max_height_m", m.peak_height},
               {"max_solid_speed_m_s", peak_solid_speed},
               {"max_fluid_speed_m_s", peak_fluid_speed},
               {"max_pressure_Pa", peak_pressure},
               {"affected_area_m2", affected_area},
               {"deposit_area_m2", deposit_area},
               {"at_rest", solver_.at_rest()},
               {"kinetic_energy_J", solver_.kinetic_energy()}};
  path_.add_metrics(r.metrics);
  const double v0 = vs0 + vf0;
  r.headline = fmt::format(
      "two_phase: {:.4g} m^3 released ({:.0f} % solid), {:.4g} m^2 affected, {:.4g} m^2 deposit "
      "(> 1 cm); max height {:.3g} m, max speed {:.3g} m/s solid, {:.3g} m/s fluid, max pressure "
      "{:.3g} kPa; {}",
      v0, v0 > 0 ? 100 * vs0 / v0 : 0.0, affected_area, deposit_area, m.peak_height,
      peak_solid_speed, peak_fluid_speed, peak_pressure / 1e3,
      solver_.at_rest() ? "at rest" : "still moving at the end");
  if (t.solid_outflow + t.fluid_outflow > 0.0)
    r.headline += fmt::format("; {:.4g} m^3 solid and {:.4g} m^3 fluid left the grid",
                              t.solid_outflow, t.fluid_outflow);
  if (!solver_.at_rest()) r.warnings.push_back(still_moving(time(), solver_.max_speed()));
  return r;
}

Method two_phase_method() {
  Method m;
  m.name = "two_phase";
  m.accepts = [](const io::ScenarioFile& f) {
    return f.method == "runout" && f.table["run"]["model"].value_or(std::string()) == "two_phase";
  };
  m.validate = [](const io::ScenarioFile& f) {
    const auto sc = io::parse_runout_scenario(f);
    const auto solver = runout::build_two_phase(sc);
    const double dt = std::min(solver.stable_time_step(), sc.grid.max_time_step);
    std::string what = fmt::format(
        "2D two-phase runout on a {} x {} grid of {} m cells, {:.4g} m^3 of solid and {:.4g} m^3 "
        "of fluid released",
        sc.grid.shape.nx, sc.grid.shape.ny, sc.grid.shape.dx, solver.solid_volume(),
        solver.fluid_volume());
    if (!sc.grid.release_resampling.empty())
      what += "; release resampled: " + sc.grid.release_resampling;
    return Validation{what, sc.control.duration / dt, sc.control.duration};
  };
  m.create = [](const io::ScenarioFile& f, const RunContext& ctx) {
    return create_grid_run<TwoPhaseSimulation>(io::parse_runout_scenario(f), ctx.threads, ctx.out,
                                               ctx.resume, ctx.prepare);
  };
  return m;
}

}  // namespace talus::run
