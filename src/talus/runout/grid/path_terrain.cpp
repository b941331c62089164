#include "talus/runout/grid/path_terrain.hpp"

#include <cmath>

#include "talus/core/error.hpp"
#include "talus/runout/release.hpp"

namespace talus::runout {

ExtrudedPath extrude_path(const RunoutPath& path, double x_begin, double x_end, double dx,
                          std::size_t rows, double row_width,
                          const std::vector<Vec2>& release_polygon) {
  if (!(dx > 0.0) || !(x_end > x_begin) || rows == 0 || !(row_width > 0.0))
    throw InputError("extrude_path: needs dx > 0, x_end > x_begin, rows >= 1, row_width > 0");
  ExtrudedPath out;
  const auto nx = static_cast<std::size_t>(std::ceil((x_end - x_begin) / dx - 1e-9));
  out.shape = GridShape{nx, rows, dx, row_width};
  out.x_begin = x_begin;
  out.elevation.resize(out.shape.cells());
  out.release.resize(out.shape.cells());
  for (std::size_t i = 0; i < nx; ++i) {
    const double x = out.x_centre(i);
    const double y = path.point(path.s_at_x(x)).y();
    const double x0 = x_begin + static_cast<double>(i) * dx;
    const double thickness = polygon_area_between(release_polygon, x0, x0 + dx) / dx;
    for (std::size_t j = 0; j < rows; ++j) {
      out.elevation[out.shape.index(i, j)] = y;
      out.release[out.shape.index(i, j)] = thickness;
    }
  }
  return out;
}

}  // namespace talus::runout
