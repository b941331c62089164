#pragma once
// A 1D runout path as 2D terrain (spec runout.md §2: "the 1D flume is a
// special case"): the path's bed y(x) as elevation along the columns,
// repeated over a few rows (a straight channel), and a release polygon in the
// path's vertical plane as the vertical thickness of each cell. The release
// is the cell average of the polygon's vertical extent, so the volume is the
// polygon's area exactly, sliced the same way as DAN's vertical blocks
// (release.hpp): both models start from the same mass distribution in x.
#include <vector>

#include "talus/runout/grid/terrain.hpp"
#include "talus/runout/path.hpp"

namespace talus::runout {

struct ExtrudedPath {
  GridShape shape;
  double x_begin = 0.0;           // x of the west edge of column 0
  std::vector<double> elevation;  // per cell: path y at the cell centre's x
  std::vector<double> release;    // per cell: vertical thickness (m)
  double x_centre(std::size_t i) const {
    return x_begin + (static_cast<double>(i) + 0.5) * shape.dx;
  }
};

// Columns of width dx from x_begin to (at least) x_end, `rows` rows of width
// row_width. The path's x must increase along it (RunoutPath::s_at_x).
// Throws InputError for dx <= 0, x_end <= x_begin, rows == 0 or row_width <= 0.
ExtrudedPath extrude_path(const RunoutPath& path, double x_begin, double x_end, double dx,
                          std::size_t rows, double row_width,
                          const std::vector<Vec2>& release_polygon);

}  // namespace talus::runout
