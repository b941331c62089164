#include "talus/runout/grid/terrain.hpp"

#include <fmt/format.h>

#include <cmath>

#include "talus/core/error.hpp"

namespace talus::runout {

Terrain::Terrain(GridShape shape, std::vector<double> elevation)
    : shape_(shape), b_(std::move(elevation)) {
  const std::size_t nx = shape.nx, ny = shape.ny, n = shape.cells();
  if (nx == 0 || ny == 0) throw InputError("terrain: the grid has no cells");
  if (!(shape.dx > 0) || !(shape.dy > 0))
    throw InputError(
        fmt::format("terrain: cell size {} x {} must be positive", shape.dx, shape.dy));
  if (b_.size() != n)
    throw InputError(
        fmt::format("terrain: {} elevations for a {} x {} grid", b_.size(), shape.nx, shape.ny));
  for (std::size_t c = 0; c < n; ++c)
    if (!std::isfinite(b_[c]))
      throw InputError(
          fmt::format("terrain: elevation of cell ({}, {}) is not finite", c % nx, c / nx));
  bx_.assign(n, 0.0), by_.assign(n, 0.0), bxx_.assign(n, 0.0), bxy_.assign(n, 0.0);
  byy_.assign(n, 0.0), cos2_.assign(n, 1.0);
  auto b = [&](std::size_t i, std::size_t j) { return b_[shape.index(i, j)]; };
  // First derivative along one axis at index k of m samples spaced h apart.
  auto d1 = [](auto get, std::size_t k, std::size_t m, double h) {
    if (m < 2) return 0.0;
    if (k == 0) return (get(1) - get(0)) / h;
    if (k == m - 1) return (get(m - 1) - get(m - 2)) / h;
    return (get(k + 1) - get(k - 1)) / (2 * h);
  };
  auto d2 = [](auto get, std::size_t k, std::size_t m, double h) {
    if (m < 3) return 0.0;
    const std::size_t c = k == 0 ? 1 : (k == m - 1 ? m - 2 : k);
    return (get(c + 1) - 2 * get(c) + get(c - 1)) / (h * h);
  };
  for (std::size_t j = 0; j < ny; ++j) {
    for (std::size_t i = 0; i < nx; ++i) {
      const std::size_t c = shape.index(i, j);
      auto along_x = [&](std::size_t k) { return b(k, j); };
      auto along_y = [&](std::size_t k) { return b(i, k); };
      bx_[c] = d1(along_x, i, nx, shape.dx);
      by_[c] = d1(along_y, j, ny, shape.dy);
      bxx_[c] = d2(along_x, i, nx, shape.dx);
      byy_[c] = d2(along_y, j, ny, shape.dy);
      cos2_[c] = 1.0 / (1.0 + bx_[c] * bx_[c] + by_[c] * by_[c]);
    }
  }
  // The mixed derivative from the x-slopes of the neighbouring rows.
  for (std::size_t j = 0; j < ny; ++j)
    for (std::size_t i = 0; i < nx; ++i) {
      auto slope_row = [&](std::size_t k) { return bx_[shape.index(i, k)]; };
      bxy_[shape.index(i, j)] = d1(slope_row, j, ny, shape.dy);
    }
}

}  // namespace talus::runout
