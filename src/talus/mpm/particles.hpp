#pragma once
// Material points: mass, volume, velocity and the constitutive state, stored
// as arrays (one entry per point, all of the same length).
#include <cstdint>
#include <vector>

#include "talus/core/space.hpp"
#include "talus/mpm/materials.hpp"

namespace talus::mpm {

template <int D>
struct Particles {
  using Vec = typename Space<D>::Vec;
  using Mat = Eigen::Matrix<double, D, D>;

  std::vector<Vec> x, v;
  std::vector<double> mass, volume, volume0;  // volume per metre of depth in 2D
  std::vector<MaterialState> state;
  std::vector<Mat3> velocity_gradient;  // of the last step, 3x3 (plane strain in 2D)
  std::vector<int> material;            // index into the solver's materials
  // APIC affine matrix B_p (Jiang et al. 2015), zero unless the APIC transfer runs.
  std::vector<Mat> affine;

  std::size_t size() const { return x.size(); }

  void add(const Vec& position, const Vec& velocity, double m, double vol, int mat,
           const MaterialState& s) {
    x.push_back(position);
    v.push_back(velocity);
    mass.push_back(m);
    volume.push_back(vol);
    volume0.push_back(vol);
    state.push_back(s);
    velocity_gradient.push_back(Mat3::Zero());
    material.push_back(mat);
    affine.push_back(Mat::Zero());
  }
};

template <int D>
double kinetic_energy(const Particles<D>& p) {
  double e = 0.0;
  for (std::size_t i = 0; i < p.size(); ++i) e += 0.5 * p.mass[i] * p.v[i].squaredNorm();
  return e;
}

// Potential energy m g.(x0 - x) relative to the origin, for gravity g.
template <int D>
double potential_energy(const Particles<D>& p, const typename Space<D>::Vec& gravity) {
  double e = 0.0;
  for (std::size_t i = 0; i < p.size(); ++i) e -= p.mass[i] * gravity.dot(p.x[i]);
  return e;
}

template <int D>
typename Space<D>::Vec centre_of_mass_velocity(const Particles<D>& p) {
  typename Space<D>::Vec mv = Space<D>::Vec::Zero();
  double m = 0.0;
  for (std::size_t i = 0; i < p.size(); ++i) {
    mv += p.mass[i] * p.v[i];
    m += p.mass[i];
  }
  return m > 0.0 ? (mv / m).eval() : mv;
}

}  // namespace talus::mpm
