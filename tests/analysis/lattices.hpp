#pragma once
// Lattices of touching grains for the structure analyses' tests (positions and radii).
#include <cmath>
#include <vector>

#include "talus/core/space.hpp"

namespace talus::analysis::test {

struct Lattice {
  std::vector<Vec3> position;
  std::vector<double> radius;
};

// n^3 spheres on a simple cubic lattice of spacing a, radius a/2 (touching); origin at 0.
inline Lattice simple_cubic(int n, double a) {
  Lattice l;
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j)
      for (int k = 0; k < n; ++k) l.position.push_back(a * Vec3(i, j, k));
  l.radius.assign(l.position.size(), 0.5 * a);
  return l;
}

// n^3 conventional cubic cells (4 spheres each) of an FCC lattice with cube side a; nearest
// neighbours a / sqrt(2) apart, radius a / (2 sqrt 2) (touching).
inline Lattice fcc(int n, double a) {
  const Vec3 basis[4] = {{0, 0, 0}, {0.5, 0.5, 0}, {0.5, 0, 0.5}, {0, 0.5, 0.5}};
  Lattice l;
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j)
      for (int k = 0; k < n; ++k)
        for (const Vec3& b : basis) l.position.push_back(a * (Vec3(i, j, k) + b));
  l.radius.assign(l.position.size(), a / (2 * std::sqrt(2.0)));
  return l;
}

// 2D: n x n disks on a square lattice of spacing a (z = 0), radius a/2.
inline Lattice square(int n, double a) {
  Lattice l;
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) l.position.push_back(a * Vec3(i, j, 0));
  l.radius.assign(l.position.size(), 0.5 * a);
  return l;
}

// 2D: rows of n disks spacing a, rows sqrt(3)/2 a apart and shifted by a/2 every other row
// (hexagonal, each disk touches six), radius a/2.
inline Lattice hexagonal(int n, int rows, double a) {
  Lattice l;
  for (int r = 0; r < rows; ++r)
    for (int i = 0; i < n; ++i)
      l.position.push_back(a * Vec3(i + 0.5 * (r % 2), r * std::sqrt(3.0) / 2, 0));
  l.radius.assign(l.position.size(), 0.5 * a);
  return l;
}

}  // namespace talus::analysis::test
