// The granular gripper's engine pieces (dem/membrane/driven_sphere.hpp,
// gripper.hpp, body.hpp): a sphere on a prescribed path, its Hertz contact
// with a membrane and the balance of that force with the supports'
// reaction, the held filling and the pre-tension cut, the stepped vacuum.
#include <gtest/gtest.h>

#include <cmath>

#include "talus/dem/builder.hpp"
#include "talus/dem/contact/laws.hpp"
#include "talus/dem/contact/pair_coefficients.hpp"
#include "talus/dem/membrane/from_spec.hpp"
#include "talus/dem/membrane/gripper.hpp"
#include "talus/dem/output_observer.hpp"
#include "talus/dem/system.hpp"

namespace talus::dem {
namespace {

using membrane::DrivenSphere;

TEST(DrivenSphere, PathIsThePiecewiseLinearIntegralOfItsLegs) {
  DrivenSphere o;
  o.origin = Vec3(1, 2, 3);
  o.legs = {{1.0, 3.0, Vec3(0, 0, 0.5)}, {4.0, kNever, Vec3(0.1, 0, -0.25)}};
  EXPECT_EQ(membrane::position_at(o, 0.5), o.origin);  // before the first leg
  EXPECT_EQ(membrane::position_at(o, 2.0), Vec3(1, 2, 3.5));
  EXPECT_EQ(membrane::position_at(o, 3.5), Vec3(1, 2, 4));  // rest between legs
  EXPECT_EQ(membrane::position_at(o, 6.0), Vec3(1.2, 2, 3.5));
  EXPECT_EQ(membrane::velocity_at(o, 0.5), Vec3::Zero());
  EXPECT_EQ(membrane::velocity_at(o, 2.0), Vec3(0, 0, 0.5));
  EXPECT_EQ(membrane::velocity_at(o, 3.5), Vec3::Zero());
  EXPECT_EQ(membrane::velocity_at(o, 100.0), Vec3(0.1, 0, -0.25));
}

// A 40 mm sheet of 4 mm triangles in the plane z = 0, every particle pinned,
// no gravity, and no grains: only the driven sphere touches it.
DemScenario pinned_sheet() {
  DemScenario sc;
  sc.run.dimension = 3;
  sc.run.gravity = Vec3::Zero();
  sc.contact.model = ViscoelasticHertz::name;
  MaterialParams rubber;
  rubber.name = "rubber";
  rubber.density = 2000;
  rubber.youngs_modulus = 1.25e6;
  rubber.poisson_ratio = 1.0 / 3.0;
  rubber.friction = 1.2;
  rubber.dissipation = 7e-9;
  MaterialParams object = rubber;
  object.name = "object";
  object.youngs_modulus = 1e8;
  object.poisson_ratio = 0.4;
  sc.materials = {rubber, object};
  MembraneSpec m;
  m.name = "sheet";
  m.mesh = MembraneMeshKind::FlatSheet;
  m.size_x = m.size_y = 0.04;
  m.spacing = 0.004;
  m.youngs_modulus = 1.25e6;
  m.thickness = 3e-4;
  m.density = 2000;
  m.fixed = MembraneFixed::All;
  m.material = "rubber";
  sc.membranes = {m};
  return sc;
}

DrivenSphere object_at(const Vec3& x, double radius, int membranes) {
  DrivenSphere o;
  o.radius = radius;
  o.material = 1;
  o.origin = x;
  o.memory.resize(membranes);
  return o;
}

// A sphere at rest with its centre R - delta below the centroid of a
// triangle: one face contact, the static Hertz force (4/3) E* sqrt(R)
// delta^3/2 pushing it down (no damping at rest); the pinned sheet's
// supports take exactly that force, so the object's force and the
// supports' reaction are equal (the reactions -w_k F sum to -F).
TEST(DrivenSphere, StaticHertzForceAndTheSupportsBalanceIt) {
  const DemScenario sc = pinned_sheet();
  auto run = build_dem<3>(sc, {});
  auto& s = run->system;
  const auto& mesh = s.membranes[0].body.mesh;
  const auto& x = s.membranes[0].body.x;
  const auto& tri = mesh.triangles[mesh.num_triangles() / 2];
  const Vec3 centroid = (x[tri[0]] + x[tri[1]] + x[tri[2]]) / 3.0;
  const double r = 0.005, delta = 1e-4;
  s.objects.push_back(object_at(centroid - Vec3(0, 0, r - delta), r, 1));
  run->stepper->prime();
  const auto& o = s.objects[0];
  const double e_star = effective_youngs(sc.materials[1], sc.materials[0]);
  const double f = 4.0 / 3.0 * e_star * std::sqrt(r) * std::pow(delta, 1.5);
  EXPECT_EQ(o.contacts, 1);
  EXPECT_NEAR(o.force.z(), -f, 1e-12 * f);
  EXPECT_NEAR(std::hypot(o.force.x(), o.force.y()), 0.0, 1e-12 * f);
  EXPECT_NEAR((s.membranes[0].reaction - o.force).norm(), 0.0, 1e-12 * f);
}

// Moving along the sheet while pressed into it, the sphere's path stays the
// prescribed one whatever the contact does, and friction opposes the motion
// at most mu times the normal force; the supports still take all of it.
TEST(DrivenSphere, PrescribedPathIsExactUnderFriction) {
  const DemScenario sc = pinned_sheet();
  auto run = build_dem<3>(sc, {});
  auto& s = run->system;
  const Vec3 start(0.02, 0.02, -0.005 + 1e-4);
  DrivenSphere o = object_at(start, 0.005, 1);
  o.legs = {{0.0, kNever, Vec3(0.01, 0, 0)}};
  s.objects.push_back(o);
  run->stepper->prime();
  run->stepper->advance(2000);
  const auto& d = s.objects[0];
  EXPECT_EQ(d.x, membrane::position_at(d, s.time));
  EXPECT_NEAR(d.x.x(), start.x() + 0.01 * s.time, 1e-15);
  EXPECT_DOUBLE_EQ(d.x.z(), start.z());
  ASSERT_GT(d.contacts, 0);
  EXPECT_LT(d.force.x(), 0.0);  // friction against the motion
  EXPECT_LE(-d.force.x(), 1.2 * -d.force.z() * (1 + 1e-9));
  EXPECT_NEAR((s.membranes[0].reaction - d.force).norm(), 0.0, 1e-9 * d.force.norm());
}

TEST(DrivenSphere, TouchesNothingBeforeItIsActive) {
  const DemScenario sc = pinned_sheet();
  auto run = build_dem<3>(sc, {});
  auto& s = run->system;
  DrivenSphere o = object_at(Vec3(0.02, 0.02, -0.004), 0.005, 1);  // 1 mm deep
  o.active_from = 1.0;
  s.objects.push_back(o);
  run->stepper->prime();
  EXPECT_EQ(s.objects[0].contacts, 0);
  EXPECT_EQ(s.objects[0].force, Vec3::Zero());
}

// A hemisphere R = 20 mm held and released by apply_gripper.
struct Held {
  DemScenario sc;
  DemSystem<3> s;
};

Held held_hemisphere() {
  Held h;
  h.sc = pinned_sheet();
  MembraneSpec& m = h.sc.membranes[0];
  m.name = "gripper";
  m.mesh = MembraneMeshKind::GeodesicHemisphere;
  m.radius = 0.02;
  m.frequency = 8;
  m.fixed = MembraneFixed::Edge;
  GripperParams g;
  g.membrane = "gripper";
  g.object_material = "object";
  g.release = 0.1;
  g.object_radius = 0.005;
  g.object_center = Vec3(0, 0, -0.03);
  g.vacuum = 9e4;
  g.vacuum_steps = 3;
  g.vacuum_start = 0.2;
  g.vacuum_end = 0.5;
  h.sc.gripper = g;
  h.s.materials = h.sc.materials;
  h.s.membranes.push_back(membrane::make_membrane_body(m, 0));
  return h;
}

TEST(GripperSetup, HoldsTheFreeParticlesStretchedThenCutsTheRestLengths) {
  Held h = held_hemisphere();
  const auto before = h.s.membranes[0].body;
  membrane::apply_gripper(*h.sc.gripper, h.sc, h.s);
  auto& mb = h.s.membranes[0];
  ASSERT_EQ(mb.body.x.size(), 341u);  // frequency 8: (642 + 5 * 8) / 2
  int rim = 0;
  for (std::size_t i = 0; i < mb.body.x.size(); ++i) {
    EXPECT_TRUE(mb.body.fixed[i]);
    if (before.fixed[i]) {
      ++rim;
      EXPECT_EQ(mb.body.x[i], before.x[i]);  // the rim stays
    } else {
      EXPECT_NEAR(mb.body.x[i].norm(), 1.25 * 0.02, 1e-12);
    }
  }
  EXPECT_EQ(rim, 40);  // the equator's 5 n particles
  membrane::release_if_due(mb, 0.099);
  EXPECT_EQ(mb.body.rest.length, before.rest.length);
  membrane::release_if_due(mb, 0.1);
  for (std::size_t e = 0; e < before.rest.length.size(); ++e)
    EXPECT_DOUBLE_EQ(mb.body.rest.length[e], 0.875 * before.rest.length[e]);
  for (std::size_t i = 0; i < mb.body.x.size(); ++i) EXPECT_EQ(mb.body.fixed[i], before.fixed[i]);
  // Back at the rest radius, every spring pulls with k (L0 - 0.875 L0): the
  // tension of each triangle is k 0.125 times its mean rest length.
  mb.body.x = before.x;
  const double k = membrane::spring_constant(1.25e6, 3e-4);
  const auto tension = membrane::triangle_tension(mb);
  for (std::size_t t = 0; t < tension.size(); ++t) {
    double mean = 0.0;
    for (int e : mb.body.mesh.triangle_edges[t]) mean += before.rest.length[e] / 3.0;
    EXPECT_NEAR(tension[t], k * 0.125 * mean, 1e-9 * k * mean);
  }
  // A resumed run applies the release again: nothing changes.
  const auto cut = mb.body.rest.length;
  mb.released = false;
  membrane::release_if_due(mb, 0.3);
  EXPECT_EQ(mb.body.rest.length, cut);
}

TEST(GripperSetup, VacuumRisesInSteps) {
  Held h = held_hemisphere();
  membrane::apply_gripper(*h.sc.gripper, h.sc, h.s);
  const auto& mb = h.s.membranes[0];
  // Three steps of 0.1 s from 0.2 s, each rising over its first half.
  EXPECT_EQ(membrane::pressure_at(mb, 0.1), 0.0);
  EXPECT_NEAR(membrane::pressure_at(mb, 0.225), -1.5e4, 1e-8);
  EXPECT_NEAR(membrane::pressure_at(mb, 0.27), -3e4, 1e-8);
  EXPECT_NEAR(membrane::pressure_at(mb, 0.325), -4.5e4, 1e-8);
  EXPECT_NEAR(membrane::pressure_at(mb, 0.49), -9e4, 1e-8);
  EXPECT_EQ(membrane::pressure_at(mb, 0.6), -9e4);
  // One step rising over all of it is the plain linear ramp.
  membrane::MembraneBody lin = mb;
  lin.pressure_steps = 1;
  lin.step_rise = 1.0;
  EXPECT_NEAR(membrane::pressure_at(lin, 0.35), -4.5e4, 1e-8);
  ASSERT_EQ(h.s.objects.size(), 1u);
  EXPECT_EQ(h.s.objects[0].radius, 0.005);
  EXPECT_EQ(h.s.objects[0].material, 1);
}

}  // namespace
}  // namespace talus::dem

namespace talus::dem::membrane {
namespace {

// The snapshots draw the object with the walls: a closed sphere of triangles
// on its surface, numbered after the walls.
TEST(DrivenSphere, DrawnWithTheWallsInSnapshots) {
  DemSystem<3> s;
  DrivenSphere o;
  o.radius = 0.01;
  o.x = Vec3(0.1, -0.2, 0.3);
  s.objects.push_back(o);
  const io::WallFrame f = wall_frame(s, 1.0);
  ASSERT_EQ(f.triangles.size(), 224u);  // 4 n (n - 1), n = 8
  for (const Vec3& p : f.points) EXPECT_NEAR((p - o.x).norm(), o.radius, 1e-15);
  for (int w : f.triangle_wall) EXPECT_EQ(w, 0);
  // Closed and facing outwards: the signed volume is that of the inscribed
  // polyhedron, a little below 4/3 pi r^3.
  double volume = 0.0;
  for (const auto& t : f.triangles)
    volume += (f.points[t[0]] - o.x).dot((f.points[t[1]] - o.x).cross(f.points[t[2]] - o.x)) / 6;
  const double ball = 4.0 / 3.0 * M_PI * std::pow(o.radius, 3);
  EXPECT_LT(volume, ball);
  EXPECT_GT(volume, 0.9 * ball);
}

}  // namespace
}  // namespace talus::dem::membrane
