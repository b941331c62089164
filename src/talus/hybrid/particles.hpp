#pragma once
// The particles of the hybrid method: each carries a fixed mass of the
// confined phase (structured solid with its confined fluid) at a horizontal
// position, its horizontal velocity, and the state of its Drucker-Prager
// material (mpm::MaterialState: stress, cohesion, plastic strain). Its areal
// density (mass per unit horizontal area) and depth follow each step from
// the kernel sum over its neighbours (SPH summation density), so a particle's
// count per cell is what encodes the flow depth (van den Bout et al. 2021
// §2.4.2). Structure of arrays: the force loops read positions and
// velocities of neighbours, never whole particles.
#include <cstddef>
#include <vector>

#include "talus/mpm/materials.hpp"

namespace talus::hybrid {

struct Particles {
  std::vector<double> x, y;   // m, horizontal
  std::vector<double> u, v;   // m/s, horizontal velocity
  std::vector<double> mass;   // kg, constant
  std::vector<double> areal;  // kg/m^2, sum_j m_j W_ij (each step)
  std::vector<double> depth;  // m, areal / rho_c (vertical)
  std::vector<mpm::MaterialState> state;

  std::size_t size() const { return x.size(); }
  void resize(std::size_t n) {
    x.resize(n);
    y.resize(n);
    u.resize(n);
    v.resize(n);
    mass.resize(n);
    areal.resize(n);
    depth.resize(n);
    state.resize(n);
  }
};

}  // namespace talus::hybrid
