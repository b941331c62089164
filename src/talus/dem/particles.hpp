#pragma once
// Particle state as a structure of arrays: the hot loops touch only the fields
// they need, and the layout vectorises.
#include <algorithm>
#include <cstdint>
#include <vector>

#include "talus/core/space.hpp"

namespace talus::dem {

template <int D>
struct Particles {
  using Vec = typename Space<D>::Vec;
  using Rot = typename Space<D>::Rot;

  std::vector<Vec> x, v, f;  // position, velocity, force
  std::vector<Rot> w, t;     // angular velocity, torque
  std::vector<double> r, inv_m, inv_I, m;
  std::vector<int> material;
  std::vector<int64_t> id;         // stable across re-sorting and removal
  std::vector<int> contacts;       // particle-particle contacts in the last step
  std::vector<int> wall_contacts;  // particle-wall contacts in the last step

  std::size_t size() const { return x.size(); }

  void add(const Vec& pos, const Vec& vel, const Rot& omega, double radius, double density, int mat,
           int64_t ident) {
    const double mass = density * Space<D>::volume(radius);
    x.push_back(pos);
    v.push_back(vel);
    f.push_back(Vec::Zero());
    w.push_back(omega);
    t.push_back(Space<D>::rot_zero());
    r.push_back(radius);
    m.push_back(mass);
    inv_m.push_back(1.0 / mass);
    inv_I.push_back(1.0 / (Space<D>::inertia_factor() * mass * radius * radius));
    material.push_back(mat);
    id.push_back(ident);
    contacts.push_back(0);
    wall_contacts.push_back(0);
  }

  // Reorders every field: new index k holds old index order[k]. The fields
  // are OpenMP tasks: inside a parallel region (the neighbour build runs in
  // `omp single`) the other threads take some.
  void permute(const std::vector<int>& order) {
    apply(order, x);
    apply(order, v);
    apply(order, f);
    apply(order, w);
    apply(order, t);
    apply(order, r);
    apply(order, inv_m);
    apply(order, inv_I);
    apply(order, m);
    apply(order, material);
    apply(order, id);
    apply(order, contacts);
    apply(order, wall_contacts);
#pragma omp taskwait
  }

 private:
  template <class T>
  static void apply(const std::vector<int>& order, std::vector<T>& a) {
#pragma omp task default(shared)
    {
      std::vector<T> out(order.size());
      for (std::size_t k = 0; k < order.size(); ++k) out[k] = a[order[k]];
      // Back into the same storage (a shorter order only shrinks it): the
      // Python API's views of the arrays keep their address across re-sorts.
      std::copy(out.begin(), out.end(), a.begin());
      a.resize(out.size());
    }
  }
};

}  // namespace talus::dem
