#pragma once
// Initial packings: where the particles start before the DEM builder settles them under
// gravity with the real contact laws. Pure geometry: positions and radii, no forces, no solver.
//
// Radii: both generators draw radii uniform in [r_min, r_max] and then scale all of them by one
// common factor so that the target porosity (or solid fraction) holds exactly, as PFC's radius
// expansion does. When the count comes from the porosity (N = A(1-n)/(pi rbar^2)) that factor is
// sqrt(rbar^2/<r^2>) on average: 0.982 for r in [1, 2] mm, because rbar^2 < <r^2>.
#include <optional>
#include <vector>

#include "talus/core/space.hpp"

namespace talus::dem {

struct PackedParticle {
  Vec3 position;
  double radius;
};

// Where particles go. 2D: a simple polygon (either orientation; z ignored) or, when the polygon
// is empty, the rectangle box_min..box_max in x, y. 3D: the box or, when cylinder_radius > 0, the
// cylinder of that radius about the vertical axis through the centre of the box, from box_min.z to
// box_max.z (the triaxial sample inside its membrane), or, when shell_outer_radius > 0, the
// spherical shell shell_inner_radius < |x - c| < shell_outer_radius about the box centre c (the
// hollow sphere; the box must contain the outer sphere), or, when edge_radius > 0, the box with
// its edges and corners rounded by that radius (the inside of a rounded-box membrane).
struct Region {
  int dimension = 2;
  std::vector<Vec3> polygon;
  double cylinder_radius = 0.0;
  double shell_inner_radius = 0.0, shell_outer_radius = 0.0;
  double edge_radius = 0.0;
  Vec3 box_min = Vec3::Zero();
  Vec3 box_max = Vec3::Zero();

  double area_or_volume() const;
  // Centre inside and at least `margin` from the boundary.
  bool contains(const Vec3& p, double margin) const;
};

// PFC-style radius expansion: N radii (from the porosity when count is empty), random
// non-overlapping placement at reduced size, growth to the target porosity and relaxation of the
// overlaps by FIRE minimisation of a soft repulsive energy. Throws RunError when the overlaps
// cannot be relaxed below 0.5 % of r_min on average (the porosity is beyond jamming). Every
// returned particle satisfies region.contains(position, radius).
std::vector<PackedParticle> random_fill(const Region& region, double r_min, double r_max,
                                        double porosity, std::optional<int> count, unsigned seed);

// Lubachevsky-Stillinger style growth to a target solid fraction, strictly without overlaps.
// When relaxation can no longer remove the overlaps (jamming), returns the last overlap-free
// state, its packing fraction and jammed = true.
struct GrowResult {
  std::vector<PackedParticle> particles;
  double packing_fraction;
  bool jammed;
};
GrowResult grow_packing(const Region& region, double r_min, double r_max, double target_fraction,
                        int count, unsigned seed);

// Multiply all radii by (1 - shrink): Kuen shrinks by 3 % to remove the overlap stresses.
void shrink_radii(std::vector<PackedParticle>& particles, double shrink);

// 1 - (sum of particle areas or volumes) / (region area or volume).
double porosity(const Region& region, const std::vector<PackedParticle>& particles);

// N = A(1-n)/(pi rbar^2) in 2D, V(1-n)/((4/3) pi <r^3>) in 3D, rounded to the nearest integer.
int particle_count_for_porosity(const Region& region, double r_min, double r_max, double porosity);

// Kuen Table 5: 3D porosity -> relative density D -> 2D porosity.
double porosity_2d_from_3d(double n3d);

// Overlaps of a packing: particle pairs (r_i + r_j - d > 0) and boundary penetrations
// (r - distance to the boundary > 0, or the whole r + distance for a centre outside).
struct OverlapStats {
  double max_overlap = 0.0;   // largest pair overlap, m
  double mean_overlap = 0.0;  // mean over the overlapping pairs, m
  int overlapping_pairs = 0;
  double max_wall_penetration = 0.0;
};
OverlapStats overlap_stats(const Region& region, const std::vector<PackedParticle>& particles);

}  // namespace talus::dem
