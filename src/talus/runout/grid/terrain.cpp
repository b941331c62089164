#include "talus/runout/grid/terrain.hpp"

#include <fmt/format.h>

#include <cmath>
#include <limits>

#include "talus/core/error.hpp"

namespace talus::runout {

Terrain::Terrain(GridShape shape, std::vector<double> elevation, std::vector<unsigned char> inside)
    : shape_(shape), b_(std::move(elevation)), inside_(std::move(inside)) {
  const std::size_t nx = shape.nx, ny = shape.ny, n = shape.cells();
  if (nx == 0 || ny == 0) throw InputError("terrain: the grid has no cells");
  if (!(shape.dx > 0) || !(shape.dy > 0))
    throw InputError(
        fmt::format("terrain: cell size {} x {} must be positive", shape.dx, shape.dy));
  if (b_.size() != n)
    throw InputError(
        fmt::format("terrain: {} elevations for a {} x {} grid", b_.size(), shape.nx, shape.ny));
  if (inside_.empty()) inside_.assign(n, 1);
  if (inside_.size() != n)
    throw InputError(fmt::format("terrain: {} domain flags for {} cells", inside_.size(), n));
  std::size_t count = 0;
  for (std::size_t c = 0; c < n; ++c) {
    if (!inside_[c]) {
      b_[c] = std::numeric_limits<double>::quiet_NaN();
      continue;
    }
    ++count;
    if (!std::isfinite(b_[c]))
      throw InputError(
          fmt::format("terrain: elevation of cell ({}, {}) is not finite", c % nx, c / nx));
  }
  if (count == 0) throw InputError("terrain: no cell has an elevation (all are no-data)");
  has_outside_ = count < n;
  bx_.assign(n, 0.0), by_.assign(n, 0.0), bxx_.assign(n, 0.0), bxy_.assign(n, 0.0);
  byy_.assign(n, 0.0), cos2_.assign(n, 1.0);
  // Derivatives along one line of m samples spaced h apart, `get(k)` the
  // value and `in(k)` whether sample k is in the domain: central where both
  // neighbours are, one-sided where one is, zero where neither is.
  auto d1 = [](auto get, auto in, std::size_t k, std::size_t m, double h) {
    const bool l = k > 0 && in(k - 1), r = k + 1 < m && in(k + 1);
    if (l && r) return (get(k + 1) - get(k - 1)) / (2 * h);
    if (r) return (get(k + 1) - get(k)) / h;
    if (l) return (get(k) - get(k - 1)) / h;
    return 0.0;
  };
  // Second differences on the nearest three consecutive samples in the domain
  // centred on k, k + 1 or k - 1.
  auto d2 = [](auto get, auto in, std::size_t k, std::size_t m, double h) {
    auto triple = [&](std::size_t c) {
      return c > 0 && c + 1 < m && in(c - 1) && in(c) && in(c + 1);
    };
    std::size_t c = k;
    if (!triple(c)) c = k + 1;
    if (!triple(c) && k > 0) c = k - 1;
    if (!triple(c)) return 0.0;
    return (get(c + 1) - 2 * get(c) + get(c - 1)) / (h * h);
  };
  for (std::size_t j = 0; j < ny; ++j) {
    for (std::size_t i = 0; i < nx; ++i) {
      const std::size_t c = shape.index(i, j);
      if (!inside_[c]) continue;
      auto along_x = [&](std::size_t k) { return b_[shape.index(k, j)]; };
      auto along_y = [&](std::size_t k) { return b_[shape.index(i, k)]; };
      auto in_x = [&](std::size_t k) { return inside_[shape.index(k, j)] != 0; };
      auto in_y = [&](std::size_t k) { return inside_[shape.index(i, k)] != 0; };
      bx_[c] = d1(along_x, in_x, i, nx, shape.dx);
      by_[c] = d1(along_y, in_y, j, ny, shape.dy);
      bxx_[c] = d2(along_x, in_x, i, nx, shape.dx);
      byy_[c] = d2(along_y, in_y, j, ny, shape.dy);
      cos2_[c] = 1.0 / (1.0 + bx_[c] * bx_[c] + by_[c] * by_[c]);
    }
  }
  // The mixed derivative from the x-slopes of the neighbouring rows.
  for (std::size_t j = 0; j < ny; ++j)
    for (std::size_t i = 0; i < nx; ++i) {
      if (!inside_[shape.index(i, j)]) continue;
      auto slope_row = [&](std::size_t k) { return bx_[shape.index(i, k)]; };
      auto in_y = [&](std::size_t k) { return inside_[shape.index(i, k)] != 0; };
      bxy_[shape.index(i, j)] = d1(slope_row, in_y, j, ny, shape.dy);
    }
}

}  // namespace talus::runout
