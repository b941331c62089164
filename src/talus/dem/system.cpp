#include "talus/dem/system.hpp"

#include <algorithm>

namespace talus::dem {

template <int D>
int DemSystem<D>::material_index(const std::string& name) const {
  for (std::size_t k = 0; k < materials.size(); ++k)
    if (materials[k].name == name) return static_cast<int>(k);
  return -1;
}

template <int D>
double kinetic_energy(const Particles<D>& p) {
  double e = 0.0;
  for (std::size_t i = 0; i < p.size(); ++i) e += 0.5 * p.m[i] * p.v[i].squaredNorm();
  return e;
}

template <int D>
double rotational_energy(const Particles<D>& p) {
  double e = 0.0;
  for (std::size_t i = 0; i < p.size(); ++i)
    e += 0.5 / p.inv_I[i] * Space<D>::rot_dot(p.w[i], p.w[i]);
  return e;
}

template <int D>
double potential_energy(const Particles<D>& p, const typename Space<D>::Vec& g) {
  double e = 0.0;
  for (std::size_t i = 0; i < p.size(); ++i) e -= p.m[i] * g.dot(p.x[i]);
  return e;
}

template <int D>
double front_x(const Particles<D>& p) {
  double m = p.size() ? p.x[0][0] : 0.0;
  for (const auto& x : p.x) m = std::max(m, x[0]);
  return m;
}

template <int D>
double top(const Particles<D>& p) {
  double m = p.size() ? p.x[0][D - 1] : 0.0;
  for (const auto& x : p.x) m = std::max(m, x[D - 1]);
  return m;
}

template double front_x<2>(const Particles<2>&);
template double front_x<3>(const Particles<3>&);
template double top<2>(const Particles<2>&);
template double top<3>(const Particles<3>&);
template struct DemSystem<2>;
template struct DemSystem<3>;
template double kinetic_energy<2>(const Particles<2>&);
template double kinetic_energy<3>(const Particles<3>&);
template double rotational_energy<2>(const Particles<2>&);
template double rotational_energy<3>(const Particles<3>&);
template double potential_energy<2>(const Particles<2>&, const Space<2>::Vec&);
template double potential_energy<3>(const Particles<3>&, const Space<3>::Vec&);

}  // namespace talus::dem
