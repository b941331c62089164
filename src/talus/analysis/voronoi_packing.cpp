#include "talus/analysis/voronoi_packing.hpp"

#include <fmt/core.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <voro++/voro++.hh>

#include "talus/analysis/rdf.hpp"
#include "talus/core/error.hpp"

namespace talus::analysis {

namespace {

// voro++ finds neighbours through a grid of blocks; about five grains a block is its advice.
int blocks(double side, double block) {
  return static_cast<int>(std::clamp(std::floor(side / block), 1.0, 1000.0));
}

}  // namespace

LocalPacking voronoi_packing(const std::vector<Vec3>& position, const std::vector<double>& radius,
                             int dimension, double margin) {
  const std::size_t n = position.size();
  if (radius.size() != n) throw std::invalid_argument("voronoi_packing: arrays differ in length");
  if (dimension != 2 && dimension != 3) throw InputError("packing: dimension must be 2 or 3");
  if (!(margin >= 0) || !std::isfinite(margin))
    throw InputError(fmt::format("--margin: expected a length >= 0, got {}", margin));
  for (std::size_t i = 0; i < n; ++i)
    if (!(radius[i] > 0) || !position[i].allFinite())
      throw std::invalid_argument("voronoi_packing: a grain with a radius <= 0 or not finite");
  const double nan = std::numeric_limits<double>::quiet_NaN();
  LocalPacking p;
  p.cell_volume.assign(n, nan);
  p.solid_fraction.assign(n, nan);
  p.boundary.assign(n, 1);
  std::tie(p.lo, p.hi) = grain_box(position, radius, dimension);
  if (n == 0) return p;

  // 2D: a slab [-h/2, h/2] periodic in z, every disk at z = 0 (see the header); its height
  // only scales the cell volumes, so one mean diameter keeps the cells well shaped.
  double mean_d = 0.0;
  for (double r : radius) mean_d += 2 * r / n;
  const bool flat = dimension == 2;
  const Vec3 lo(p.lo.x(), p.lo.y(), flat ? -0.5 * mean_d : p.lo.z());
  const Vec3 hi(p.hi.x(), p.hi.y(), flat ? 0.5 * mean_d : p.hi.z());
  const Vec3 side = hi - lo;
  const double per_grain = flat ? side.x() * side.y() / n : side.prod() / n;
  const double block = flat ? std::sqrt(5 * per_grain) : std::cbrt(5 * per_grain);
  voro::container_poly con(lo.x(), hi.x(), lo.y(), hi.y(), lo.z(), hi.z(), blocks(side.x(), block),
                           blocks(side.y(), block), flat ? 1 : blocks(side.z(), block), false,
                           false, flat, 8);
  for (std::size_t i = 0; i < n; ++i)
    con.put(static_cast<int>(i), position[i].x(), position[i].y(), flat ? 0.0 : position[i].z(),
            radius[i]);

  voro::voronoicell_neighbor cell;
  voro::c_loop_all loop(con);
  std::vector<int> neighbours;
  std::vector<double> vertices;
  std::vector<char> reaches_box(n, 1);  // stays 1 for a grain without a cell
  // A cell can touch the box at a vertex only (a zero-area face that voro++ may drop), as the
  // end disks of shifted rows of a hexagonal lattice do; so vertices on the box count too.
  const double on_face = 1e-10 * side.norm();
  const int faces = flat ? 2 : 3;  // the slab's z faces are periodic, not the box
  if (loop.start()) do {
      if (!con.compute_cell(cell, loop)) continue;  // empty radical cell
      const int i = loop.pid();
      p.cell_volume[i] = flat ? cell.volume() / side.z() : cell.volume();
      cell.neighbors(neighbours);
      // voro++ numbers the walls of the container -1 to -6.
      bool touches = std::any_of(neighbours.begin(), neighbours.end(), [](int k) { return k < 0; });
      double x, y, z;
      loop.pos(x, y, z);
      cell.vertices(x, y, z, vertices);
      for (std::size_t v = 0; v + 2 < vertices.size() && !touches; v += 3)
        for (int d = 0; d < faces; ++d)
          touches =
              touches || vertices[v + d] - lo[d] < on_face || hi[d] - vertices[v + d] < on_face;
      reaches_box[i] = touches;
    } while (loop.inc());

  double grains = 0.0, cells = 0.0, grains_all = 0.0, cells_all = 0.0;
  for (std::size_t i = 0; i < n; ++i) {
    if (std::isnan(p.cell_volume[i])) continue;
    const double v =
        flat ? M_PI * radius[i] * radius[i] : 4.0 / 3.0 * M_PI * radius[i] * radius[i] * radius[i];
    p.solid_fraction[i] = v / p.cell_volume[i];
    grains_all += v;
    cells_all += p.cell_volume[i];
    bool near_face = false;
    for (int d = 0; d < dimension; ++d)
      near_face =
          near_face || position[i][d] - p.lo[d] < margin || p.hi[d] - position[i][d] < margin;
    p.boundary[i] = reaches_box[i] || near_face;
    if (p.boundary[i]) continue;
    ++p.interior;
    p.mean_interior += p.solid_fraction[i];
    grains += v;
    cells += p.cell_volume[i];
  }
  if (p.interior) {
    p.mean_interior /= p.interior;
    p.overall_interior = grains / cells;
  }
  p.overall_all = cells_all > 0 ? grains_all / cells_all : 0.0;
  return p;
}

}  // namespace talus::analysis
