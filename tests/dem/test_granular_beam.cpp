// The granular beam of Götz 2024 §5.2 before loading, reduced so that it runs
// in seconds: a rounded-box membrane (3 x 3 x 6 cm instead of 8 x 8 x 40 cm)
// filled by growth with the source's grains (R 2.5-2.9 mm, E 100 MPa), no
// gravity, 90 kPa of vacuum ramped in. It must stay closed (every grain inside
// the membrane) and come to rest. Here the beam is free (no mould, no [beam]
// rig); the bending test with the mould is tests/dem/test_beam_run.cpp.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "talus/dem/builder.hpp"
#include "talus/dem/contact/laws.hpp"
#include "talus/dem/system.hpp"

namespace talus::dem {
namespace {

constexpr double kVacuum = 9e4, kRamp = 0.01;
const Vec3 kSize(0.03, 0.03, 0.06);

DemScenario reduced_beam() {
  DemScenario sc;
  sc.run.dimension = 3;
  sc.run.gravity = Vec3::Zero();
  sc.run.seed = 5;
  sc.contact.model = ViscoelasticHertz::name;
  sc.contact.tangential_damping = 0.3;
  // Götz Table 6, with the stiffest grains and membrane of the study.
  MaterialParams grain;
  grain.name = "grain";
  grain.density = 2000;
  grain.youngs_modulus = 1e8;
  grain.poisson_ratio = 0.245;
  grain.friction = 0.25;
  grain.dissipation = 4.3e-9;
  MaterialParams rubber = grain;
  rubber.name = "rubber";
  rubber.poisson_ratio = 1.0 / 3.0;
  rubber.friction = 1.2;
  sc.materials = {grain, rubber};
  // Grown in the box 4 mm inside the membrane: at the corners (edge radius
  // 7.5 mm) a grain of 2.9 mm then still clears the chords of the mesh.
  ParticleSourceParams src;
  src.kind = SourceKind::Grow;
  src.material = "grain";
  src.box_max = 0.5 * kSize - Vec3::Constant(0.004);
  src.box_min = -src.box_max;
  src.radius_min = 2.5e-3;
  src.radius_max = 2.9e-3;
  src.packing_fraction = 0.58;
  src.count = 176;  // 0.58 of the box over the mean grain volume of 2.5-2.9 mm
  sc.sources = {src};
  MembraneSpec m;
  m.name = "beam";
  m.mesh = MembraneMeshKind::Box;
  m.size_x = kSize.x();
  m.size_y = kSize.y();
  m.size_z = kSize.z();
  m.edge_radius = 0.0075;
  m.spacing = 0.006;
  m.youngs_modulus = 1e8;
  m.thickness = 3e-4;
  m.density = 1000;
  m.spring_damping = 0.15;
  m.bending_stiffness = 1e-3;
  m.bending_damping = 1e-4;
  m.pressure = -kVacuum;
  m.pressure_ramp_end = kRamp;  // from t = 0
  m.material = "rubber";
  sc.membranes = {m};
  return sc;
}

// Winding number of the closed mesh about p (sum of the triangles' solid
// angles, Van Oosterom & Strackee, over 4 pi): 1 inside, 0 outside.
double winding_number(const membrane::Membrane& m, const Vec3& p) {
  double omega = 0;
  for (const auto& t : m.mesh.triangles) {
    const Vec3 a = m.x[t[0]] - p, b = m.x[t[1]] - p, c = m.x[t[2]] - p;
    const double la = a.norm(), lb = b.norm(), lc = c.norm();
    omega += 2 * std::atan2(a.dot(b.cross(c)),
                            la * lb * lc + a.dot(b) * lc + b.dot(c) * la + c.dot(a) * lb);
  }
  return omega / (4 * M_PI);
}

double enclosed_volume(const membrane::Membrane& m) {
  double v = 0;
  for (const auto& t : m.mesh.triangles) v += m.x[t[0]].dot(m.x[t[1]].cross(m.x[t[2]])) / 6.0;
  return v;
}

TEST(GranularBeam, FilledBeamUnderVacuumStaysClosedAndComesToRest) {
  auto run = build_dem<3>(reduced_beam(), {});
  auto& s = run->system;
  ASSERT_EQ(s.particles.size(), 176u);
  const auto& mem = s.membranes[0].body;
  for (const Vec3& x : s.particles.x) ASSERT_NEAR(winding_number(mem, x), 1.0, 1e-9);
  const double v0 = enclosed_volume(mem);
  double grains = 0;
  for (double r : s.particles.r) grains += 4.0 / 3.0 * M_PI * r * r * r;
  run->stepper->prime();
  auto energy = [&] {
    return kinetic_energy(s.particles) + membrane::kinetic_energy(s.membranes[0]);
  };
  double peak = 0, last = 0;
  const double end = 0.05;  // the ramp, then four times as long to settle
  while (s.time < end) {
    run->stepper->advance(std::max<int64_t>(1, std::llround(5e-4 / s.dt)));
    last = energy();
    peak = std::max(peak, last);
    // The ramp: p = p_final t / t_ramp, set at the last force pass (one step
    // before s.time at most).
    EXPECT_NEAR(mem.params.pressure, -kVacuum * std::min(1.0, s.time / kRamp),
                kVacuum * s.dt / kRamp * 1.001);
  }
  // Closed: every grain centre is still inside the membrane (winding number 1;
  // 1e-6 allows the rounding of the solid-angle sum, an escaped grain gives 0).
  int outside = 0;
  for (const Vec3& x : s.particles.x) outside += std::abs(winding_number(mem, x) - 1.0) > 1e-6;
  EXPECT_EQ(outside, 0);
  // The vacuum compacted the beam, but not below the grains' own volume.
  const double v1 = enclosed_volume(mem);
  EXPECT_LT(v1, v0);
  EXPECT_GT(v1, grains);
  // At rest: 1e-3 of the peak kinetic energy of the compaction, i.e. the
  // velocities 3 % of their peak (the contacts' and the springs' damping).
  // Measured 4.3e-5 (seeds 1-6 of this test: 1.5e-6 to 6.3e-5).
  EXPECT_LT(last, 1e-3 * peak) << "peak " << peak << " J, last " << last << " J, t " << s.time
                               << " s, dt " << s.dt << " s, V " << v0 << " -> " << v1
                               << " m^3, grains " << grains << " m^3";
  // Nothing spins the free beam up: the angular momentum about the centre of
  // mass (orbital and the grains' spin), over the inertia tensor, is a rigid
  // rotation rate below 1e-9 rad/s (forces and torques balance exactly, so
  // rounding only; measured 1.2e-14). With the grain's lever arm at the
  // overlap's midpoint instead of the membrane point, friction left a torque
  // (overlap / 2) n x ft per contact and the beam reached 2.4 rad/s by 50 ms.
  double mass = 0;
  Vec3 com = Vec3::Zero();
  auto each = [&](auto&& f) {
    for (std::size_t i = 0; i < s.particles.size(); ++i)
      f(s.particles.m[i], s.particles.x[i], s.particles.v[i]);
    for (std::size_t i = 0; i < mem.x.size(); ++i) f(mem.mass[i], mem.x[i], mem.v[i]);
  };
  each([&](double m, const Vec3& x, const Vec3&) { mass += m, com += m * x; });
  com /= mass;
  Eigen::Matrix3d inertia = Eigen::Matrix3d::Zero();
  Vec3 L = Vec3::Zero();
  each([&](double m, const Vec3& x, const Vec3& v) {
    const Vec3 d = x - com;
    inertia += m * (d.squaredNorm() * Eigen::Matrix3d::Identity() - d * d.transpose());
    L += m * d.cross(v);
  });
  for (std::size_t i = 0; i < s.particles.size(); ++i)  // the grains' spin (solid spheres)
    L += 0.4 * s.particles.m[i] * s.particles.r[i] * s.particles.r[i] * s.particles.w[i];
  EXPECT_LT((inertia.inverse() * L).norm(), 1e-9) << "L = " << L.transpose() << " kg m^2/s";
}

}  // namespace
}  // namespace talus::dem
