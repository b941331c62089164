#include "talus/mpm/metrics.hpp"

#include <algorithm>

namespace talus::mpm {

template <int D>
double front_x(const Particles<D>& p) {
  double x = -1e300;
  for (const auto& xi : p.x) x = std::max(x, xi[0]);
  return x;
}

template <int D>
double top(const Particles<D>& p, const typename Space<D>::Vec& gravity) {
  const double g = gravity.norm();
  const auto up = g > 0 ? (-gravity / g).eval() : Space<D>::Vec::Unit(D - 1).eval();
  double t = -1e300;
  for (const auto& xi : p.x) t = std::max(t, up.dot(xi));
  return t;
}

template double front_x<2>(const Particles<2>&);
template double front_x<3>(const Particles<3>&);
template double top<2>(const Particles<2>&, const Space<2>::Vec&);
template double top<3>(const Particles<3>&, const Space<3>::Vec&);

}  // namespace talus::mpm
