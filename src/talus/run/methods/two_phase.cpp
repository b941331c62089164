// The two-phase model (run.model = "two_phase") on the run loop.
#include "talus/run/methods/two_phase.hpp"

#include <fmt/core.h>

#include <algorithm>
#include <cmath>

#include "talus/run/methods/methods.hpp"
#include "talus/runout/grid/two_phase_builder.hpp"
#include "talus/scenario/scenario_runout.hpp"

namespace talus::run {

TwoPhaseSimulation::TwoPhaseSimulation(runout::RunoutScenario scenario, int threads)
    : GridSimulation(std::move(scenario), threads, &runout::build_two_phase) {}

void TwoPhaseSimulation::start(bool fresh) {
  if (!fresh) return;
  maxima_.reset(solver_.terrain().shape().cells());
  maxima_.observe(solver_);
  released_ = {solver_.solid_volume(), solver_.fluid_volume()};
}

void TwoPhaseSimulation::advance(double target, double tolerance, std::int64_t max_steps) {
  step_to(target, tolerance, max_steps, [&] {
    // Rain keeps adding water: such a run is never at rest.
    const auto& p = solver_.params();
    const bool raining = p.rainfall > 0.0 || !p.rainfall_map.empty();
    return scenario_.control.stop_at_rest && !raining && solver_.at_rest();
  });
}

std::vector<double> TwoPhaseSimulation::normal_heights() const {
  std::vector<double> h(solver_.state().hs.size());
  for (std::size_t c = 0; c < h.size(); ++c)
    h[c] = solver_.normal_height(c, runout::Phase::Solid) +
           solver_.normal_height(c, runout::Phase::Fluid);
  return h;
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
    return create_grid_run<TwoPhaseSimulation>(io::parse_runout_scenario(f), ctx);
  };
  return m;
}

}  // namespace talus::run
