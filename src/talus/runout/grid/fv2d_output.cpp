#include "talus/runout/grid/fv2d_output.hpp"

#include <fmt/format.h>

#include <limits>

#include "talus/io/raster.hpp"

namespace talus::runout {

namespace {

// The grid as a raster without values, in the terrain's place and CRS.
io::Raster grid_raster(const GridSpec& g) {
  io::Raster r;
  r.nx = g.shape.nx, r.ny = g.shape.ny, r.dx = g.shape.dx, r.dy = g.shape.dy;
  r.x_west = g.x_west, r.y_north = g.y_north, r.projection = g.projection;
  r.nodata = std::numeric_limits<double>::quiet_NaN();
  return r;
}

bool inside(const GridSpec& g, std::size_t c) { return g.inside.empty() || g.inside[c]; }

// The bed (with obstacles) as a surface for ParaView: grid nodes at the mean
// elevation of the cells of the domain around them, two triangles per cell.
void terrain_surface(const GridSpec& g, io::MeshFrame& mesh, std::vector<std::size_t>& cell_of) {
  const std::size_t nx = g.shape.nx, ny = g.shape.ny;
  std::vector<double> sum((nx + 1) * (ny + 1), 0.0), count(sum.size(), 0.0);
  for (std::size_t j = 0; j < ny; ++j)
    for (std::size_t i = 0; i < nx; ++i) {
      const std::size_t c = j * nx + i;
      if (!inside(g, c)) continue;
      const double z = g.elevation[c] + (g.obstacles.empty() ? 0.0 : g.obstacles[c]);
      for (std::size_t n : {j * (nx + 1) + i, j * (nx + 1) + i + 1, (j + 1) * (nx + 1) + i,
                            (j + 1) * (nx + 1) + i + 1})
        sum[n] += z, count[n] += 1.0;
    }
  for (std::size_t j = 0; j <= ny; ++j)
    for (std::size_t i = 0; i <= nx; ++i) {
      const std::size_t n = j * (nx + 1) + i;
      mesh.points.emplace_back(g.x_west + i * g.shape.dx, g.y_north - j * g.shape.dy,
                               count[n] > 0 ? sum[n] / count[n] : 0.0);
    }
  for (std::size_t j = 0; j < ny; ++j)
    for (std::size_t i = 0; i < nx; ++i) {
      if (!inside(g, j * nx + i)) continue;
      const int a = static_cast<int>(j * (nx + 1) + i), b = a + 1;
      const int d = static_cast<int>((j + 1) * (nx + 1) + i), e = d + 1;
      mesh.triangles.push_back({a, b, e});
      mesh.triangles.push_back({a, e, d});
      cell_of.push_back(j * nx + i), cell_of.push_back(j * nx + i);
    }
}

}  // namespace

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
  if (!snapshots) return;
  const auto folder = dir_ / "snapshots";
  std::filesystem::create_directories(folder);
  if (resume) io::CsvSeries::truncate_after(folder / "times.csv", resume_time);
  snapshot_times_ = std::make_unique<io::CsvSeries>(
      folder / "times.csv", std::vector<std::string>{"time", "index"}, resume);
  snapshot_meshes_ = std::make_unique<io::PvdSeries>(folder, "flow", resume);
  if (resume) snapshot_meshes_->truncate_after(resume_time);
  terrain_surface(grid_, mesh_, mesh_cell_);
}

void Fv2dOutputs::on_snapshot(const Fv2dSolver& s) {
  const std::size_t n = s.state().h.size(), index = snapshot_meshes_->entries().size();
  const double t = s.state().time;
  std::vector<double> height(n), speed(n);
  for (std::size_t c = 0; c < n; ++c) {
    const bool in = inside(grid_, c);
    height[c] = in ? s.normal_height(c) : std::numeric_limits<double>::quiet_NaN();
    speed[c] = in ? s.speed(c) : std::numeric_limits<double>::quiet_NaN();
  }
  const auto folder = dir_ / "snapshots";
  auto write = [&](const std::string& name, const std::vector<double>& values, std::string what,
                   std::string unit) {
    io::Raster r = grid_raster(grid_);
    r.description = std::move(what), r.unit = std::move(unit), r.values = values;
    io::write_geotiff((folder / fmt::format("{}_{:06d}.tif", name, index)).string(), r);
  };
  write("height", height, fmt::format("flow height at t = {:.6g} s, bed-normal", t), "m");
  write("speed", speed, fmt::format("flow speed at t = {:.6g} s, bed-parallel", t), "m/s");
  auto& h = mesh_.cell_scalars["height"];
  auto& v = mesh_.cell_scalars["speed"];
  h.resize(mesh_cell_.size()), v.resize(mesh_cell_.size());
  for (std::size_t k = 0; k < mesh_cell_.size(); ++k)
    h[k] = height[mesh_cell_[k]], v[k] = speed[mesh_cell_[k]];
  snapshot_meshes_->add(t, mesh_);
  snapshot_times_->row({t, static_cast<double>(index)});
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
  if (snapshot_times_) snapshot_times_->flush();
}

void Fv2dOutputs::write_results(const Fv2dSolver& s, const Fv2dMaxima& m) const {
  io::Raster r = grid_raster(grid_);
  // Cells outside the domain (the terrain's no-data) are no-data in every map.
  const auto& inside = s.terrain().inside();
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
