#include "talus/runout/grid/fv2d_output.hpp"

#include <limits>

#include "talus/io/raster.hpp"

namespace talus::runout {

Fv2dOutputs::Fv2dOutputs(std::filesystem::path dir, const GridSpec& grid, bool resume,
                         double resume_time)
    : dir_(std::move(dir)), grid_(grid) {
  if (resume) io::CsvSeries::truncate_after(dir_ / "series.csv", resume_time);
  series_ = std::make_unique<io::CsvSeries>(
      dir_ / "series.csv",
      std::vector<std::string>{"time", "volume", "outflow_volume", "mass", "momentum_x",
                               "momentum_y", "momentum_sum", "kinetic_energy", "max_speed",
                               "max_height", "flowing_area"},
      resume);
}

void Fv2dOutputs::on_series(const Fv2dSolver& s) {
  std::size_t flowing = 0;
  for (std::size_t c = 0; c < s.state().h.size(); ++c)
    if (s.speed(c) >= Fv2dSolver::kRestSpeed) ++flowing;
  series_->row({s.state().time, s.volume(), s.outflow_volume(), s.mass(), s.momentum_x(),
                s.momentum_y(), s.momentum_sum(), s.kinetic_energy(), s.max_speed(), s.max_height(),
                static_cast<double>(flowing) * s.terrain().shape().cell_area()});
}

void Fv2dOutputs::flush() { series_->flush(); }

void Fv2dOutputs::write_results(const Fv2dSolver& s, const Fv2dMaxima& m) const {
  io::Raster r;
  r.nx = grid_.shape.nx, r.ny = grid_.shape.ny, r.dx = grid_.shape.dx, r.dy = grid_.shape.dy;
  r.x_west = grid_.x_west, r.y_north = grid_.y_north, r.projection = grid_.projection;
  // Cells outside the domain (the terrain's no-data) are no-data in every map.
  const auto& inside = s.terrain().inside();
  r.nodata = std::numeric_limits<double>::quiet_NaN();
  auto write = [&](const std::string& name, std::vector<double> values, const char* what,
                   const char* unit) {
    r.description = what, r.unit = unit;
    for (std::size_t c = 0; c < values.size(); ++c)
      if (!inside[c]) values[c] = std::numeric_limits<double>::quiet_NaN();
    r.values = std::move(values);
    io::write_geotiff((dir_ / (name + ".tif")).string(), r);
    io::write_npy((dir_ / (name + ".npy")).string(), r);
  };
  std::vector<double> deposit(s.state().h.size());
  for (std::size_t c = 0; c < deposit.size(); ++c) deposit[c] = s.normal_height(c);
  // Heights are bed-normal (H cos(theta)); the released depth and the volume
  // are vertical, so on a slope the sum of deposit x cell area is less than
  // the volume (by cos(theta)).
  write("max_height", m.height, "maximum flow height, bed-normal", "m");
  write("max_speed", m.speed, "maximum flow speed, bed-parallel", "m/s");
  write("max_pressure", m.pressure, "maximum impact pressure rho v^2", "Pa");
  write("deposit", deposit, "deposit height at the end, bed-normal", "m");
  write("elevation", s.terrain().elevation(), "bed elevation with obstacles", "m");
  // NaN also where the flow never arrived.
  write("arrival_time", m.arrival, "time the flow height first exceeded 1 cm", "s");
  series_->flush();
}

}  // namespace talus::runout
