#pragma once
// The divergence of a depth-averaged velocity at a cell, for the earth
// pressure's switch between k_a and k_p (fv2d and the two-phase solver).
#include <cstddef>

#include "talus/runout/grid/terrain.hpp"

namespace talus::runout {

// Central differences of u(cell) along x and v(cell) along y, one-sided
// next to the domain's edge, no term across a single cell.
template <class U, class V>
double velocity_divergence(const Terrain& terrain, std::ptrdiff_t i, std::ptrdiff_t j, U u, V v) {
  using Index = std::ptrdiff_t;
  const auto& g = terrain.shape();
  const auto& dom = terrain.inside();
  const Index nx = static_cast<Index>(g.nx), ny = static_cast<Index>(g.ny), c = j * nx + i;
  const Index w = i > 0 && dom[c - 1] ? c - 1 : c, e = i < nx - 1 && dom[c + 1] ? c + 1 : c;
  const Index s = j > 0 && dom[c - nx] ? c - nx : c, n = j < ny - 1 && dom[c + nx] ? c + nx : c;
  double div = 0.0;
  if (e != w) div += (u(e) - u(w)) / (static_cast<double>(e - w) * g.dx);
  if (n != s) div += (v(n) - v(s)) / (static_cast<double>((n - s) / nx) * g.dy);
  return div;
}

}  // namespace talus::runout
