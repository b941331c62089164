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

// Spatial autocorrelation of D_min (Götz 2024 §5.3.6, eqs. 48-49), as written there:
//     C_i(r) = (1/M_i) sum_j D_min,i D_min,j / d_mean   over the M_i grains j with
//              |x_i - x_j| = r +- dr,
//     C(r)   = mean of C_i(r) over the grains i.
// D_min = min |D| of eq. 47, where D^2 is the mean over the neighbours, i.e. D_min =
// sqrt(D^2_min / n_i) = d_min_norm * d_mean of D2min above (a length); d_mean is the mean grain
// diameter (d_mittel). C is then a length; the source plots C(r)/C(0), where d_mean cancels.
// Choices where the source is silent:
//  - Bins [k w, (k + 1) w), k = 0 .. ceil(r_max / w) - 1, reported at their centre (k + 1/2) w:
//    r +- dr with dr = w/2, the binning of the g(r) above.
//  - C(0) is the r -> 0 limit, where the only grain at distance 0 +- dr is i itself:
//    C_i(0) = D_min,i^2 / d_mean, so C(0) = mean over i of D_min,i^2 / d_mean. (A pair closer
//    than w falls in the first bin, not in C(0).)
//  - The mean over i in eq. 49 takes only the grains that have at least one partner in the bin
//    (C_i is undefined for M_i = 0; counting such grains as 0 would make C(r) fall off at the
//    sample's edge for no physical reason).
//  - Grains without a value (NaN: left out of D2min, e.g. fewer than 3 contacts) are neither i
//    nor j, as the source leaves them out of the analysis.
struct D2minCorrelationOptions {
  int dimension = 3;       // 2: distances in the x-y plane only
  double bin_width = 0.0;  // w = 2 dr, > 0
  double r_max = 0.0;      // > 0; rounded up to a whole number of bins (at most 10^6)
};

struct D2minCorrelation {
  std::vector<double> r;            // bin centres (k + 1/2) w
  std::vector<double> c;            // C(r), m; NaN in a bin without pairs
  std::vector<double> c_over_c0;    // C(r) / C(0); NaN without pairs or when C(0) = 0
  std::vector<std::size_t> grains;  // grains i with M_i > 0 in the bin (the N of eq. 49)
  std::vector<std::size_t> pairs;   // pairs {i, j} in the bin (each counted once)
  double c0 = 0.0;                  // C(0), m
  std::size_t valued = 0;           // grains with a D_min value (the N of C(0))
};

// position and d_min have one entry per grain (d_min in m, NaN = no value); mean_diameter is
// d_mean (> 0). Pairs by the cell list of the g(r) and D2min (O(N log N + pairs)). Throws
// InputError for a bad bin width, r_max or dimension, std::invalid_argument when the arrays
// differ in length.
D2minCorrelation d2min_correlation(const std::vector<Vec3>& position,
                                   const std::vector<double>& d_min, double mean_diameter,
                                   const D2minCorrelationOptions& options);

}  // namespace talus::analysis
