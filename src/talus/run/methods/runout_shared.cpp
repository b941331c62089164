// What DAN and fv2d share on the run loop: the resolved scenario a run starts
// from, and the warning of a run that ends with its mass still moving.
#include <fmt/format.h>

#include <algorithm>

#include "talus/io/archive.hpp"
#include "talus/run/methods/runout.hpp"
#include "talus/runout/output_observer.hpp"
#include "talus/scenario/scenario_runout.hpp"

namespace talus::run {

std::string still_moving(double time, double max_speed) {
  return fmt::format(
      "the mass is still moving at the end (t = {:.4g} s, up to {:.3g} m/s): the deposit and "
      "run-out are not final; lengthen run.duration",
      time, max_speed);
}

runout::RunoutScenario write_resolved_runout(const runout::RunoutScenario& scenario,
                                             const std::filesystem::path& out, bool write) {
  const auto path = out / "scenario.toml";
  const std::string text = io::runout_scenario_to_toml(scenario);
  if (write) io::write_file_atomically(path, text);
  return io::parse_runout_scenario(io::load_scenario_text(text, path.string()));
}

nlohmann::json runup_json(const runout::RunUp& u) {
  return {{"elevation_m", u.elevation},
          {"s_m", u.s},
          {"distance_on_barrier_m", u.distance_on_barrier},
          {"time_s", u.time}};
}

GridPathResults::GridPathResults(const runout::RunoutScenario& sc) {
  if (sc.grid.on_path) tracker_.emplace(sc);
}

void GridPathResults::observe_step(double time, const std::vector<double>& depth,
                                   double max_speed) {
  if (tracker_) tracker_->observe_step(time, depth, max_speed);
}

void GridPathResults::sample_front(double time, const std::vector<double>& depth) {
  if (tracker_) tracker_->sample_front(time, depth);
}

void GridPathResults::finish(const std::filesystem::path& out, double time,
                             const std::vector<double>& depth, bool at_rest) {
  if (!tracker_) return;
  tracker_->finish(time, depth, at_rest);
  if (out.empty()) return;
  runout::write_path_csv(out, tracker_->path());
  runout::write_path_results(out, tracker_->results());
}

runout::RunoutResults GridPathResults::results() const {
  return tracker_ ? tracker_->results() : runout::RunoutResults{};
}

void GridPathResults::restore(runout::RunoutResults results) {
  if (tracker_) tracker_->restore(std::move(results));
}

void GridPathResults::add_metrics(nlohmann::json& m) const {
  if (!tracker_) return;
  const auto& r = tracker_->results();
  m["front_s_m"] = tracker_->final_front_s();
  m["tail_s_m"] = r.tail_s;
  m["tail_s_absolute_m"] = r.tail_s_absolute;
  m["barrier_arrival_time_s"] = r.barrier_arrival_time;
  m["rest_time_s"] = r.rest_time;
  m["runup_max"] = runup_json(r.runup_max);
  m["runup_final"] = runup_json(r.runup_final);
}

Schedules grid_schedules(const runout::RunoutControl& c, bool files) {
  Schedules s;
  s.series = OutputSchedule(std::max(c.series_interval, 1e-12));
  s.checkpoints =
      OutputSchedule(c.checkpoint_interval > 0.0 && files ? c.checkpoint_interval : -1.0);
  // Snapshot maps only when asked for (interval > 0): they are large.
  s.snapshots = OutputSchedule(c.snapshot_interval > 0.0 && files ? c.snapshot_interval : -1.0);
  return s;
}

nlohmann::json grid_resolved(const runout::GridSpec& grid, int threads) {
  const auto& g = grid.shape;
  nlohmann::json r = {
      {"cells_x", g.nx},       {"cells_y", g.ny},         {"cell_size_m", {g.dx, g.dy}},
      {"x_west", grid.x_west}, {"y_north", grid.y_north}, {"threads", threads}};
  if (!grid.release_resampling.empty()) r["release_resampling"] = grid.release_resampling;
  return r;
}

}  // namespace talus::run
