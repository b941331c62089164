#include "talus/mpm/nonlocal.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>

namespace talus::mpm {

namespace {

// The 2^D lattice nodes around a point and their tent weights.
template <int D>
struct Corners {
  std::array<std::int64_t, 1 << D> node;
  std::array<double, 1 << D> w;
};

}  // namespace

template <int D>
void nonlocal_average(const Particles<D>& p, const std::vector<int>& list, double ell,
                      std::vector<double>& values, std::vector<double>& scratch) {
  using Vec = typename Space<D>::Vec;
  if (list.empty()) return;
  // Lattice over the points' bounding box, one node beyond on each side.
  Vec lo = p.x[list[0]], hi = lo;
  for (int i : list) {
    lo = lo.cwiseMin(p.x[i]);
    hi = hi.cwiseMax(p.x[i]);
  }
  std::array<std::int64_t, D> n{};
  std::int64_t nodes = 1;
  for (int d = 0; d < D; ++d) {
    lo[d] -= ell;
    n[d] = static_cast<std::int64_t>(std::floor((hi[d] - lo[d]) / ell)) + 2;
    nodes *= n[d];
  }
  auto corners = [&](const Vec& x) {
    Corners<D> c;
    std::array<std::int64_t, D> base{};
    std::array<double, D> frac{};
    for (int d = 0; d < D; ++d) {
      const double s = (x[d] - lo[d]) / ell;
      base[d] = std::clamp<std::int64_t>(static_cast<std::int64_t>(std::floor(s)), 0, n[d] - 2);
      frac[d] = s - static_cast<double>(base[d]);
    }
    for (int k = 0; k < (1 << D); ++k) {
      std::int64_t index = 0;
      double w = 1.0;
      for (int d = D - 1; d >= 0; --d) {
        const int up = (k >> d) & 1;
        index = index * n[d] + base[d] + up;
        w *= up ? frac[d] : 1.0 - frac[d];
      }
      c.node[k] = index;
      c.w[k] = w;
    }
    return c;
  };
  scratch.assign(2 * nodes, 0.0);  // volume, volume * value
  for (std::size_t k = 0; k < list.size(); ++k) {
    const int i = list[k];
    const auto c = corners(p.x[i]);
    for (int a = 0; a < (1 << D); ++a) {
      scratch[2 * c.node[a]] += c.w[a] * p.volume[i];
      scratch[2 * c.node[a] + 1] += c.w[a] * p.volume[i] * values[k];
    }
  }
  const auto count = static_cast<std::int64_t>(list.size());
#pragma omp parallel for schedule(static)
  for (std::int64_t k = 0; k < count; ++k) {
    const auto c = corners(p.x[list[k]]);
    double v = 0.0, w = 0.0;
    for (int a = 0; a < (1 << D); ++a) {
      const double vol = scratch[2 * c.node[a]];
      if (vol <= 0.0) continue;
      v += c.w[a] * scratch[2 * c.node[a] + 1] / vol;
      w += c.w[a];
    }
    values[k] = w > 0.0 ? v / w : values[k];
  }
}

template void nonlocal_average<2>(const Particles<2>&, const std::vector<int>&, double,
                                  std::vector<double>&, std::vector<double>&);
template void nonlocal_average<3>(const Particles<3>&, const std::vector<int>&, double,
                                  std::vector<double>&, std::vector<double>&);

}  // namespace talus::mpm
