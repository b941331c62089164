#include "talus/runout/grid/fv2d_output.hpp"

#include <fmt/format.h>

#include <limits>

namespace talus::runout {

Fv2dOutputs::Fv2dOutputs(std::filesystem::path dir, const GridSpec& grid, bool resume,
                         double resume_time, bool snapshots)
    : dir_(std::move(dir)), grid_(grid) {
  if (resume) io::CsvSeries::truncate_after(dir_ / "series.csv", resume_time);
  series_ = std::make_unique<io::CsvSeries>(
      dir_ / "series.csv",
      std::vector<std::string>{"time", "volume", "outflow_volume", "mass", "momentum_x",
                               "momentum_y", "momentum_sum", "kinetic_energy", "max_speed",
                               "max_height", "flowing_area"},
      resume);
  if (snapshots) snapshots_ = std::make_unique<GridSnapshots>(dir_, grid, resume, resume_time);
}

void Fv2dOutputs::on_snapshot(const Fv2dSolver& s) {
  const std::size_t n = s.state().h.size();
  const double t = s.state().time;
  std::vector<double> height(n), speed(n);
  for (std::size_t c = 0; c < n; ++c) height[c] = s.normal_height(c), speed[c] = s.speed(c);
  snapshots_->add(t, {{"height", std::move(height),
                       fmt::format("flow height at t = {:.6g} s, bed-normal", t), "m"},
                      {"speed", std::move(speed),
                       fmt::format("flow speed at t = {:.6g} s, bed-parallel", t), "m/s"}});
}

void Fv2dOutputs::on_series(const Fv2dSolver& s) {
  std::size_t flowing = 0;
  for (std::size_t c = 0; c < s.state().h.size(); ++c)
    if (s.speed(c) >= Fv2dSolver::kRestSpeed) ++flowing;
  series_->row({s.state().time, s.volume(), s.outflow_volume(), s.mass(), s.momentum_x(),
                s.momentum_y(), s.momentum_sum(), s.kinetic_energy(), s.max_speed(), s.max_height(),
                static_cast<double>(flowing) * s.terrain().shape().cell_area()});
}

void Fv2dOutputs::flush() {
  series_->flush();
  if (snapshots_) snapshots_->flush();
}

void Fv2dOutputs::write_results(const Fv2dSolver& s, const Fv2dMaxima& m) const {
  std::vector<double> deposit(s.state().h.size());
  for (std::size_t c = 0; c < deposit.size(); ++c) deposit[c] = s.normal_height(c);
  // Heights are bed-normal (H cos(theta)); the released depth and the volume
  // are vertical, so on a slope the sum of deposit x cell area is less than
  // the volume (by cos(theta)).
  const std::vector<GridField> maps = {
      {"max_height", m.height, "maximum flow height, bed-normal", "m"},
      {"max_speed", m.speed, "maximum flow speed, bed-parallel", "m/s"},
      {"max_pressure", m.pressure, "maximum impact pressure rho v^2", "Pa"},
      {"deposit", deposit, "deposit height at the end, bed-normal", "m"},
      {"elevation", s.terrain().elevation(), "bed elevation with obstacles", "m"},
      // NaN also where the flow never arrived.
      {"arrival_time", m.arrival, "time the flow height first exceeded 1 cm", "s"}};
  for (const auto& map : maps) write_result_map(dir_, grid_, map);
  series_->flush();
}

}  // namespace talus::runout
