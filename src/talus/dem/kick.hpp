#pragma once
// The half kick of velocity Verlet, with PFC's optional local damping: shared
// by the CPU stepper and the GPU backend (dem_gpu/), which call it on their
// own particle arrays (any type with the Particles field names).
#include <cmath>

#include "talus/core/space.hpp"

namespace talus::dem {

template <int D>
struct Kick {
  typename Space<D>::Vec g;
  double h, alpha;
  bool rotate;  // false: Kuen's Model 1 keeps omega at zero
};

TALUS_HOT double kick_sign(double x) { return x > 0.0 ? 1.0 : (x < 0.0 ? -1.0 : 0.0); }

template <int D, class P>
TALUS_HOT void kick_one(P& p, int i, const Kick<D>& k) {
  using Vec = typename Space<D>::Vec;
  using Rot = typename Space<D>::Rot;
  Vec f = p.f[i] + p.m[i] * k.g;
  Rot t = p.t[i];
  if (k.alpha > 0.0) {
    for (int d = 0; d < D; ++d) f[d] -= k.alpha * std::abs(f[d]) * kick_sign(p.v[i][d]);
    if constexpr (D == 2) {
      t -= k.alpha * std::abs(t) * kick_sign(p.w[i]);
    } else {
      for (int d = 0; d < 3; ++d) t[d] -= k.alpha * std::abs(t[d]) * kick_sign(p.w[i][d]);
    }
  }
  p.v[i] += (k.h * p.inv_m[i]) * f;
  if (k.rotate) p.w[i] += (k.h * p.inv_I[i]) * t;
}

}  // namespace talus::dem
