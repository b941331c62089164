// Grain-membrane contacts (spec/membranes-and-jamming.md "Grain-membrane
// contact", Götz 2024 §3.2.3 and §3.3.2): closest-point classification, the
// face > edge > vertex priority (one force per feature), barycentric reactions
// (momentum), friction history across triangle boundaries, and the friction test.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

#include "membrane_case.hpp"
#include "talus/dem/membrane/contact.hpp"
#include "talus/dem/membrane/forces.hpp"
#include "talus/geometry/primitive.hpp"

using namespace talus;
using namespace talus::dem;
using namespace talus::dem::membrane;

namespace {

std::vector<int> all_triangles(const Mesh& m) {
  std::vector<int> t(m.num_triangles());
  for (std::size_t k = 0; k < t.size(); ++k) t[k] = static_cast<int>(k);
  return t;
}

// Triangles whose closest point lies within R of x: the contacts before the
// priority rule.
int raw_touching(const Mesh& m, const Vec3& x, double R) {
  int raw = 0;
  for (const auto& tri : m.triangles)
    raw +=
        (closest_on_triangle(m.vertices[tri[0]], m.vertices[tri[1]], m.vertices[tri[2]], x).point -
         x)
            .norm() < R;
  return raw;
}

// The forces of one fresh contact set on a mesh at rest; the vertex reactions go into f.
GrainForce forces_at_rest(const Mesh& m, const Grain& g,
                          const std::vector<TriangleContact>& contacts,
                          const ViscoelasticHertz::Coeffs& c, std::vector<Vec3>& f) {
  const std::vector<Vec3> vel(m.num_vertices(), Vec3::Zero());
  f.assign(m.num_vertices(), Vec3::Zero());
  ContactMemory mem;
  mem.begin_step();
  return grain_membrane_forces(m, m.vertices, vel, f, 0, g, contacts, c, 1e-6, mem);
}

}  // namespace

// The closest point matches geometry::closest_point (the walls' Ericson code),
// and the weights reproduce it: sum w = 1, point = sum w_i r_i.
TEST(MembraneContact, ClosestPointAndWeights) {
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> u(-1, 1);
  int kinds[4] = {0, 0, 0, 0};
  for (int trial = 0; trial < 2000; ++trial) {
    const Vec3 a(u(rng), u(rng), u(rng)), b(u(rng), u(rng), u(rng)), c(u(rng), u(rng), u(rng));
    const Vec3 x(2 * u(rng), 2 * u(rng), 2 * u(rng));
    geometry::Primitive prim;
    if (!geometry::make_triangle(a, b, c, prim)) continue;
    geometry::Closest<3> ref;
    ASSERT_TRUE(geometry::closest_point<3>(prim, x, 100.0, ref));
    const TrianglePoint p = closest_on_triangle(a, b, c, x);
    ++kinds[static_cast<int>(p.kind)];
    EXPECT_NEAR((p.point - ref.point).norm(), 0.0, 1e-12);
    EXPECT_NEAR(p.w[0] + p.w[1] + p.w[2], 1.0, 1e-15);
    EXPECT_NEAR((p.w[0] * a + p.w[1] * b + p.w[2] * c - p.point).norm(), 0.0, 1e-12);
    for (double w : p.w) EXPECT_GE(w, -1e-15);
    if (p.kind == Feature::Vertex) {
      EXPECT_EQ(p.w[p.corner], 1.0);
    }
    if (p.kind == Feature::Edge) {
      EXPECT_EQ(p.w[p.corner], 0.0);
    }
  }
  EXPECT_GT(kinds[1], 100);  // every region was visited
  EXPECT_GT(kinds[2], 100);
  EXPECT_GT(kinds[3], 100);
}

// A sphere pressed into a flat sheet by the same overlap over a vertex (six
// triangles touch it), over an edge (two) and inside a face: after the priority
// rule exactly one contact, with the Hertz force (4/3) E* sqrt(R) delta^1.5 at
// rest (spec/dem.md), and the vertex reactions sum to minus the grain force.
TEST(MembraneContact, OneNormalForceOverVertexEdgeAndFace) {
  const double s = 1.33e-3, R = 2e-3, delta = 5e-6;
  const Mesh m = flat_sheet(9, 9, s);
  const auto c = cases::goetz_grain_membrane(0.5);
  const double expected = 4.0 / 3.0 * c.h.e_star * std::sqrt(R) * std::pow(delta, 1.5);
  const int v = 4 * 9 + 4;  // an interior vertex
  const Edge* interior = nullptr;
  for (const auto& e : m.edges)
    if (e.a == v && e.interior()) interior = &e;
  ASSERT_NE(interior, nullptr);
  const auto& t = m.triangles[interior->t0];
  const Vec3 spots[3] = {m.vertices[v], 0.5 * (m.vertices[interior->a] + m.vertices[interior->b]),
                         (m.vertices[t[0]] + m.vertices[t[1]] + m.vertices[t[2]]) / 3.0};
  const Feature kinds[3] = {Feature::Vertex, Feature::Edge, Feature::Face};
  for (int k = 0; k < 3; ++k) {
    Grain g;
    g.x = spots[k] + Vec3(0, 0, R - delta);
    g.radius = R;
    g.mass = 2000 * 4.0 / 3.0 * M_PI * R * R * R;
    // Without the rule several triangles would be touched.
    EXPECT_EQ(raw_touching(m, g.x, R), k == 0 ? 6 : k == 1 ? 2 : 1);
    std::vector<TriangleContact> contacts;
    select_contacts(m, m.vertices, g.x, R, all_triangles(m), contacts);
    ASSERT_EQ(contacts.size(), 1u) << "spot " << k;
    // Over the edge's midpoint round-off may put the closest point just inside
    // one of the two triangles (a face contact): same point, same force.
    if (k != 1) {
      EXPECT_EQ(contacts[0].kind, kinds[k]);
    }
    std::vector<Vec3> f;
    const GrainForce gf = forces_at_rest(m, g, contacts, c, f);
    EXPECT_NEAR(gf.force.z(), expected, 1e-12 * expected);
    EXPECT_NEAR(gf.force.head<2>().norm(), 0.0, 1e-12 * expected);
    Vec3 sum = gf.force;
    for (const auto& fi : f) sum += fi;
    EXPECT_LT(sum.norm(), 1e-15 * expected);
  }
}

// On a convex mesh the classification is robust: a grain radially outside an
// edge midpoint touches both triangles at the edge, one outside a vertex all
// triangles around it, and one outside a face centre only that face. One
// contact each, of that kind, with the Hertz force.
TEST(MembraneContact, PriorityOnAConvexMesh) {
  const Mesh m = geodesic_sphere(0.02, 4);
  const double R = 2e-3, delta = 1e-5;
  const auto c = cases::goetz_grain_membrane(0.5);
  const double expected = 4.0 / 3.0 * c.h.e_star * std::sqrt(R) * std::pow(delta, 1.5);
  const Edge& e = m.edges[17];
  const auto& t = m.triangles[e.t0];
  const int v = e.a;
  const Vec3 spots[3] = {m.vertices[v], 0.5 * (m.vertices[e.a] + m.vertices[e.b]),
                         (m.vertices[t[0]] + m.vertices[t[1]] + m.vertices[t[2]]) / 3.0};
  const Feature kinds[3] = {Feature::Vertex, Feature::Edge, Feature::Face};
  const int around_v = m.vertex_triangle_start[v + 1] - m.vertex_triangle_start[v];
  const int raw_expected[3] = {around_v, 2, 1};
  for (int k = 0; k < 3; ++k) {
    Grain g;
    // Outwards: radial at the vertex and at the edge midpoint (the chord's
    // perpendicular bisector), the face normal over the centroid.
    const Vec3 face_normal = (m.vertices[t[1]] - m.vertices[t[0]])
                                 .cross(m.vertices[t[2]] - m.vertices[t[0]])
                                 .normalized();
    const Vec3 out_dir = k == 2 ? face_normal : spots[k].normalized();
    g.x = spots[k] + (R - delta) * out_dir;
    g.radius = R;
    g.mass = 1e-5;
    EXPECT_EQ(raw_touching(m, g.x, R), raw_expected[k]) << "spot " << k;
    std::vector<TriangleContact> contacts;
    select_contacts(m, m.vertices, g.x, R, all_triangles(m), contacts);
    ASSERT_EQ(contacts.size(), 1u) << "spot " << k;
    EXPECT_EQ(contacts[0].kind, kinds[k]);
    std::vector<Vec3> f;
    const GrainForce gf = forces_at_rest(m, g, contacts, c, f);
    EXPECT_NEAR(gf.force.norm(), expected, 1e-9 * expected);
    EXPECT_NEAR(gf.force.normalized().dot(out_dir), 1.0, 1e-12);
  }
}

// Random grains against a crumpled closed membrane with random velocities,
// several steps so that friction springs build up: the grain forces and the
// vertex reactions cancel to round-off (sum w_i = 1).
TEST(MembraneContact, MomentumIsConserved) {
  Mesh m = geodesic_sphere(0.01, 6);
  std::mt19937 rng(9);
  std::uniform_real_distribution<double> u(-1, 1);
  for (auto& p : m.vertices) p *= 1.0 + 0.05 * u(rng);
  std::vector<Vec3> vel(m.num_vertices());
  for (auto& w : vel) w = Vec3(u(rng), u(rng), u(rng)) * 0.1;
  const auto c = cases::goetz_grain_membrane(0.5);
  ContactMemory mem;
  int touching = 0;
  for (int trial = 0; trial < 50; ++trial) {
    Grain g;
    const Vec3 dir = Vec3(u(rng), u(rng), u(rng)).normalized();
    g.radius = 1e-3 * (1 + 0.5 * u(rng));
    g.x = dir * (0.01 + 0.9 * g.radius * u(rng));
    g.v = Vec3(u(rng), u(rng), u(rng));
    g.w = Vec3(u(rng), u(rng), u(rng)) * 100;
    g.mass = 1e-5;
    for (int step = 0; step < 5; ++step) {
      mem.begin_step();
      std::vector<TriangleContact> contacts;
      select_contacts(m, m.vertices, g.x, g.radius, all_triangles(m), contacts);
      std::vector<Vec3> f(m.num_vertices(), Vec3::Zero());
      const GrainForce gf =
          grain_membrane_forces(m, m.vertices, vel, f, trial, g, contacts, c, 1e-6, mem);
      touching += gf.contacts;
      Vec3 sum = gf.force;
      double scale = gf.force.norm();
      for (const auto& fi : f) {
        sum += fi;
        scale += fi.norm();
      }
      EXPECT_LE(sum.norm(), 1e-14 * scale);
      g.x += 1e-6 * g.v;
    }
  }
  EXPECT_GT(touching, 100);
}

// A grain held at a fixed overlap and moved over a pinned sheet while it
// sticks (mu = 1000, so the Coulomb cap is never reached): the tangential spring
// grows as v t, so the tangential force is (2/3) k_t v t + gamma_t sqrt(m k_t) v
// (ViscoelasticHertz), across several triangle boundaries. Dropping the spring
// at a boundary would lose what was built before it.
TEST(MembraneContact, FrictionSpringFollowsTheContactAcrossTriangles) {
  const double s = 1.33e-3, R = 2e-3, delta = 5e-6, speed = 1e-3, dt = 1e-3;
  const Mesh m = flat_sheet(12, 12, s);
  const auto c = cases::goetz_grain_membrane(1000.0);
  const std::vector<Vec3> vel(m.num_vertices(), Vec3::Zero());
  Grain g;
  g.radius = R;
  g.mass = 6.7e-5;
  const Vec3 dir(std::cos(0.3), std::sin(0.3), 0);
  const Vec3 start(3 * s + 0.1 * s, 3 * s + 0.2 * s, R - delta);
  g.v = speed * dir;
  ContactMemory mem;
  std::vector<TriangleContact> contacts;
  std::vector<int> triangles_seen;
  const int steps = 4000;  // 4 mm: three to four triangle widths
  GrainForce gf;
  for (int step = 0; step < steps; ++step) {
    g.x = start + (step * dt) * g.v;
    mem.begin_step();
    select_contacts(m, m.vertices, g.x, R, all_triangles(m), contacts);
    ASSERT_EQ(contacts.size(), 1u);
    triangles_seen.push_back(contacts[0].feature);
    std::vector<Vec3> f(m.num_vertices(), Vec3::Zero());
    gf = grain_membrane_forces(m, m.vertices, vel, f, 0, g, contacts, c, dt, mem);
  }
  std::sort(triangles_seen.begin(), triangles_seen.end());
  const auto distinct =
      std::unique(triangles_seen.begin(), triangles_seen.end()) - triangles_seen.begin();
  EXPECT_GE(distinct, 3);
  const double kt = 32.0 / 3.0 * c.h.g_star * std::sqrt(R * delta);
  const double expected =
      2.0 / 3.0 * kt * speed * steps * dt + 0.3 * std::sqrt(g.mass * kt) * speed;
  const Vec3 ft = gf.force - gf.force.dot(Vec3::UnitZ()) * Vec3::UnitZ();
  EXPECT_NEAR(ft.norm(), expected, 1e-9 * expected);
  EXPECT_NEAR(ft.normalized().dot(-dir), 1.0, 1e-12);
}
