#include "talus/io/raster_resample.hpp"

#include <algorithm>
#include <cmath>

namespace talus::io {
namespace {

// Along one axis: target interval k is [t0 + k ht, t0 + (k + 1) ht], source
// interval m is [s0 + m hs, ...]; returns per target interval the source
// intervals it overlaps and the length they share.
struct Overlap {
  std::size_t source;
  double length;
};

std::vector<std::vector<Overlap>> overlaps(double t0, double ht, std::size_t nt, double s0,
                                           double hs, std::size_t ns) {
  std::vector<std::vector<Overlap>> out(nt);
  for (std::size_t k = 0; k < nt; ++k) {
    const double a = t0 + k * ht, b = a + ht;
    // Source intervals that can overlap [a, b].
    const double first = std::floor((a - s0) / hs), last = std::ceil((b - s0) / hs);
    for (double m = std::max(first, 0.0); m < std::min(last, static_cast<double>(ns)); ++m) {
      const double lo = std::max(a, s0 + m * hs), hi = std::min(b, s0 + (m + 1) * hs);
      if (hi > lo) out[k].push_back({static_cast<std::size_t>(m), hi - lo});
    }
  }
  return out;
}

}  // namespace

std::vector<double> resample_area_weighted(const Raster& source, const Raster& grid) {
  // Columns run east from x_west; rows run south from y_north, so along y
  // both are measured southwards from their northern edges.
  const auto wx = overlaps(grid.x_west, grid.dx, grid.nx, source.x_west, source.dx, source.nx);
  const auto wy = overlaps(-grid.y_north, grid.dy, grid.ny, -source.y_north, source.dy, source.ny);
  std::vector<double> out(grid.nx * grid.ny, 0.0);
  const double area = grid.dx * grid.dy;
  for (std::size_t j = 0; j < grid.ny; ++j)
    for (std::size_t i = 0; i < grid.nx; ++i) {
      double sum = 0.0;
      for (const Overlap& y : wy[j])
        for (const Overlap& x : wx[i]) {
          const double v = source.at(x.source, y.source);
          if (!source.is_nodata(v)) sum += v * x.length * y.length;
        }
      out[j * grid.nx + i] = sum / area;
    }
  return out;
}

double raster_integral(const Raster& r) {
  double sum = 0.0;
  for (double v : r.values)
    if (!r.is_nodata(v)) sum += v;
  return sum * r.dx * r.dy;
}

}  // namespace talus::io
