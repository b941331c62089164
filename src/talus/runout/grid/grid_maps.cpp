#include "talus/runout/grid/grid_maps.hpp"

#include <fmt/format.h>

#include <limits>

#include "talus/io/raster.hpp"

namespace talus::runout {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

// The grid as a raster without values, in the terrain's place and CRS.
io::Raster grid_raster(const GridSpec& g) {
  io::Raster r;
  r.nx = g.shape.nx, r.ny = g.shape.ny, r.dx = g.shape.dx, r.dy = g.shape.dy;
  r.x_west = g.x_west, r.y_north = g.y_north, r.projection = g.projection;
  r.nodata = kNaN;
  return r;
}

bool inside(const GridSpec& g, std::size_t c) { return g.inside.empty() || g.inside[c]; }

io::Raster field_raster(const GridSpec& g, GridField& f) {
  io::Raster r = grid_raster(g);
  for (std::size_t c = 0; c < f.values.size(); ++c)
    if (!inside(g, c)) f.values[c] = kNaN;
  r.description = std::move(f.description), r.unit = std::move(f.unit);
  r.values = std::move(f.values);
  return r;
}

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

void write_result_map(const std::filesystem::path& dir, const GridSpec& grid, GridField field) {
  const std::string name = field.name;
  const io::Raster r = field_raster(grid, field);
  io::write_geotiff((dir / (name + ".tif")).string(), r);
  io::write_npy((dir / (name + ".npy")).string(), r);
}

GridSnapshots::GridSnapshots(const std::filesystem::path& dir, const GridSpec& grid, bool resume,
                             double resume_time)
    : folder_(dir / "snapshots"), grid_(grid) {
  std::filesystem::create_directories(folder_);
  if (resume) io::CsvSeries::truncate_after(folder_ / "times.csv", resume_time);
  times_ = std::make_unique<io::CsvSeries>(folder_ / "times.csv",
                                           std::vector<std::string>{"time", "index"}, resume);
  meshes_ = std::make_unique<io::PvdSeries>(folder_, "flow", resume);
  if (resume) meshes_->truncate_after(resume_time);
  terrain_surface(grid_, mesh_, mesh_cell_);
}

void GridSnapshots::add(double time, std::vector<GridField> fields) {
  const std::size_t index = meshes_->entries().size();
  for (auto& f : fields) {
    auto& cells = mesh_.cell_scalars[f.name];
    cells.resize(mesh_cell_.size());
    for (std::size_t k = 0; k < mesh_cell_.size(); ++k)
      cells[k] = inside(grid_, mesh_cell_[k]) ? f.values[mesh_cell_[k]] : kNaN;
    const std::string file = fmt::format("{}_{:06d}.tif", f.name, index);
    io::write_geotiff((folder_ / file).string(), field_raster(grid_, f));
  }
  meshes_->add(time, mesh_);
  times_->row({time, static_cast<double>(index)});
}

void GridSnapshots::flush() { times_->flush(); }

}  // namespace talus::runout
