// Initial packings: particle counts, porosity mapping, random fill and growth.
#include <gtest/gtest.h>

#include <cmath>

#include "talus/core/error.hpp"
#include "talus/dem/packing.hpp"

namespace talus::dem {
namespace {

constexpr double kRmin = 1e-3, kRmax = 2e-3;  // Kuen: radius uniform 1-2 mm

// flume.md, Table 3: the sand fills the triangle between the chute W1, the gate W4 and the lid W5.
Region flume_triangle() {
  Region r;
  r.dimension = 2;
  r.polygon = {Vec3(0, 1.115, 0), Vec3(0.5276, 0.8226, 0), Vec3(0.5276, 1.115, 0)};
  return r;
}

Region box_2d(double width, double height) {
  Region r;
  r.dimension = 2;
  r.box_min = Vec3(0, 0, 0);
  r.box_max = Vec3(width, height, 0);
  return r;
}

Region box_3d(double side) {
  Region r;
  r.dimension = 3;
  r.box_min = Vec3(0, 0, 0);
  r.box_max = Vec3(side, side, side);
  return r;
}

// The flume fill is the expensive one (about 1 s): made once per process, checked by two tests.
const std::vector<PackedParticle>& flume_fill() {
  static const std::vector<PackedParticle> particles =
      random_fill(flume_triangle(), kRmin, kRmax, porosity_2d_from_3d(0.39), std::nullopt, 1);
  return particles;
}

int count_outside(const Region& region, const std::vector<PackedParticle>& particles) {
  int outside = 0;
  for (const PackedParticle& p : particles) outside += !region.contains(p.position, p.radius);
  return outside;
}

TEST(Packing, PorosityMapping2dFrom3d) {
  // dem.md (Kuen Table 5): n = 0.39 gives D = 0.3983 and a 2D porosity of 0.1662.
  EXPECT_NEAR(porosity_2d_from_3d(0.39), 0.1662, 5e-5);
  // The ends of the relative density scale map onto each other.
  EXPECT_NEAR(porosity_2d_from_3d(0.4764), 0.2146, 1e-12);
  EXPECT_NEAR(porosity_2d_from_3d(0.2595), 0.0931, 1e-12);
}

TEST(Packing, RegionGeometry) {
  const Region tri = flume_triangle();
  // flume.md: triangle area 0.07714 m^2 (exactly 0.5 * 0.5276 * 0.2924 = 0.07713512).
  EXPECT_NEAR(tri.area_or_volume(), 0.07713512, 1e-10);
  Region clockwise = tri;
  std::swap(clockwise.polygon[1], clockwise.polygon[2]);
  EXPECT_NEAR(clockwise.area_or_volume(), 0.07713512, 1e-10);
  // A centroid lies a third of each altitude from that side; the nearest side is the slope:
  // altitude 2A / |slope| = 0.15427 / 0.60321 = 0.25575, a third is 0.08525 (lid 0.0975).
  const Vec3 centroid(0.5276 * 2 / 3, (2 * 1.115 + 0.8226) / 3, 0);
  for (const Region& r : {tri, clockwise}) {
    EXPECT_TRUE(r.contains(centroid, 0.0852));
    EXPECT_FALSE(r.contains(centroid, 0.0853));
    EXPECT_FALSE(r.contains(Vec3(0.1, 0.9, 0), 0.0));  // below the chute
  }
  EXPECT_DOUBLE_EQ(box_3d(0.02).area_or_volume(), 8e-6);
  EXPECT_TRUE(box_3d(0.02).contains(Vec3(0.01, 0.01, 0.019), 0.0009));
  EXPECT_FALSE(box_3d(0.02).contains(Vec3(0.01, 0.01, 0.019), 0.0011));
}

TEST(Packing, ParticleCountFromPorosity) {
  // dem.md: N = A(1 - n)/(pi rbar^2) with A = 0.07714, rbar = 1.5 mm and Kuen's 2D porosity gives
  // 9099 disks (9098.7 with the exact area, rounded). With n rounded to 0.166 it would be 9101.
  EXPECT_EQ(particle_count_for_porosity(flume_triangle(), kRmin, kRmax, porosity_2d_from_3d(0.39)),
            9099);
  EXPECT_EQ(particle_count_for_porosity(flume_triangle(), kRmin, kRmax, 0.166), 9101);
  // 3D: N = V(1 - n)/((4/3) pi <r^3>), <r^3> = (1 + 2)(1 + 4)/4 = 3.75 mm^3 for r in 1..2 mm:
  // 8e-6 * 0.5 / (4.18879 * 3.75e-9) = 254.6 -> 255.
  EXPECT_EQ(particle_count_for_porosity(box_3d(0.02), kRmin, kRmax, 0.5), 255);
}

TEST(Packing, FlumeFillReachesPorosityWithNegligibleOverlap) {
  const Region tri = flume_triangle();
  const std::vector<PackedParticle>& particles = flume_fill();
  EXPECT_EQ(particles.size(), 9099u);
  // The radii are scaled to the target porosity exactly (PFC radius expansion).
  EXPECT_NEAR(porosity(tri, particles), porosity_2d_from_3d(0.39), 1e-9);
  EXPECT_EQ(count_outside(tri, particles), 0);
  // Solid fraction 0.834 lies just below jamming for these disks (about 0.84 here); the
  // relaxation reaches max 0.013-0.035 % and mean 0.0015 % of r_min over seeds 1-4. A 3 % shrink
  // removes overlaps up to 6 % of r_min.
  const OverlapStats stats = overlap_stats(tri, particles);
  EXPECT_LT(stats.max_overlap, 1e-3 * kRmin);
  EXPECT_LT(stats.mean_overlap, 1e-4 * kRmin);
  EXPECT_LE(stats.max_wall_penetration, 0.0);
  // Kuen's 3 % shrink: porosity 1 - 0.8338 * 0.97^2 = 0.2155 and no overlap left.
  std::vector<PackedParticle> shrunk = particles;
  shrink_radii(shrunk, 0.03);
  EXPECT_NEAR(porosity(tri, shrunk), 1 - (1 - porosity_2d_from_3d(0.39)) * 0.9409, 1e-9);
  EXPECT_EQ(overlap_stats(tri, shrunk).overlapping_pairs, 0);
}

TEST(Packing, RadiiAreUniformAndScaledTogether) {
  const std::vector<PackedParticle>& particles = flume_fill();
  double smallest = kRmax, largest = 0.0, sum = 0.0;
  for (const PackedParticle& p : particles) {
    smallest = std::min(smallest, p.radius);
    largest = std::max(largest, p.radius);
    sum += p.radius;
  }
  const double n = static_cast<double>(particles.size());
  // All radii share one factor m, chosen so that the porosity holds. With N from the porosity,
  // m^2 = rbar^2/<r^2> = 2.25/(7/3): the formula's rbar^2 is smaller than <r^2> of uniform radii.
  const double m = std::sqrt(2.25 / (7.0 / 3.0));  // 0.98198
  // Ratio kept; the extremes of 9099 uniform draws lie within ~(r_max - r_min)/N of the ends.
  EXPECT_LE(largest / smallest, kRmax / kRmin * (1 + 1e-12));
  EXPECT_GT(largest / smallest, 1.99);
  EXPECT_GT(smallest, 0.99 * m * kRmin);
  EXPECT_LT(largest, 1.01 * m * kRmax);
  // Mean radius m * 1.5 mm; standard error of the mean of uniform draws (r_max - r_min)/sqrt(12 N)
  // = 3.0e-6 m (0.2 %). Allow 4 standard errors.
  const double standard_error = (kRmax - kRmin) / std::sqrt(12.0 * n);
  EXPECT_NEAR(sum / n, m * 0.5 * (kRmin + kRmax), 4 * standard_error * m);
}

TEST(Packing, RandomFillSmallBox) {
  const Region box = box_2d(0.1, 0.06);
  // Small regions jam earlier (walls loosen the packing: 0.166 jams in this box), so 0.20 here.
  const std::vector<PackedParticle> particles =
      random_fill(box, kRmin, kRmax, 0.20, std::nullopt, 7);
  // 0.006 * 0.8 / (pi * 2.25e-6) = 679.1
  EXPECT_EQ(particles.size(), 679u);
  EXPECT_NEAR(porosity(box, particles), 0.20, 0.005);
  EXPECT_EQ(count_outside(box, particles), 0);
  // Measured: max 0.016 % of r_min.
  EXPECT_LT(overlap_stats(box, particles).max_overlap, 1e-3 * kRmin);
}

TEST(Packing, RandomFillNonConvexPolygonGivenClockwise) {
  Region l_shape;  // an L, clockwise: a reflex corner at (0.03, 0.03)
  l_shape.dimension = 2;
  l_shape.polygon = {Vec3(0, 0, 0),       Vec3(0, 0.08, 0),    Vec3(0.03, 0.08, 0),
                     Vec3(0.03, 0.03, 0), Vec3(0.08, 0.03, 0), Vec3(0.08, 0, 0)};
  const std::vector<PackedParticle> particles =
      random_fill(l_shape, kRmin, kRmax, 0.22, std::nullopt, 7);
  EXPECT_NEAR(porosity(l_shape, particles), 0.22, 0.005);
  EXPECT_EQ(count_outside(l_shape, particles), 0);
  // Measured: max 0.009 % of r_min.
  EXPECT_LT(overlap_stats(l_shape, particles).max_overlap, 1e-3 * kRmin);
}

TEST(Packing, RandomFill3dBox) {
  const Region box = box_3d(0.02);
  const std::vector<PackedParticle> particles =
      random_fill(box, kRmin, kRmax, 0.5, std::nullopt, 5);
  EXPECT_EQ(particles.size(), 255u);  // see ParticleCountFromPorosity
  EXPECT_NEAR(porosity(box, particles), 0.5, 1e-9);
  EXPECT_EQ(count_outside(box, particles), 0);
  EXPECT_LT(overlap_stats(box, particles).max_overlap, 1e-3 * kRmin);
}

TEST(Packing, UnreachablePorosityIsAnInputError) {
  // Solid fraction 0.9 is beyond random jamming of disks (about 0.84).
  EXPECT_THROW(random_fill(box_2d(0.05, 0.05), kRmin, kRmax, 0.10, std::nullopt, 1), InputError);
}

TEST(Packing, BadInputIsRejected) {
  EXPECT_THROW(random_fill(box_2d(0.05, 0.05), 0.0, kRmax, 0.2, std::nullopt, 1), InputError);
  EXPECT_THROW(random_fill(box_2d(0.05, 0.05), kRmax, kRmin, 0.2, std::nullopt, 1), InputError);
  EXPECT_THROW(random_fill(box_2d(0.05, 0.05), kRmin, kRmax, 1.2, std::nullopt, 1), InputError);
  Region bad = box_3d(0.02);
  bad.dimension = 4;
  EXPECT_THROW(grow_packing(bad, kRmin, kRmax, 0.5, 10, 1), InputError);
  EXPECT_THROW(grow_packing(box_3d(0.02), kRmin, kRmax, 0.5, 0, 1), InputError);
}

TEST(Packing, GrowTo3dFractionWithoutOverlap) {
  const Region box = box_3d(0.02);
  const GrowResult result = grow_packing(box, kRmin, kRmax, 0.5, 1000, 3);
  // Goetz's phi_init = 0.5 (dem.md), well below random close packing (~0.64).
  EXPECT_FALSE(result.jammed);
  EXPECT_NEAR(result.packing_fraction, 0.5, 1e-12);
  EXPECT_NEAR(porosity(box, result.particles), 0.5, 1e-9);
  const OverlapStats stats = overlap_stats(box, result.particles);
  EXPECT_EQ(stats.overlapping_pairs, 0);
  EXPECT_LE(stats.max_wall_penetration, 0.0);
  EXPECT_EQ(count_outside(box, result.particles), 0);
}

TEST(Packing, GrowStopsAtJamming) {
  const Region box = box_2d(0.1, 0.06);
  const GrowResult result = grow_packing(box, kRmin, kRmax, 0.95, 600, 3);
  // Random close packing of polydisperse disks is about 0.84 (O'Hern et al. 2003, bidisperse);
  // the walls of a small box lower it (measured 0.823). 0.95 is out of reach.
  EXPECT_TRUE(result.jammed);
  EXPECT_GT(result.packing_fraction, 0.78);
  EXPECT_LT(result.packing_fraction, 0.86);
  EXPECT_NEAR(1 - porosity(box, result.particles), result.packing_fraction, 1e-9);
  EXPECT_EQ(overlap_stats(box, result.particles).overlapping_pairs, 0);
  EXPECT_EQ(count_outside(box, result.particles), 0);
}

// A 4 x 2 x 2 cm box with edges rounded by 5 mm: the core box 3 x 1 x 1 cm swept by a 5 mm ball.
Region rounded_box() {
  Region r;
  r.dimension = 3;
  r.box_min = Vec3(-0.02, -0.01, -0.01);
  r.box_max = Vec3(0.02, 0.01, 0.01);
  r.edge_radius = 0.005;
  return r;
}

TEST(Packing, RoundedBoxGeometry) {
  const Region box = rounded_box();
  // Core 30 x 10 x 10 mm, e = 5 mm: 3000 + 2*5*(300 + 100 + 300) + pi*25*50 + (4/3) pi 125
  // = 10000 + 3926.99 + 523.60 = 14450.5896 mm^3 (Steiner's formula for a box).
  EXPECT_NEAR(box.area_or_volume(), 14450.5896e-9, 1e-13);
  // The rounded box tends to the sharp box as e -> 0 and to a ball for a cube of side 2e.
  Region sharp = box;
  sharp.edge_radius = 1e-9;
  EXPECT_NEAR(sharp.area_or_volume(), 16e-6, 1e-13);
  Region ball = box_3d(0.02);
  ball.edge_radius = 0.01;
  EXPECT_NEAR(ball.area_or_volume(), 4.0 / 3.0 * M_PI * 1e-6, 1e-15);
  // On a flat face the distance is the box's: 4 mm from the top face above the core.
  EXPECT_TRUE(box.contains(Vec3(0.0, 0.0, 0.006), 0.0039));
  EXPECT_FALSE(box.contains(Vec3(0.0, 0.0, 0.006), 0.0041));
  // At a corner of the sharp box the rounded one is e(sqrt 3 - 1) = 3.66 mm away inwards: a
  // point 1 mm inside along the diagonal is outside the rounded box, one 4.7 mm inside is 1 mm in.
  const Vec3 corner(0.02, 0.01, 0.01), diagonal = Vec3(1, 1, 1).normalized();
  EXPECT_FALSE(box.contains(corner - 0.001 * diagonal, 0.0));
  EXPECT_TRUE(box.contains(corner - (0.005 * std::sqrt(3.0) - 0.004 + 1e-6) * diagonal, 0.001));
  EXPECT_FALSE(box.contains(corner - (0.005 * std::sqrt(3.0) - 0.004 - 1e-6) * diagonal, 0.001));
}

TEST(Packing, GrowInRoundedBoxStaysInsideTheRounding) {
  const Region box = rounded_box();
  const GrowResult result = grow_packing(box, kRmin, kRmax, 0.5, 600, 4);
  EXPECT_FALSE(result.jammed);
  // The fraction is of the rounded volume, not of the enclosing box.
  EXPECT_NEAR(porosity(box, result.particles), 0.5, 1e-9);
  const OverlapStats stats = overlap_stats(box, result.particles);
  EXPECT_EQ(stats.overlapping_pairs, 0);
  EXPECT_LE(stats.max_wall_penetration, 0.0);
  EXPECT_EQ(count_outside(box, result.particles), 0);
  // Grains reach into the rounded edges: some lie where the sharp box's edge region would be.
  int in_edges = 0;
  for (const PackedParticle& p : result.particles) {
    const Vec3 a = p.position.cwiseAbs();
    in_edges += (a.y() > 0.005 && a.z() > 0.005) || (a.x() > 0.015 && a.y() > 0.005);
  }
  EXPECT_GT(in_edges, 0);
}

TEST(Packing, ShrinkRadiiIsExact) {
  std::vector<PackedParticle> particles = {{Vec3(1, 1, 0), 1.0}, {Vec3(3, 1, 0), 0.5}};
  shrink_radii(particles, 0.03);
  EXPECT_DOUBLE_EQ(particles[0].radius, 0.97);
  EXPECT_DOUBLE_EQ(particles[1].radius, 0.485);
  EXPECT_EQ(particles[1].position, Vec3(3, 1, 0));
  // Porosity by hand: 1 - pi (0.97^2 + 0.485^2) / (4 * 2).
  EXPECT_NEAR(porosity(box_2d(4, 2), particles), 1 - M_PI * (0.9409 + 0.235225) / 8, 1e-15);
}

TEST(Packing, SameSeedSameResult) {
  const Region box = box_2d(0.05, 0.04);
  const auto a = random_fill(box, kRmin, kRmax, 0.25, std::nullopt, 11);
  const auto b = random_fill(box, kRmin, kRmax, 0.25, std::nullopt, 11);
  const auto c = random_fill(box, kRmin, kRmax, 0.25, std::nullopt, 12);
  ASSERT_EQ(a.size(), b.size());
  ASSERT_EQ(a.size(), c.size());
  int same_as_other_seed = 0;
  for (size_t i = 0; i < a.size(); ++i) {
    EXPECT_EQ(a[i].position, b[i].position);
    EXPECT_EQ(a[i].radius, b[i].radius);
    same_as_other_seed += a[i].position == c[i].position;
  }
  EXPECT_EQ(same_as_other_seed, 0);
  const GrowResult g1 = grow_packing(box_3d(0.01), kRmin, kRmax, 0.4, 100, 4);
  const GrowResult g2 = grow_packing(box_3d(0.01), kRmin, kRmax, 0.4, 100, 4);
  for (size_t i = 0; i < g1.particles.size(); ++i)
    EXPECT_EQ(g1.particles[i].position, g2.particles[i].position);
}

}  // namespace
}  // namespace talus::dem
