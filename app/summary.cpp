#include "summary.hpp"

#include <fstream>
#include <nlohmann/json.hpp>

#include "talus/core/version.hpp"
#include "talus/io/scenario.hpp"
#include "talus/io/scenario_mpm.hpp"
#include "talus/io/scenario_runout.hpp"

namespace talus::app {

namespace {

// Written next to the final name and renamed, so a reader never sees half a file.
void write_summary_file(nlohmann::json& j, const RunSummary& summary, const std::string& error) {
  if (!error.empty()) j["error"] = error;
  const auto tmp = summary.output / "summary.json.tmp";
  std::ofstream(tmp) << j.dump(2) << "\n";
  std::filesystem::rename(tmp, summary.output / "summary.json");
}

// What every summary starts with; `model` only where a method has several (runout).
nlohmann::json header(const std::string& status, const char* method, const char* model,
                      int dimension, nlohmann::json scenario) {
  nlohmann::json j = {{"talus_version", talus::version()},
                      {"status", status},
                      {"method", method},
                      {"dimension", dimension},
                      {"scenario", std::move(scenario)}};
  if (model) j["model"] = model;
  return j;
}

// Steps, times and the throughput: `items` (particles, blocks, points, cells)
// advanced per second of the time loop.
nlohmann::json run_block(const RunSummary& summary, double simulated_time, const char* rate_key,
                         double items) {
  return nlohmann::json{
      {"steps", summary.steps},
      {"simulated_time_s", simulated_time},
      {"loop_wall_s", summary.loop_seconds},
      {"setup_wall_s", summary.setup_seconds},
      {rate_key, summary.loop_seconds > 0 ? items * summary.steps / summary.loop_seconds : 0.0}};
}

}  // namespace

template <int D>
void write_dem_summary(const dem::DemScenario& sc, const dem::DemRun<D>& run,
                       const dem::DemOutputs<D>& outputs, const RunSummary& summary, int threads,
                       const std::string& status, const std::string& error) {
  using nlohmann::json;
  const auto& s = run.system;
  const auto& p = s.particles;
  json walls = json::array();
  for (std::size_t w = 0; w < s.walls.size(); ++w) {
    const auto& wall = s.walls[w];
    walls.push_back({{"name", wall.name},
                     {"force_N", {wall.force.x(), wall.force.y(), wall.force.z()}},
                     {"peak_force_N", outputs.peak_wall_force[w]},
                     {"impulse_Ns", {wall.impulse.x(), wall.impulse.y(), wall.impulse.z()}}});
  }
  json j = header(status, "dem", nullptr, D, io::scenario_to_json(sc));
  j["resolved"] = {{"time_step_s", s.dt},
                   {"critical_time_step_s", run.system.critical_time_step},
                   {"reference_impact_speed_m_s", run.system.reference_speed},
                   {"skin_m", s.skin},
                   {"settle_time_s", run.system.settle_time},
                   {"threads", threads}};
  j["run"] = run_block(summary, s.time, "particle_steps_per_s", p.size());
  j["run"]["neighbour_builds"] = s.neighbours.builds;
  j["metrics"] = {{"particles", p.size()},
                  {"particles_removed", s.removed},
                  {"kinetic_energy_J", dem::kinetic_energy(p)},
                  {"rotational_energy_J", dem::rotational_energy(p)},
                  {"peak_kinetic_energy_J", outputs.peak_kinetic_energy},
                  {"peak_kinetic_energy_time_s", outputs.peak_kinetic_energy_time},
                  {"front_x_m", dem::front_x(p)},
                  {"top_m", dem::top(p)},
                  {"contacts_per_particle", p.size() ? 2.0 * s.pair_contacts / p.size() : 0.0},
                  {"walls", walls}};
  for (const auto& [name, value] : summary.analysis.items()) j[name] = value;
  write_summary_file(j, summary, error);
}

template void write_dem_summary<2>(const dem::DemScenario&, const dem::DemRun<2>&,
                                   const dem::DemOutputs<2>&, const RunSummary&, int,
                                   const std::string&, const std::string&);
template void write_dem_summary<3>(const dem::DemScenario&, const dem::DemRun<3>&,
                                   const dem::DemOutputs<3>&, const RunSummary&, int,
                                   const std::string&, const std::string&);

// --- runout (method = "runout") ---
void write_runout_summary(const runout::RunoutScenario& sc, const runout::DanModel& model,
                          const runout::RunoutResults& r, const RunSummary& summary,
                          const std::string& status, const std::string& error) {
  using nlohmann::json;
  auto runup = [](const runout::RunUp& u) {
    return json{{"elevation_m", u.elevation},
                {"s_m", u.s},
                {"distance_on_barrier_m", u.distance_on_barrier},
                {"time_s", u.time}};
  };
  json j = header(status, "runout", "dan", 1, io::runout_scenario_to_json(sc));
  j["resolved"] = {
      {"boundary_blocks", model.size()},
      {"time_step_s", sc.control.time_step > 0 ? json(sc.control.time_step) : json("auto")},
      {"path_s_begin_m", model.path().s_begin()},
      {"path_s_end_m", model.path().s_end()}};
  j["run"] = run_block(summary, model.blocks().time, "block_steps_per_s", model.size());
  j["metrics"] = {{"mass_kg", model.total_mass()},
                  {"volume_m3", model.deformed_volume()},
                  {"front_s_m", model.blocks().s.back()},
                  {"tail_s_m", r.tail_s},
                  {"tail_s_absolute_m", r.tail_s_absolute},
                  {"barrier_arrival_time_s", r.barrier_arrival_time},
                  {"rest_time_s", r.rest_time},
                  {"runup_max", runup(r.runup_max)},
                  {"runup_final", runup(r.runup_final)},
                  {"max_speed_m_s", r.max_speed},
                  {"max_depth_m", r.max_depth},
                  {"kinetic_energy_J", model.kinetic_energy()}};
  write_summary_file(j, summary, error);
}

// --- MPM ---
template <int D>
void write_mpm_summary(const mpm::MpmScenario& sc, const mpm::Solver<D>& s,
                       const mpm::MpmOutputs<D>& outputs, const RunSummary& summary, int threads,
                       const std::string& status, const std::string& error) {
  using nlohmann::json;
  const auto& p = s.particles;
  int yielding = 0, cracked = 0;
  for (std::size_t i = 0; i < p.size(); ++i) {
    yielding += p.state[i].yielding;
    const double c0 = mpm::initial_cohesion(sc.materials[p.material[i]]);
    cracked += c0 > 0.0 && p.state[i].cohesion < c0;
  }
  const double front = mpm::front_x(p), height = mpm::top(p, s.gravity());
  json j = header(status, "mpm", nullptr, D, io::mpm_scenario_to_json(sc));
  j["resolved"] = {{"last_time_step_s", s.last_dt},
                   {"cell_size_m", s.grid.h},
                   {"gimp_half_width_over_h", s.params.gimp_half_width},
                   {"grid_nodes", s.grid.nodes()},
                   {"threads", threads}};
  j["run"] = run_block(summary, s.time, "point_steps_per_s", p.size());
  j["metrics"] = {{"points", p.size()},
                  {"kinetic_energy_J", mpm::kinetic_energy(p)},
                  {"peak_kinetic_energy_J", outputs.peak_kinetic_energy},
                  {"peak_kinetic_energy_time_s", outputs.peak_kinetic_energy_time},
                  {"front_x_m", front},
                  {"front_advance_m", front - outputs.initial_front_x},
                  {"top_m", height},
                  {"top_change_m", height - outputs.initial_top},
                  {"yielding_points", yielding},
                  {"cracked_points", cracked}};
  if (const auto* m = outputs.membrane_outputs()) {
    double final_max = 0.0;
    for (const auto& mb : s.membranes) final_max = std::max(final_max, mb.max_tension());
    j["metrics"]["membrane_peak_tension_N_m"] = m->peak_tension;
    j["metrics"]["membrane_peak_tension_time_s"] = m->peak_tension_time;
    j["metrics"]["membrane_final_max_tension_N_m"] = final_max;
  }
  for (const auto& [name, value] : summary.analysis.items()) j[name] = value;
  write_summary_file(j, summary, error);
}

template void write_mpm_summary<2>(const mpm::MpmScenario&, const mpm::Solver<2>&,
                                   const mpm::MpmOutputs<2>&, const RunSummary&, int,
                                   const std::string&, const std::string&);
template void write_mpm_summary<3>(const mpm::MpmScenario&, const mpm::Solver<3>&,
                                   const mpm::MpmOutputs<3>&, const RunSummary&, int,
                                   const std::string&, const std::string&);

// --- runout, model = "fv2d" ---
void write_fv2d_summary(const runout::RunoutScenario& sc, const runout::Fv2dSolver& solver,
                        const runout::Fv2dMaxima& m, double initial_volume,
                        const RunSummary& summary, int threads, const std::string& status,
                        const std::string& error) {
  using nlohmann::json;
  const auto& g = sc.grid.shape;
  double deposit_area = 0.0, affected_area = 0.0, peak_pressure = 0.0;
  for (std::size_t c = 0; c < g.cells(); ++c) {
    if (solver.normal_height(c) > 0.01) deposit_area += g.cell_area();
    if (m.height[c] > 0.01) affected_area += g.cell_area();
    peak_pressure = std::max(peak_pressure, m.pressure[c]);
  }
  const double volume = solver.volume();
  json j = header(status, "runout", "fv2d", 2, io::runout_scenario_to_json(sc));
  j["resolved"] = {{"cells_x", g.nx},
                   {"cells_y", g.ny},
                   {"cell_size_m", {g.dx, g.dy}},
                   {"x_west", sc.grid.x_west},
                   {"y_north", sc.grid.y_north},
                   {"threads", threads}};
  j["run"] = run_block(summary, solver.state().time, "cell_updates_per_s", g.cells());
  j["metrics"] = {
      {"released_volume_m3", initial_volume},
      {"volume_m3", volume},
      {"outflow_volume_m3", solver.outflow_volume()},
      {"volume_error_relative",
       initial_volume > 0
           ? std::abs(volume + solver.outflow_volume() - initial_volume) / initial_volume
           : 0.0},
      {"max_height_m", m.peak_height},
      {"max_speed_m_s", m.peak_speed},
      {"max_pressure_Pa", peak_pressure},
      {"affected_area_m2", affected_area},
      {"deposit_area_m2", deposit_area},
      {"at_rest", solver.at_rest()},
      {"kinetic_energy_J", solver.kinetic_energy()}};
  write_summary_file(j, summary, error);
}

}  // namespace talus::app
