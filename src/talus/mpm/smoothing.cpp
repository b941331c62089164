#include "talus/mpm/smoothing.hpp"

#include <algorithm>
#include <cmath>

namespace talus::mpm {

namespace {

// Cell of a point on the node lattice (cell k lies between nodes k and k + 1).
template <int D>
std::int64_t cell_of(const Grid<D>& g, const typename Space<D>::Vec& x) {
  std::int64_t c = 0;
  for (int d = D - 1; d >= 0; --d) {
    const int i =
        std::clamp(static_cast<int>(std::floor((x[d] - g.origin[d]) / g.h)), 0, g.n[d] - 2);
    c = c * (g.n[d] - 1) + i;
  }
  return c;
}

}  // namespace

template <int D>
void smooth_volumetric_strain(const Grid<D>& grid, Particles<D>& p, std::vector<double>& sums) {
  std::int64_t cells = 1;
  for (int d = 0; d < D; ++d) cells *= grid.n[d] - 1;
  sums.assign(2 * cells, 0.0);  // volume, volume * tr(L)
  const std::size_t n = p.size();
  std::vector<std::int64_t> cell(n);
  // Serial sums in point order: the same bits for any number of threads.
  for (std::size_t i = 0; i < n; ++i) {
    cell[i] = cell_of(grid, p.x[i]);
    sums[2 * cell[i]] += p.volume[i];
    sums[2 * cell[i] + 1] += p.volume[i] * p.velocity_gradient[i].trace();
  }
  const auto count = static_cast<std::int64_t>(n);
#pragma omp parallel for schedule(static)
  for (std::int64_t i = 0; i < count; ++i) {
    const std::int64_t c = cell[i];
    const double mean = sums[2 * c + 1] / sums[2 * c];
    Mat3& l = p.velocity_gradient[i];
    const double shift = (mean - l.trace()) / D;
    for (int d = 0; d < D; ++d) l(d, d) += shift;
  }
}

template void smooth_volumetric_strain<2>(const Grid<2>&, Particles<2>&, std::vector<double>&);
template void smooth_volumetric_strain<3>(const Grid<3>&, Particles<3>&, std::vector<double>&);

}  // namespace talus::mpm
