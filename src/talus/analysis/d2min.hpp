#pragma once
// Non-affine displacement D^2_min (Falk & Langer 1998; Götz 2024 §5.3.6, eq. 47) of each grain
// between a reference state x0 and a later state x1 of the same grains. The neighbours of grain
// i are the grains j within `cutoff` of it in the reference state; with d_j = x_j - x_i,
//     D^2_min(i) = min over J of sum_j |d_j(t1) - J d_j(t0)|^2,
// J the best local affine map (J = 1 + epsilon of the source), found by linear least squares
// (Eigen's column-pivoting QR, so degenerate neighbourhoods still give the minimum). It is zero
// for any homogeneous deformation (stretch, shear, rotation, translation).
// Two forms are returned: the Falk-Langer sum (m^2), and the source's D_min / d_mean =
// sqrt(D^2_min / n_i) / d_mean, with n_i the neighbour count (eq. 47 averages over them) and
// d_mean the mean grain diameter. Pure geometry: no files, no solver.
#include <cstddef>
#include <vector>

#include "talus/core/space.hpp"

namespace talus::analysis {

struct D2minOptions {
  int dimension = 3;    // 2: x-y components only
  double cutoff = 0.0;  // > 0, neighbourhood radius in the reference state
};

struct D2min {
  // Per grain; NaN for a grain left out (not `included`, or fewer than D + 1 neighbours, or
  // neighbours that do not span the space: J is then not determined by them).
  std::vector<double> d2min;       // Falk-Langer sum, m^2
  std::vector<double> d_min_norm;  // sqrt(d2min / neighbours) / d_mean
  std::vector<int> neighbours;     // n_i (included neighbours within the cutoff at t0)
  std::size_t evaluated = 0;       // grains with a value
  double mean_d2min = 0.0;         // means over the evaluated grains (0 if none)
  double mean_d_min_norm = 0.0;
  double mean_diameter = 0.0;  // d_mean of all grains
};

// x0, x1 and radius have one entry per grain, in the same order. `included` (optional, empty =
// all): grains left out are neither evaluated nor neighbours (e.g. rattlers with too few
// contacts, which Götz leaves out). Throws InputError for a bad cutoff or dimension and
// std::invalid_argument when the arrays differ in length.
D2min non_affine_displacement(const std::vector<Vec3>& x0, const std::vector<Vec3>& x1,
                              const std::vector<double>& radius, const D2minOptions& options,
                              const std::vector<char>& included = {});

}  // namespace talus::analysis
