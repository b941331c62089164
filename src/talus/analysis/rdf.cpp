#include "talus/analysis/rdf.hpp"

#include <fmt/core.h>

#include <cmath>
#include <limits>
#include <stdexcept>

#include "talus/analysis/cell_list.hpp"
#include "talus/core/error.hpp"

namespace talus::analysis {

std::pair<Vec3, Vec3> grain_box(const std::vector<Vec3>& position,
                                const std::vector<double>& radius, int dimension) {
  if (position.size() != radius.size())
    throw std::invalid_argument("grain_box: positions and radii differ in length");
  Vec3 lo = Vec3::Constant(std::numeric_limits<double>::infinity()), hi = -lo;
  for (std::size_t i = 0; i < position.size(); ++i) {
    lo = lo.cwiseMin(position[i] - Vec3::Constant(radius[i]));
    hi = hi.cwiseMax(position[i] + Vec3::Constant(radius[i]));
  }
  if (position.empty()) lo = hi = Vec3::Zero();
  if (dimension == 2) lo.z() = hi.z() = 0.0;
  return {lo, hi};
}

Rdf radial_distribution(const std::vector<Vec3>& position, const std::vector<double>& radius,
                        const RdfOptions& o) {
  if (o.dimension != 2 && o.dimension != 3) throw InputError("rdf: dimension must be 2 or 3");
  if (!(o.r_max > 0) || !std::isfinite(o.r_max))
    throw InputError(fmt::format("--rmax: expected a positive length, got {}", o.r_max));
  if (o.bins < 1) throw InputError(fmt::format("--bins: expected at least 1, got {}", o.bins));
  Rdf rdf;
  std::tie(rdf.lo, rdf.hi) = grain_box(position, radius, o.dimension);
  double volume = 1.0;
  for (int d = 0; d < o.dimension; ++d) volume *= rdf.hi[d] - rdf.lo[d];
  const std::size_t n = position.size();
  rdf.density = volume > 0 ? n / volume : 0.0;

  std::vector<std::size_t> reference;
  for (std::size_t i = 0; i < n; ++i) {
    bool inside = true;
    for (int d = 0; d < o.dimension; ++d)
      inside =
          inside && position[i][d] - rdf.lo[d] >= o.r_max && rdf.hi[d] - position[i][d] >= o.r_max;
    if (inside) reference.push_back(i);
  }
  if (reference.empty())
    throw InputError(fmt::format(
        "--rmax {} m is too large for this sample: no grain centre lies that far inside every face "
        "of the box the grains fill ({:.4g} x {:.4g}{} m)",
        o.r_max, rdf.hi.x() - rdf.lo.x(), rdf.hi.y() - rdf.lo.y(),
        o.dimension == 3 ? fmt::format(" x {:.4g}", rdf.hi.z() - rdf.lo.z()) : std::string()));
  rdf.reference_grains = reference.size();

  const double width = o.r_max / o.bins;
  std::vector<double> count(o.bins, 0.0);
  const CellList cells(position, o.r_max);
  for (std::size_t i : reference)
    cells.for_each_neighbour(i, [&](std::size_t, double dist) {
      // dist < r_max, so the bin is < bins except when rounding lands on the edge.
      const auto b = std::min(static_cast<int>(dist / width), o.bins - 1);
      count[b] += 1.0;
    });

  double cumulative = 0.0;
  for (int b = 0; b < o.bins; ++b) {
    const double r0 = b * width, r1 = (b + 1) * width;
    const double shell = o.dimension == 3 ? 4.0 / 3.0 * M_PI * (r1 * r1 * r1 - r0 * r0 * r0)
                                          : M_PI * (r1 * r1 - r0 * r0);
    const double refs = static_cast<double>(reference.size());
    cumulative += count[b] / refs;
    rdf.r.push_back(0.5 * (r0 + r1));
    rdf.g.push_back(count[b] / (refs * rdf.density * shell));
    rdf.coordination.push_back(cumulative);
  }
  return rdf;
}

}  // namespace talus::analysis
