#pragma once
// Metrics of the point cloud: the furthest point along +x (with half a point
// spacing added by the caller if wanted) and the highest point along -gravity.
#include "talus/mpm/solver.hpp"

namespace talus::mpm {

template <int D>
double front_x(const Particles<D>& p);
template <int D>
double top(const Particles<D>& p, const typename Space<D>::Vec& gravity);

}  // namespace talus::mpm
