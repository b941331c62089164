#pragma once
// Coarse-graining of particle data onto a grid of boxes (Götz 2024, appendix C): the density
// of a particle quantity G in cell a is
//     j_a = sum_i G_i V_{i∩a} / (V_i V_a),
// with V_{i∩a} the exact volume of the intersection of sphere i and cell a. With G_i = m_i this
// is the mass density; with G_i = m_i (r_i(t1) - r_i(t0)) / (t1 - t0) the momentum density, and
// their ratio the mean velocity over [t0, t1] (one vibration period in the convection runs).
// Pure geometry on positions, radii and densities: no files, no solver.
#include <array>
#include <vector>

#include "talus/core/space.hpp"

namespace talus::analysis {

// Exact volume of the intersection of the ball |x - centre| < radius and the box [lo, hi]
// (lo <= hi componentwise). Analytic: inclusion-exclusion over the box's 8 corners of the
// volume of the ball beyond three orthogonal planes, each in closed form (asin, atan).
double sphere_box_overlap(const Vec3& centre, double radius, const Vec3& lo, const Vec3& hi);

// Volume of the ball (centre 0) beyond three orthogonal planes: {x > a, y > b, z > c}.
double sphere_orthant_volume(double radius, double a, double b, double c);

// A regular grid of nx x ny x nz boxes covering [lo, hi]; cell (i, j, k) has the flat index
// i + nx (j + ny k).
struct CellGrid {
  Vec3 lo = Vec3::Zero(), hi = Vec3::Zero();
  std::array<int, 3> cells{1, 1, 1};

  Vec3 spacing() const;
  double cell_volume() const;
  std::size_t size() const;
  std::size_t index(int i, int j, int k) const;
  Vec3 cell_lo(int i, int j, int k) const;
  Vec3 cell_centre(int i, int j, int k) const;
};

// One state of the particles (any order; the sampler matches them by id).
struct ParticleSample {
  double time = 0.0;
  std::vector<long long> id;
  std::vector<Vec3> position;
  std::vector<double> radius;
  std::vector<double> density;  // kg/m^3 of each particle's material
};

// Sums of the densities over the intervals added so far; the fields are their means.
struct CoarseField {
  CellGrid grid;
  int intervals = 0;
  std::vector<double> solid_fraction;  // sum_i V_{i∩a} / V_a
  std::vector<double> mass_density;    // kg/m^3
  std::vector<Vec3> momentum_density;  // kg/(m^2 s)
  // Mean velocity j_p / rho (zero where there is no mass).
  std::vector<Vec3> velocity() const;
};

// Averages j_a over intervals [t0, t1]: the mass density of the particles at t0 and the
// momentum density of their mean velocities (r(t1) - r(t0)) / (t1 - t0), both coarse-grained
// at the positions of t0 (overlap-free states, so the solid fraction stays below 1).
class CoarseGrainer {
 public:
  explicit CoarseGrainer(const CellGrid& grid);
  // Particles present in both samples (matched by id) count; returns how many did.
  // Throws InputError when t1 <= t0 or a sample's arrays differ in length.
  int add_interval(const ParticleSample& first, const ParticleSample& second);
  const CoarseField& field() const { return field_; }
  CoarseField mean() const;

 private:
  void deposit(const Vec3& x, double r, double rho, const Vec3& v);
  CoarseField field_;
};

// Azimuthal average about the vertical line through `axis` (x, y): cells binned by the
// distance of their centres from it into `rings` rings of width `ring_width`, per z layer of the
// grid; velocities as mass-weighted means of (v_r, v_z). Row-major: ring + rings * k.
struct RadialField {
  int rings = 0, layers = 0;
  double ring_width = 0.0;
  std::vector<double> r, z, solid_fraction, v_r, v_z;
};
RadialField azimuthal_average(const CoarseField& mean, const Vec3& axis, int rings,
                              double ring_width);

}  // namespace talus::analysis
