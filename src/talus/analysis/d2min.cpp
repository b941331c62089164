#include "talus/analysis/d2min.hpp"

#include <fmt/core.h>

#include <Eigen/QR>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "talus/analysis/cell_list.hpp"
#include "talus/core/error.hpp"

namespace talus::analysis {

D2min non_affine_displacement(const std::vector<Vec3>& x0, const std::vector<Vec3>& x1,
                              const std::vector<double>& radius, const D2minOptions& o,
                              const std::vector<char>& included) {
  const std::size_t n = x0.size();
  if (x1.size() != n || radius.size() != n || (!included.empty() && included.size() != n))
    throw std::invalid_argument("non_affine_displacement: arrays differ in length");
  if (o.dimension != 2 && o.dimension != 3) throw InputError("d2min: dimension must be 2 or 3");
  if (!(o.cutoff > 0) || !std::isfinite(o.cutoff))
    throw InputError(fmt::format("--cutoff: expected a positive length, got {}", o.cutoff));
  const int dim = o.dimension;
  auto in = [&](std::size_t i) { return included.empty() || included[i]; };

  D2min out;
  const double nan = std::numeric_limits<double>::quiet_NaN();
  out.d2min.assign(n, nan);
  out.d_min_norm.assign(n, nan);
  out.neighbours.assign(n, 0);
  for (double r : radius) out.mean_diameter += 2 * r / n;
  if (n == 0) return out;

  const CellList cells(x0, o.cutoff);
  std::vector<std::size_t> near;
  for (std::size_t i = 0; i < n; ++i) {
    if (!in(i)) continue;
    near.clear();
    cells.for_each_neighbour(i, [&](std::size_t j, double) {
      if (in(j)) near.push_back(j);
    });
    out.neighbours[i] = static_cast<int>(near.size());
    // Fewer than D + 1 neighbours fit any motion exactly: D^2_min = 0 would say nothing.
    if (static_cast<int>(near.size()) < dim + 1) continue;
    // Rows d_j(t0) and d_j(t1); J^T solves A J^T = B in the least-squares sense.
    Eigen::MatrixXd a(near.size(), dim), b(near.size(), dim);
    for (std::size_t k = 0; k < near.size(); ++k) {
      const Vec3 d0 = x0[near[k]] - x0[i], d1 = x1[near[k]] - x1[i];
      a.row(k) = d0.head(dim).transpose();
      b.row(k) = d1.head(dim).transpose();
    }
    Eigen::ColPivHouseholderQR<Eigen::MatrixXd> qr(a);
    // Neighbours on a plane (a line in 2D) leave J undetermined across it: no value. The
    // threshold is relative to the largest pivot; round-off of a degenerate set is ~1e-16.
    qr.setThreshold(1e-9);
    if (qr.rank() < dim) continue;
    const Eigen::MatrixXd jt = qr.solve(b);
    const double d2 = (a * jt - b).squaredNorm();
    out.d2min[i] = d2;
    out.d_min_norm[i] =
        out.mean_diameter > 0 ? std::sqrt(d2 / near.size()) / out.mean_diameter : nan;
    ++out.evaluated;
    out.mean_d2min += d2;
    out.mean_d_min_norm += out.d_min_norm[i];
  }
  if (out.evaluated) {
    out.mean_d2min /= out.evaluated;
    out.mean_d_min_norm /= out.evaluated;
  }
  return out;
}

}  // namespace talus::analysis
