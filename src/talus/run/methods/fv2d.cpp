// fv2d (2D depth-averaged runout on a terrain grid) on the run loop.
#include "talus/run/methods/fv2d.hpp"

#include <fmt/core.h>

#include <algorithm>
#include <cmath>

#include "talus/core/error.hpp"
#include "talus/run/methods/methods.hpp"
#include "talus/runout/grid/fv2d_builder.hpp"
#include "talus/scenario/scenario_runout.hpp"

namespace talus::run {

Fv2dSimulation::Fv2dSimulation(runout::RunoutScenario scenario, int threads)
    : GridSimulation(std::move(scenario), threads, &runout::build_fv2d) {}

void Fv2dSimulation::distribute(const comm::Comm& ranks) {
  if (path_.active())
    throw InputError(
        "fv2d on several MPI ranks: a grid on a flume path ([path]) runs on one rank only");
  solver_.distribute(ranks);
}

void Fv2dSimulation::start(bool fresh) {
  if (!fresh) return;
  maxima_.reset(solver_.terrain().shape().cells());
  maxima_.observe(solver_);
  maxima_.gather(solver_);
  released_ = solver_.volume();
}

void Fv2dSimulation::advance(double target, double tolerance, std::int64_t max_steps) {
  step_to(target, tolerance, max_steps, [&] {
    if (scenario_.control.stop_at_rest && solver_.at_rest()) return true;
    const double f = scenario_.control.stop_momentum_fraction;
    if (f <= 0.0) return false;
    const double momentum = solver_.momentum_sum();
    maxima_.peak_momentum = std::max(maxima_.peak_momentum, momentum);
    return momentum_stop_ = momentum < f * maxima_.peak_momentum;
  });
  // Every call ends where the run loop writes (series, maps, checkpoint) or
  // stops: the state and maxima whole on every rank from here on.
  solver_.gather();
  maxima_.gather(solver_);
}

std::vector<double> Fv2dSimulation::normal_heights() const {
  std::vector<double> h(solver_.state().h.size());
  for (std::size_t c = 0; c < h.size(); ++c) h[c] = solver_.normal_height(c);
  return h;
}

MethodReport Fv2dSimulation::report() const {
  using nlohmann::json;
  const auto& g = scenario_.grid.shape;
  const auto& m = maxima_;
  double deposit_area = 0.0, affected_area = 0.0, peak_pressure = 0.0;
  for (std::size_t c = 0; c < g.cells(); ++c) {
    if (solver_.normal_height(c) > 0.01) deposit_area += g.cell_area();
    if (m.height[c] > 0.01) affected_area += g.cell_area();
    peak_pressure = std::max(peak_pressure, m.pressure[c]);
  }
  const double volume = solver_.volume(), v0 = released_;
  MethodReport r;
  r.method = "runout";
  r.model = "fv2d";
  r.dimension = 2;
  r.scenario = io::runout_scenario_to_json(scenario_);
  r.rate_key = "cell_updates_per_s";
  r.items = static_cast<double>(g.cells());
  r.resolved = grid_resolved(scenario_.grid, threads_);
  r.metrics = {{"released_volume_m3", v0},
               {"volume_m3", volume},
               {"outflow_volume_m3", solver_.outflow_volume()},
               {"volume_error_relative",
                v0 > 0 ? std::abs(volume + solver_.outflow_volume() - v0) / v0 : 0.0},
               {"max_height_m", m.peak_height},
               {"max_speed_m_s", m.peak_speed},
               {"max_pressure_Pa", peak_pressure},
               {"affected_area_m2", affected_area},
               {"deposit_area_m2", deposit_area},
               {"at_rest", solver_.at_rest()},
               {"stopped_by_momentum", momentum_stop_},
               {"kinetic_energy_J", solver_.kinetic_energy()}};
  // The stop rule's reference, tracked only when the rule is on.
  if (scenario_.control.stop_momentum_fraction > 0.0)
    r.metrics["peak_momentum_kg_m_s"] = maxima_.peak_momentum;
  path_.add_metrics(r.metrics);
  // "fv2d: 1200 m^3 released, 35000 m^2 affected, 21000 m^2 deposit; max height
  // 3.1 m, max speed 12 m/s, max pressure 140 kPa; at rest".
  const std::string end =
      solver_.at_rest() ? "at rest"
      : momentum_stop_  ? fmt::format("stopped at t = {:.4g} s: momentum below {:g} % of its peak",
                                      time(), 100 * scenario_.control.stop_momentum_fraction)
                        : "still moving at the end";
  r.headline = fmt::format(
      "fv2d: {:.4g} m^3 released, {:.4g} m^2 affected, {:.4g} m^2 deposit (> 1 cm); max height "
      "{:.3g} m, max speed {:.3g} m/s, max pressure {:.3g} kPa; {}",
      v0, affected_area, deposit_area, m.peak_height, m.peak_speed, peak_pressure / 1e3, end);
  if (solver_.outflow_volume() > 0.0)
    r.headline += fmt::format("; {:.4g} m^3 left the grid", solver_.outflow_volume());
  // Stopping by the momentum rule is the user's choice, not a warning.
  if (!solver_.at_rest() && !momentum_stop_)
    r.warnings.push_back(still_moving(time(), solver_.max_speed()));
  return r;
}

Method fv2d_method() {
  Method m;
  m.name = "fv2d";
  m.accepts = [](const io::ScenarioFile& f) {
    return f.method == "runout" && f.table["run"]["model"].value_or(std::string()) == "fv2d";
  };
  m.validate = [](const io::ScenarioFile& f) {
    const auto sc = io::parse_runout_scenario(f);
    const auto solver = runout::build_fv2d(sc);
    const double dt = std::min(solver.stable_time_step(), sc.grid.max_time_step);
    std::string what =
        fmt::format("2D runout on a {} x {} grid of {} m cells, {:.4g} m^3 released",
                    sc.grid.shape.nx, sc.grid.shape.ny, sc.grid.shape.dx, solver.volume());
    if (!sc.grid.release_resampling.empty())
      what += "; release resampled: " + sc.grid.release_resampling;
    return Validation{what, sc.control.duration / dt, sc.control.duration};
  };
  m.create = [](const io::ScenarioFile& f, const RunContext& ctx) {
    return create_grid_run<Fv2dSimulation>(io::parse_runout_scenario(f), ctx);
  };
  m.spreads_over_ranks = true;
  return m;
}

}  // namespace talus::run
