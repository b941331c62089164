#pragma once
// Radial distribution function g(r) of the grain centres of one snapshot, normalised so that an
// uncorrelated (ideal-gas) arrangement gives g = 1:
//     g(r_b) = n_b / (N_ref rho V_b),
// n_b the number of (reference grain, other grain) pairs whose centre distance falls in bin b,
// V_b the volume of the spherical shell of bin b (the area of the ring in 2D), rho = N / V_box.
// The edge of a finite sample: V_box is the box the grains fill (from min(x - r) to max(x + r)
// per axis), and only grains whose centre lies at least r_max inside every face of that box are
// reference grains, so every shell around a reference grain lies inside the box and is not cut
// by the sample's edge. (Götz 2024 eq. 42 counts the grains whose body cuts the sphere around a
// grain and divides by 4 pi (r / R_mean)^2 only, which does not tend to 1; this is the
// standard definition that it approximates.) Pure geometry: no files, no solver.
#include <cstddef>
#include <vector>

#include "talus/core/space.hpp"

namespace talus::analysis {

struct RdfOptions {
  int dimension = 3;   // 2: disks in the x-y plane (z ignored), 3: spheres
  double r_max = 0.0;  // > 0
  int bins = 100;      // >= 1, of equal width r_max / bins
};

struct Rdf {
  std::vector<double> r;             // bin centres
  std::vector<double> g;             // g(r) of each bin
  std::vector<double> coordination;  // mean number of other centres within the bin's outer edge
  std::size_t reference_grains = 0;
  double density = 0.0;                       // rho = N / V_box, grains per m^3 (per m^2 in 2D)
  Vec3 lo = Vec3::Zero(), hi = Vec3::Zero();  // the box
};

// Throws InputError when r_max or bins are out of range or no grain is r_max inside the box
// (r_max too large for the sample); std::invalid_argument when the arrays differ in length.
Rdf radial_distribution(const std::vector<Vec3>& position, const std::vector<double>& radius,
                        const RdfOptions& options);

// Box the grains fill: min(x - r), max(x + r) per axis (z = 0 on both sides in 2D).
std::pair<Vec3, Vec3> grain_box(const std::vector<Vec3>& position,
                                const std::vector<double>& radius, int dimension);

}  // namespace talus::analysis
