#include "talus/analysis/d2min.hpp"

#include <fmt/core.h>

#include <Eigen/QR>
#include <algorithm>
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

D2minCorrelation d2min_correlation(const std::vector<Vec3>& position,
                                   const std::vector<double>& d_min, double mean_diameter,
                                   const D2minCorrelationOptions& o) {
  const std::size_t n = position.size();
  if (d_min.size() != n)
    throw std::invalid_argument("d2min_correlation: positions and values differ in length");
  if (o.dimension != 2 && o.dimension != 3)
    throw InputError("d2min correlation: dimension must be 2 or 3");
  if (!(o.bin_width > 0) || !std::isfinite(o.bin_width))
    throw InputError(
        fmt::format("--correlation: expected a positive bin width, got {}", o.bin_width));
  if (!(o.r_max > 0) || !std::isfinite(o.r_max))
    throw InputError(
        fmt::format("--correlation-rmax: expected a positive length, got {}", o.r_max));
  if (!(mean_diameter > 0) || !std::isfinite(mean_diameter))
    throw InputError(
        fmt::format("d2min correlation: mean diameter {} is not positive", mean_diameter));
  // A bound on the bins keeps a slip of units (a bin width in mm given in m) from asking for
  // gigabytes; 10^6 bins is far finer than any plot of C(r) needs.
  const double bins_wanted = std::ceil(o.r_max / o.bin_width);
  if (bins_wanted > 1e6)
    throw InputError(fmt::format(
        "--correlation {}: {:.0f} bins up to {:.4g} m; use a bin width of at least {:.3g} m",
        o.bin_width, bins_wanted, o.r_max, o.r_max / 1e6));
  const int bins = std::max(1, static_cast<int>(bins_wanted));
  const double w = o.bin_width, reach = bins * w;

  D2minCorrelation out;
  const double nan = std::numeric_limits<double>::quiet_NaN();
  out.r.resize(bins);
  for (int b = 0; b < bins; ++b) out.r[b] = (b + 0.5) * w;
  out.c.assign(bins, nan);
  out.c_over_c0.assign(bins, nan);
  out.grains.assign(bins, 0);
  out.pairs.assign(bins, 0);
  auto valued = [&](std::size_t i) { return !std::isnan(d_min[i]); };
  for (std::size_t i = 0; i < n; ++i)
    if (valued(i)) {
      out.c0 += d_min[i] * d_min[i] / mean_diameter;
      ++out.valued;
    }
  if (out.valued == 0) return out;
  out.c0 /= out.valued;

  // In 2D the grains lie in a plane; a z left in the snapshot must not count in the distance.
  std::vector<Vec3> flat;
  if (o.dimension == 2) {
    flat = position;
    for (Vec3& x : flat) x.z() = 0.0;
  }
  const CellList cells(o.dimension == 2 ? flat : position, reach);
  // Per centre i: the sum of D_min,j and the count M_i in each bin, then C_i into the totals.
  // Only the bins i's partners fall in are visited and cleared (`touched`), so fine bins cost
  // memory but no time per grain.
  std::vector<double> sum_j(bins, 0.0), sum_c(bins, 0.0);
  std::vector<std::size_t> m(bins, 0);
  std::vector<int> touched;
  for (std::size_t i = 0; i < n; ++i) {
    if (!valued(i)) continue;
    cells.for_each_neighbour(i, [&](std::size_t j, double dist) {
      if (!valued(j)) return;
      // dist < reach = bins w, so b < bins except when rounding lands on the last edge.
      const auto b = std::min(static_cast<int>(dist / w), bins - 1);
      if (m[b]++ == 0) touched.push_back(b);
      sum_j[b] += d_min[j];
      if (j > i) ++out.pairs[b];
    });
    for (int b : touched) {
      sum_c[b] += d_min[i] * sum_j[b] / (static_cast<double>(m[b]) * mean_diameter);
      ++out.grains[b];
      sum_j[b] = 0.0;
      m[b] = 0;
    }
    touched.clear();
  }
  for (int b = 0; b < bins; ++b)
    if (out.grains[b]) {
      out.c[b] = sum_c[b] / static_cast<double>(out.grains[b]);
      if (out.c0 > 0) out.c_over_c0[b] = out.c[b] / out.c0;
    }
  return out;
}

}  // namespace talus::analysis
