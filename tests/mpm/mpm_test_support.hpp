#pragma once
// Small helpers the MPM tests share: one OpenMP thread for a test's scope
// (a few hundred to a few thousand points: threads only cost there), the
// least-squares slope of a sampled speed, a body's centre of mass, and the
// elastic block material of the contact tests.
#include <omp.h>

#include <cstddef>
#include <string>

#include "talus/mpm/materials.hpp"

namespace talus::mpm {

struct OneThread {
  int before = omp_get_max_threads();
  OneThread() { omp_set_num_threads(1); }
  ~OneThread() { omp_set_num_threads(before); }
};

// Least-squares slope of v against t (an acceleration from sampled speeds).
struct Fit {
  double st = 0, sv = 0, stt = 0, stv = 0;
  int n = 0;
  void add(double t, double v) { st += t, sv += v, stt += t * t, stv += t * v, ++n; }
  double slope() const { return (n * stv - st * sv) / (n * stt - st * st); }
};

// Coordinate d of the points' centre of mass.
template <class Points>
double centre_of_mass(const Points& p, int d) {
  double mx = 0.0, m = 0.0;
  for (std::size_t i = 0; i < p.size(); ++i) {
    mx += p.mass[i] * p.x[i][d];
    m += p.mass[i];
  }
  return mx / m;
}

inline MaterialParams elastic_material(const std::string& name, double density, double youngs,
                                       double poisson) {
  MaterialParams m;
  m.name = name;
  m.model = LinearElastic::name;
  m.density = density;
  m.youngs_modulus = youngs;
  m.poisson_ratio = poisson;
  return m;
}

}  // namespace talus::mpm
