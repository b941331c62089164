// Membranes in a DEM run (dem/membrane/membrane_step.hpp hooked into the
// stepper): statics of grains resting on a pinned sheet, and momentum
// conservation of a grain thrown onto a free sheet.
#include <gtest/gtest.h>

#include <cmath>

#include "talus/dem/builder.hpp"
#include "talus/dem/contact/laws.hpp"
#include "talus/dem/system.hpp"

namespace talus::dem {
namespace {

// Grains (E = 10 MPa, Götz's soft grains) and a rubber-like membrane of Götz
// Table 2 (d = 0.3 mm) but E_m = 10 MPa, on a 40 mm sheet with 4 mm triangles.
DemScenario sheet_scenario(bool pinned, const Vec3& gravity) {
  DemScenario sc;
  sc.run.dimension = 3;
  sc.run.gravity = gravity;
  sc.contact.model = ViscoelasticHertz::name;
  MaterialParams grain;
  grain.name = "grain";
  grain.density = 2500;
  grain.youngs_modulus = 1e7;
  grain.poisson_ratio = 0.3;
  grain.friction = 0.3;
  grain.dissipation = 2e-4;
  MaterialParams rubber = grain;
  rubber.name = "rubber";
  rubber.friction = 0.5;
  sc.materials = {grain, rubber};
  MembraneSpec m;
  m.name = "sheet";
  m.mesh = MembraneMeshKind::FlatSheet;
  m.size_x = m.size_y = 0.04;
  m.spacing = 0.004;
  m.youngs_modulus = 1e7;
  m.thickness = 3e-4;
  m.density = 1000;
  m.spring_damping = 0.3;
  m.bending_stiffness = 1e-4;
  m.bending_damping = 1e-5;
  m.fixed = pinned ? MembraneFixed::Edge : MembraneFixed::None;
  m.material = "rubber";
  sc.membranes = {m};
  return sc;
}

double membrane_mass(const membrane::MembraneBody& m) {
  double s = 0;
  for (double x : m.body.mass) s += x;
  return s;
}

TEST(MembraneRun, PinnedSheetCarriesTheWeightOfGrainsAndItself) {
  DemScenario sc = sheet_scenario(true, Vec3(0, 0, -9.81));
  ParticleSourceParams src;
  src.kind = SourceKind::Lattice;
  src.material = "grain";
  src.box_min = Vec3(0.011, 0.011, 0.003);
  src.box_max = Vec3(0.029, 0.029, 0.0075);  // 4 x 4 grains, one layer
  src.spacing = 0.0045;
  src.radius = 0.002;
  sc.sources = {src};
  sc.contact.local_damping = 0.3;  // grains come to rest sooner; no effect on statics
  auto run = build_dem<3>(sc, {});
  auto& s = run->system;
  ASSERT_EQ(s.particles.size(), 16u);
  run->stepper->prime();
  const int64_t steps = std::llround(0.4 / s.dt);
  run->stepper->advance(steps);
  double m_grains = 0;
  for (double m : s.particles.m) m_grains += m;
  const auto& sheet = s.membranes[0];
  // Statics: at rest the supports carry every weight (grains and membrane,
  // pinned particles included), since all other forces are internal.
  const double weight = 9.81 * (m_grains + membrane_mass(sheet));
  // 5e-3: the 0.5 % of spec/dem.md's statics check (wall forces of a settled
  // packing = its weight), applied to the supports' total and to each component.
  EXPECT_NEAR(sheet.reaction.z(), weight, 5e-3 * weight)
      << "t = " << s.time << " s, dt = " << s.dt << " s, membrane KE "
      << membrane::kinetic_energy(sheet) << " J, grain KE " << kinetic_energy(s.particles);
  EXPECT_NEAR(sheet.reaction.x(), 0.0, 5e-3 * weight);
  EXPECT_NEAR(sheet.reaction.y(), 0.0, 5e-3 * weight);
  // All grains on the sheet (none fell through), above its pinned plane minus the sag.
  // 16: at least one contact for each of the 16 grains of the lattice.
  EXPECT_GE(sheet.contacts, 16);
  // -0.01 m: a quarter of the 40 mm sheet side, room for its sag; a grain that
  // fell through would be in free fall (0.5 g t^2 = 0.78 m in 0.4 s).
  for (const auto& x : s.particles.x) EXPECT_GT(x.z(), -0.01);
}

TEST(MembraneRun, GrainThrownOntoFreeSheetConservesMomentum) {
  DemScenario sc = sheet_scenario(false, Vec3::Zero());
  ParticleSourceParams src;
  src.kind = SourceKind::List;
  ParticleSpec g;
  g.position = Vec3(0.018, 0.016, 0.006);
  g.velocity = Vec3(0.4, 0.3, -2.0);
  g.angular_velocity = Vec3(0, 50, 0);
  g.radius = 0.002;
  g.material = "grain";
  src.particles = {g};
  sc.sources = {src};
  auto run = build_dem<3>(sc, {});
  auto& s = run->system;
  auto total = [&] {
    Vec3 p = membrane::momentum(s.membranes[0]);
    for (std::size_t i = 0; i < s.particles.size(); ++i) p += s.particles.m[i] * s.particles.v[i];
    return p;
  };
  const Vec3 p0 = total();
  run->stepper->prime();
  int max_contacts = 0;
  for (int k = 0; k < 300; ++k) {
    run->stepper->advance(10);
    max_contacts = std::max(max_contacts, s.membranes[0].contacts);
  }
  // The grain hit the sheet and handed it a good share of its momentum...
  // 0.1: a loose lower bound; a grain of 0.084 g that ends moving with the
  // 0.48 g sheet leaves it 0.48 / (0.48 + 0.084) = 85 % of p0.
  ASSERT_GT(max_contacts, 0);
  EXPECT_GT(membrane::momentum(s.membranes[0]).norm(), 0.1 * p0.norm());
  // ...and the sum is conserved: equal and opposite contact forces (reactions
  // -w_i F with sum w_i = 1), internal forces that sum to zero, and the same
  // half kicks for both. Round-off only: each kick m (h / m) f differs from h f by
  // ~1e-16 relative, over 3000 steps ~1e-12 |p0|; 1e-11 leaves a margin.
  EXPECT_LT((total() - p0).norm(), 1e-11 * p0.norm()) << (total() - p0).transpose();
}

}  // namespace
}  // namespace talus::dem
