// Coarse-graining (Götz 2024 appendix C): exact sphere-box overlap volumes, densities and the
// velocity field from displacements.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numeric>
#include <random>

#include "talus/analysis/coarse_grain.hpp"
#include "talus/core/error.hpp"
#include "talus/dem/packing.hpp"

namespace talus::analysis {
namespace {

constexpr double kPi = M_PI;
double ball(double r) { return 4.0 / 3.0 * kPi * r * r * r; }

// An independent reference: the slice of the ball at height z is a disc of radius rho; its area
// inside [x0, x1] x [y0, y1] is the integral over x of the chord length clipped to [y0, y1].
// Both integrals by composite Gauss-Legendre after x = rho sin(t), z = R sin(t) (no square-root
// ends), split at every kink of the integrand, so they converge fast: ~1e-12 of R^3.
template <class F>
double gauss(double a, double b, const std::vector<double>& kinks, int pieces, F f) {
  static const double g[5] = {-0.9061798459386640, -0.5384693101056831, 0.0, 0.5384693101056831,
                              0.9061798459386640};
  static const double w[5] = {0.2369268850561891, 0.4786286704993665, 0.5688888888888889,
                              0.4786286704993665, 0.2369268850561891};
  std::vector<double> cuts{a, b};
  for (double k : kinks)
    if (k > a && k < b) cuts.push_back(k);
  std::sort(cuts.begin(), cuts.end());
  double sum = 0.0;
  for (std::size_t c = 0; c + 1 < cuts.size(); ++c)
    for (int p = 0; p < pieces; ++p) {
      const double lo = cuts[c] + (cuts[c + 1] - cuts[c]) * p / pieces;
      const double hi = cuts[c] + (cuts[c + 1] - cuts[c]) * (p + 1) / pieces;
      for (int q = 0; q < 5; ++q)
        sum += 0.5 * (hi - lo) * w[q] * f(0.5 * (lo + hi + (hi - lo) * g[q]));
    }
  return sum;
}

double chord_area(double rho, double x0, double x1, double y0, double y1) {
  x0 = std::max(x0, -rho), x1 = std::min(x1, rho);
  if (x1 <= x0) return 0.0;
  std::vector<double> kinks;  // where the chord end +-s crosses y0 or y1
  for (double y : {y0, y1})
    if (std::abs(y) < rho) {
      const double t = std::acos(std::abs(y) / rho);
      kinks.push_back(t), kinks.push_back(-t);
    }
  return gauss(std::asin(x0 / rho), std::asin(x1 / rho), kinks, 20, [&](double t) {
    const double s = rho * std::cos(t);
    return std::max(0.0, std::min(s, y1) - std::max(-s, y0)) * rho * std::cos(t);
  });
}

double reference_overlap(double R, const Vec3& lo, const Vec3& hi) {
  const double z0 = std::max(lo.z(), -R), z1 = std::min(hi.z(), R);
  if (z1 <= z0) return 0.0;
  std::vector<double> kinks;  // heights where the slice's circle meets an edge or a corner
  for (double x : {lo.x(), hi.x(), lo.y(), hi.y()})
    for (double y : {0.0, lo.x(), hi.x(), lo.y(), hi.y()}) {
      const double rho = std::hypot(x, y);
      if (rho < R) {
        const double t = std::acos(rho / R);
        kinks.push_back(t), kinks.push_back(-t);
      }
    }
  return gauss(std::asin(z0 / R), std::asin(z1 / R), kinks, 20, [&](double t) {
    const double rho = R * std::cos(t);
    return chord_area(rho, lo.x(), hi.x(), lo.y(), hi.y()) * rho;
  });
}

TEST(SphereBoxOverlap, KnownFractions) {
  const double R = 0.7e-3;
  const Vec3 c(0.01, -0.02, 0.03);
  const double V = ball(R), big = 1.0;
  // Wholly inside: the ball's volume (4/3) pi R^3.
  EXPECT_NEAR(sphere_box_overlap(c, R, c - Vec3::Constant(big), c + Vec3::Constant(big)), V,
              1e-14 * V);
  // Centre on a face, an edge, a corner of the box: 1/2, 1/4, 1/8 of the ball by symmetry.
  EXPECT_NEAR(sphere_box_overlap(c, R, c - Vec3(0, big, big), c + Vec3::Constant(big)), V / 2,
              1e-13 * V);
  EXPECT_NEAR(sphere_box_overlap(c, R, c - Vec3(0, 0, big), c + Vec3::Constant(big)), V / 4,
              1e-13 * V);
  EXPECT_NEAR(sphere_box_overlap(c, R, c, c + Vec3::Constant(big)), V / 8, 1e-13 * V);
  EXPECT_NEAR(sphere_box_overlap(c, R, c - Vec3::Constant(big), c), V / 8, 1e-13 * V);
  // Disjoint: nothing; touching: nothing up to the round-off of c + R - c in the coordinates.
  EXPECT_EQ(sphere_box_overlap(c, R, c + Vec3(1.01 * R, -big, -big), c + Vec3::Constant(big)),
            0.0);
  EXPECT_NEAR(sphere_box_overlap(c, R, c + Vec3(R, -big, -big), c + Vec3::Constant(big)), 0.0,
              1e-15 * V);
}

TEST(SphereBoxOverlap, CapsAndLenses) {
  const double R = 1.0;
  // A cap of height h: pi h^2 (3R - h) / 3.
  for (double h : {1e-3, 0.1, 0.5, 1.0, 1.7}) {
    const double cap = kPi * h * h * (3 * R - h) / 3;
    EXPECT_NEAR(sphere_box_overlap(Vec3::Zero(), R, Vec3(R - h, -2, -2), Vec3(2, 2, 2)), cap, 1e-14)
        << h;
  }
  // A slab |z| < a through the centre: V - 2 caps of height R - a.
  const double a = 0.3, h = R - a;
  EXPECT_NEAR(sphere_box_overlap(Vec3::Zero(), R, Vec3(-2, -2, -a), Vec3(2, 2, a)),
              ball(R) - 2 * kPi * h * h * (3 * R - h) / 3, 1e-14);
  // Half a cap (cap cut by a plane through the axis): by symmetry half the cap.
  EXPECT_NEAR(sphere_box_overlap(Vec3::Zero(), R, Vec3(0.4, 0, -2), Vec3(2, 2, 2)),
              0.5 * kPi * 0.36 * (3 - 0.6) / 3, 1e-14);
}

TEST(SphereBoxOverlap, GeneralBoxesMatchNumericalIntegration) {
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> u(-1.3, 1.3), s(0.05, 1.5);
  for (int trial = 0; trial < 40; ++trial) {
    const Vec3 lo(u(rng), u(rng), u(rng));
    const Vec3 hi = lo + Vec3(s(rng), s(rng), s(rng));
    // The reference agrees to 2e-12 on these boxes; 1e-10 leaves room for other compilers.
    EXPECT_NEAR(sphere_box_overlap(Vec3::Zero(), 1.0, lo, hi), reference_overlap(1.0, lo, hi),
                1e-10)
        << "box " << lo.transpose() << " / " << hi.transpose();
  }
}

TEST(SphereBoxOverlap, GridSumsToTheBallVolume) {
  // The cells of a grid partition space: the overlaps sum to the ball (inclusion-exclusion
  // telescopes, and each term is accurate), to round-off.
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> u(-0.5, 0.5);
  for (double h : {0.13, 0.4, 0.77, 2.5}) {
    const Vec3 c(u(rng), u(rng), u(rng));
    double sum = 0.0;
    const int n = static_cast<int>(std::ceil(2.0 / h)) + 1;
    for (int i = -n; i < n; ++i)
      for (int j = -n; j < n; ++j)
        for (int k = -n; k < n; ++k) {
          const Vec3 lo = h * Vec3(i, j, k);
          sum += sphere_box_overlap(c, 1.0, lo, lo + Vec3::Constant(h));
        }
    EXPECT_NEAR(sum, ball(1.0), 1e-13) << "cell size " << h;
  }
}

std::vector<dem::PackedParticle> box_packing(const dem::Region& region) {
  // Radii as the convection grains (0.665-0.735 mm), 0.45 solid fraction.
  return dem::grow_packing(region, 0.665e-3, 0.735e-3, 0.45, 1200, 3).particles;
}

ParticleSample sample_of(const std::vector<dem::PackedParticle>& packed, double time) {
  ParticleSample s;
  s.time = time;
  for (std::size_t n = 0; n < packed.size(); ++n) {
    s.id.push_back(static_cast<long long>(n));
    s.position.push_back(packed[n].position);
    s.radius.push_back(packed[n].radius);
    s.density.push_back(2000.0);
  }
  return s;
}

TEST(CoarseGrainer, RandomPackingDensityIsItsSolidFraction) {
  dem::Region region;
  region.dimension = 3;
  region.box_max = Vec3(0.02, 0.02, 0.02);
  const auto packed = box_packing(region);
  const ParticleSample s = sample_of(packed, 0.0);
  CellGrid grid;
  grid.hi = region.box_max;
  grid.cells = {5, 5, 5};
  CoarseGrainer cg(grid);
  cg.add_interval(s, sample_of(packed, 1.0));
  const CoarseField f = cg.mean();
  double solid = 0.0;
  for (double r : s.radius) solid += ball(r);
  const double phi = solid / region.area_or_volume();
  // Every grain lies wholly inside the grid, so the cells share out exactly its volume:
  // the mean over all cells is the packing's solid fraction to round-off, and the mass density
  // is rho times it.
  const double mean_all =
      std::accumulate(f.solid_fraction.begin(), f.solid_fraction.end(), 0.0) / grid.size();
  EXPECT_NEAR(mean_all, phi, 1e-12);
  // Inner cells (the 3 x 3 x 3 away from the walls, 4 mm = 5.7 radii inside): compared with
  // an independent Monte Carlo estimate of the solid fraction of the same region (fraction of
  // random points inside some grain). The coarse-grained value is exact, so the tolerance is
  // the Monte Carlo error, 4 sigma = 4 sqrt(phi (1 - phi) / N) = 0.0063 for N = 1e5.
  const Vec3 lo = grid.cell_lo(1, 1, 1), hi = grid.cell_lo(4, 4, 4);
  double inner = 0.0;
  for (int k = 1; k < 4; ++k)
    for (int j = 1; j < 4; ++j)
      for (int i = 1; i < 4; ++i) {
        inner += f.solid_fraction[grid.index(i, j, k)] / 27.0;
        EXPECT_NEAR(f.mass_density[grid.index(i, j, k)],
                    2000.0 * f.solid_fraction[grid.index(i, j, k)], 1e-9);
      }
  std::mt19937_64 rng(5);
  std::uniform_real_distribution<double> ux(lo.x(), hi.x()), uy(lo.y(), hi.y()), uz(lo.z(), hi.z());
  const int samples = 100000;
  int hits = 0;
  for (int m = 0; m < samples; ++m) {
    const Vec3 p(ux(rng), uy(rng), uz(rng));
    for (std::size_t n = 0; n < s.position.size(); ++n)
      if ((p - s.position[n]).squaredNorm() < s.radius[n] * s.radius[n]) {
        ++hits;
        break;
      }
  }
  const double mc = static_cast<double>(hits) / samples;
  EXPECT_NEAR(inner, mc, 4 * std::sqrt(mc * (1 - mc) / samples));
}

TEST(CoarseGrainer, UniformDisplacementGivesItsVelocityExactly) {
  dem::Region region;
  region.dimension = 3;
  region.box_max = Vec3(0.02, 0.02, 0.02);
  const auto packed = box_packing(region);
  ParticleSample first = sample_of(packed, 0.5);
  ParticleSample second = sample_of(packed, 0.5 + 1.0 / 12.0);
  const Vec3 d(1.3e-4, -0.4e-4, 2.1e-4);  // the same displacement for every grain
  for (Vec3& x : second.position) x += d;
  // The second sample in another order: grains are matched by id, not by position in the list.
  std::reverse(second.id.begin(), second.id.end());
  std::reverse(second.position.begin(), second.position.end());
  std::reverse(second.radius.begin(), second.radius.end());
  CellGrid grid;
  grid.hi = region.box_max;
  grid.cells = {4, 3, 5};
  CoarseGrainer cg(grid);
  EXPECT_EQ(cg.add_interval(first, second), static_cast<int>(packed.size()));
  const Vec3 v = d * 12.0;  // displacement over one period of 1/12 s
  const auto velocity = cg.mean().velocity();
  for (std::size_t a = 0; a < velocity.size(); ++a)
    EXPECT_NEAR((velocity[a] - v).norm(), 0.0, 1e-12 * v.norm()) << "cell " << a;
  // The azimuthal average of a uniform axial displacement: v_z everywhere, v_r = 0.
  const Vec3 d_axial(0, 0, 2.1e-4);
  second = sample_of(packed, 0.5 + 1.0 / 12.0);
  for (Vec3& x : second.position) x += d_axial;
  CoarseGrainer axial(grid);
  axial.add_interval(first, second);
  const RadialField rz = azimuthal_average(axial.mean(), Vec3(0.01, 0.01, 0), 2, 0.004);
  for (std::size_t b = 0; b < rz.v_z.size(); ++b) {
    EXPECT_NEAR(rz.v_z[b], 12.0 * 2.1e-4, 1e-12);
    EXPECT_NEAR(rz.v_r[b], 0.0, 1e-15);
  }
}

TEST(CoarseGrainer, RefusesEmptyIntervalsAndBadGrids) {
  CellGrid grid;
  grid.hi = Vec3::Ones();
  CoarseGrainer cg(grid);
  ParticleSample s;
  s.time = 1.0;
  EXPECT_THROW(cg.add_interval(s, s), InputError);
  grid.cells = {0, 1, 1};
  EXPECT_THROW(CoarseGrainer{grid}, InputError);
}

}  // namespace
}  // namespace talus::analysis
