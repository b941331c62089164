#pragma once
// Local packing fraction from the radical (Laguerre) Voronoi tessellation of the grains (Götz
// 2024 §5.3.7: "Partikelvolumen durch das Volumen seiner Voronoi-Zelle"): phi_i = V_i / V_cell,i.
// The radical tessellation splits the space between two grains at the plane of equal power
// |x - x_i|^2 - r_i^2, which for touching grains of any sizes is their tangent plane, so a large
// grain gets a larger cell than a small neighbour (the plain Voronoi cell would cut through
// the large grain). Cells are computed by voro++ inside the box the grains fill (min(x - r) to
// max(x + r) per axis). 2D (disks, z = 0): voro++ has no 2D part in Debian; the disks are put
// in a slab periodic in z, where every radical cell is the disk's 2D radical cell times the
// slab height, so the cell area is the cell volume / height.
#include <cstddef>
#include <vector>

#include "talus/core/space.hpp"

namespace talus::analysis {

struct LocalPacking {
  std::vector<double> cell_volume;     // m^3 (m^2 in 2D); NaN for a grain without a cell
  std::vector<double> solid_fraction;  // grain volume (area) / cell volume; NaN without a cell
  // A grain is at the boundary when its cell reaches the box (a face or a vertex lies on it),
  // or has no cell (a small grain deep inside a large one has an empty radical cell), or its
  // centre is closer than `margin` to a face of the box. The cells of boundary grains are cut
  // by the box, not by neighbours, so their phi says little: they are left out of the means.
  std::vector<char> boundary;
  Vec3 lo = Vec3::Zero(), hi = Vec3::Zero();  // the box
  std::size_t interior = 0;                   // grains not at the boundary
  double mean_interior = 0.0;                 // mean of phi_i over the interior grains (0 if none)
  double overall_interior = 0.0;  // sum of their grain volumes / sum of their cell volumes
  // The same over all grains with a cell (= grain volume / box volume when all have one).
  double overall_all = 0.0;
};

// margin >= 0 (m). Throws InputError for a bad dimension or margin, std::invalid_argument when
// the arrays differ in length or a radius is not positive.
LocalPacking voronoi_packing(const std::vector<Vec3>& position, const std::vector<double>& radius,
                             int dimension, double margin = 0.0);

}  // namespace talus::analysis
