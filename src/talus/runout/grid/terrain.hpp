#pragma once
// The bed of a 2D depth-averaged run: elevations on a regular grid of cell
// centres, and the slope and curvature terms the flow equations need, computed
// once from them. Cells are indexed c = j * nx + i, i along x (columns), j
// along the rows in memory order. For a raster read from GeoTIFF or ESRI ASCII
// the rows run from north to south, so +j points south; the equations are the
// same in a mirrored frame, so the solver never needs to know.
#include <cstddef>
#include <vector>

namespace talus::runout {

struct GridShape {
  std::size_t nx = 0, ny = 0;  // cells along x and along the rows
  double dx = 1.0, dy = 1.0;   // cell size, m
  std::size_t cells() const { return nx * ny; }
  std::size_t index(std::size_t i, std::size_t j) const { return j * nx + i; }
  double cell_area() const { return dx * dy; }
};

class Terrain {
 public:
  // inside: 1 for a cell of the domain, 0 for one outside it (a raster's
  // no-data cells, whose elevation is not read); empty: every cell is inside.
  // Throws InputError for an empty grid, a cell size <= 0, a size mismatch,
  // no cell inside, or a non-finite elevation inside.
  Terrain(GridShape shape, std::vector<double> elevation, std::vector<unsigned char> inside = {});

  const GridShape& shape() const { return shape_; }
  // NaN outside the domain.
  const std::vector<double>& elevation() const { return b_; }
  const std::vector<unsigned char>& inside() const { return inside_; }
  bool has_outside() const { return has_outside_; }
  // Central differences inside, one-sided next to an edge or an outside cell
  // (so an inclined plane is exact everywhere).
  const std::vector<double>& slope_x() const { return bx_; }
  const std::vector<double>& slope_y() const { return by_; }
  // Second derivatives (zero across an edge with a single row or column).
  const std::vector<double>& curvature_xx() const { return bxx_; }
  const std::vector<double>& curvature_xy() const { return bxy_; }
  const std::vector<double>& curvature_yy() const { return byy_; }
  // cos^2 of the bed inclination, 1 / (1 + |grad b|^2).
  const std::vector<double>& cos2() const { return cos2_; }

 private:
  GridShape shape_;
  std::vector<double> b_, bx_, by_, bxx_, bxy_, byy_, cos2_;
  std::vector<unsigned char> inside_;
  bool has_outside_ = false;
};

}  // namespace talus::runout
