// Membrane self-contact (spec/membranes-and-jamming.md "membrane self-contact:
// membrane particles against triangles"; dem/membrane/self_contact.hpp): two
// parts of one membrane pushed together stay apart only with it, the contact
// forces sum to zero, and a membrane at rest (flat sheet, closed sphere) has
// no self-contact at all, its own and neighbouring triangles being skipped.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <random>
#include <vector>

#include "talus/dem/contact/pair_coefficients.hpp"
#include "talus/dem/membrane/self_contact.hpp"

using namespace talus;
using namespace talus::dem;
using namespace talus::dem::membrane;

namespace {

// Götz's membrane (Table 2) against itself: E 1.25 MPa, nu 1/3, mu 1.2,
// A = 7 ns, gamma_t = 0.3.
ViscoelasticHertz::Coeffs membrane_on_membrane() {
  MaterialParams m;
  m.youngs_modulus = 1.25e6;
  m.poisson_ratio = 1.0 / 3.0;
  return {{effective_youngs(m, m), effective_shear(m, m), 1.2}, 7e-9, 0.3};
}

MembraneParams goetz_membrane() {
  MembraneParams p;
  p.youngs_modulus = 1.25e6;
  p.thickness = 3e-4;
  p.density = 1000;
  p.spring_damping = 0.15;
  p.bending_elastic = 1e-3;
  p.bending_dissipative = 1e-4;
  return p;
}

constexpr double kSpacing = 0.004;
constexpr int kLower = 12 * 12;  // vertices of the lower part

// One membrane of two parts: a 12 x 12 sheet in z = 0 and, `gap` above it, an
// 8 x 8 sheet shifted by part of a spacing (its particles over faces of the
// lower one), well inside the lower sheet's outline so that it cannot slip past.
Membrane two_sheets(double gap) {
  Mesh lower = flat_sheet(12, 12, kSpacing), upper = flat_sheet(8, 8, kSpacing);
  Mesh m;
  m.vertices = lower.vertices;
  m.triangles = lower.triangles;
  for (const Vec3& v : upper.vertices)
    m.vertices.push_back(v + Vec3(2.3 * kSpacing, 1.7 * kSpacing, gap));
  for (auto t : upper.triangles) {
    for (int& k : t) k += kLower;
    m.triangles.push_back(t);
  }
  m.build_topology("two sheets");
  return make_membrane(std::move(m), goetz_membrane());
}

// Forces of one pass: internal, and self-contact when asked.
int forces(Membrane& m, bool self, const SelfExclusion& ex, ContactMemory& mem,
           SelfContactScratch& scratch, double dt) {
  std::fill(m.f.begin(), m.f.end(), Vec3::Zero());
  add_internal_forces(m);
  if (!self) return 0;
  TriangleGrid grid;
  grid.build(m.mesh, m.x, 2.0 * self_contact_radius(m));
  mem.begin_step(1);
  return add_self_contact_forces(m, grid, ex, self_contact_radius(m), membrane_on_membrane(), dt,
                                 mem, scratch);
}

struct Collision {
  double min_separation = 1e300;  // min over steps of (lowest upper z - highest lower z)
  double final_separation = 0;    // mean upper z - mean lower z at the end
  int max_contacts = 0;
  double max_momentum = 0;  // max over steps of |total momentum - initial|, kg m/s
};

// The two parts approach at 1 m/s, 1 mm apart, for 3 ms: without contact
// they cross after 1 ms. pinned_lower: the lower part is pinned (a rigid
// floor) and the upper one falls onto it; otherwise each moves at 0.5 m/s,
// and the lower part's rim, which has nothing above
// it, goes on rising past the upper part's edge (separation means nothing).
Collision collide(bool self, bool pinned_lower) {
  Membrane m = two_sheets(1e-3);
  for (std::size_t i = 0; i < m.x.size(); ++i) {
    const bool lower = static_cast<int>(i) < kLower;
    m.fixed[i] = lower && pinned_lower;
    m.v[i] = Vec3(0, 0, lower ? (pinned_lower ? 0.0 : 0.5) : (pinned_lower ? -1.0 : -0.5));
  }
  const SelfExclusion ex = self_contact_exclusion(m.mesh);
  ContactMemory mem;
  SelfContactScratch scratch;
  const double m_min = *std::min_element(m.mass.begin(), m.mass.end());
  const double dt = 0.5 * std::min(critical_time_step(m), ViscoelasticHertz::critical_time_step(
                                                              membrane_on_membrane(), 0.5 * m_min,
                                                              self_contact_radius(m), 1.0));
  Collision out;
  Vec3 p0 = Vec3::Zero();
  for (std::size_t i = 0; i < m.x.size(); ++i) p0 += m.mass[i] * m.v[i];
  forces(m, self, ex, mem, scratch, dt);
  const int steps = static_cast<int>(3e-3 / dt);
  for (int s = 0; s < steps; ++s) {
    for (std::size_t i = 0; i < m.x.size(); ++i) {
      if (m.fixed[i]) continue;
      m.v[i] += (0.5 * dt / m.mass[i]) * m.f[i];
      m.x[i] += dt * m.v[i];
    }
    out.max_contacts = std::max(out.max_contacts, forces(m, self, ex, mem, scratch, dt));
    Vec3 p = Vec3::Zero();
    double lower_top = -1e300, upper_bottom = 1e300;
    for (std::size_t i = 0; i < m.x.size(); ++i) {
      if (!m.fixed[i]) m.v[i] += (0.5 * dt / m.mass[i]) * m.f[i];
      p += m.mass[i] * m.v[i];
      if (static_cast<int>(i) < kLower)
        lower_top = std::max(lower_top, m.x[i].z());
      else
        upper_bottom = std::min(upper_bottom, m.x[i].z());
    }
    out.min_separation = std::min(out.min_separation, upper_bottom - lower_top);
    out.max_momentum = std::max(out.max_momentum, (p - p0).norm());
  }
  double lower = 0, upper = 0;
  for (std::size_t i = 0; i < m.x.size(); ++i)
    (static_cast<int>(i) < kLower ? lower : upper) += m.x[i].z();
  out.final_separation = upper / (m.x.size() - kLower) - lower / kLower;
  return out;
}

}  // namespace

// The closed one-ring of an interior vertex of a triangular lattice (7
// vertices) touches 24 triangles: the hexagon of two rings.
TEST(MembraneSelfContact, ExclusionIsTheTwoRingOfTriangles) {
  const Mesh sheet = flat_sheet(9, 9, kSpacing);
  const SelfExclusion ex = self_contact_exclusion(sheet);
  const int centre = 4 * 9 + 4;
  EXPECT_EQ(ex.count(centre), 24u);
  for (int k = sheet.vertex_triangle_start[centre]; k < sheet.vertex_triangle_start[centre + 1];
       ++k)
    EXPECT_TRUE(ex.excluded(centre, sheet.vertex_triangle_list[k]));
}

// (a) Two parts of one membrane driven into each other do not pass through
// each other with self-contact, and do without it (so the check has teeth).
// The upper part falls at 1 m/s onto the pinned lower one. With
// self-contact its lowest particle stays above z = 0 at every step: the part
// stays flat (uniform approach), and the Hertz overlap at 1 m/s (about
// 0.1 mm, hertz_max_overlap with half a particle's mass) is below the contact
// distance d = 0.3 mm.
TEST(MembraneSelfContact, TwoPartsPushedTogetherDoNotPassThrough) {
  const Collision with = collide(true, true), without = collide(false, true);
  EXPECT_GT(with.max_contacts, 0);
  EXPECT_GT(with.min_separation, 0.0);
  EXPECT_GT(with.final_separation, 0.0);
  EXPECT_EQ(without.max_contacts, 0);
  EXPECT_LT(without.final_separation, -1e-3);  // 1 mm apart, 3 mm closed: crossed by ~2 mm
  RecordProperty("min_separation_with_mm", std::to_string(with.min_separation * 1e3));
  RecordProperty("final_separation_without_mm", std::to_string(without.final_separation * 1e3));
  std::printf(
      "min separation with self-contact %.4g mm, final separation without %.4g mm, "
      "max contacts %d\n",
      with.min_separation * 1e3, without.final_separation * 1e3, with.max_contacts);
}

// (b) over a whole collision of two free parts: the total momentum stays
// what it was to round-off. Scale: one part's momentum (0.5 m/s times
// 2e-4 kg, 1e-4 kg m/s); the forces sum to zero to a few ulp per contact and
// step, so 1e-12 of it allows thousands of steps of accumulated rounding
// (measured: 3e-19 kg m/s, 3e-15 of it).
TEST(MembraneSelfContact, MomentumIsConservedInACollision) {
  const Collision free = collide(true, false);
  EXPECT_GT(free.max_contacts, 0);
  const double one_part = 0.5 * 1000 * 3e-4 * flat_sheet(8, 8, kSpacing).area();
  std::printf("max |momentum| %.3g kg m/s (one part %.3g)\n", free.max_momentum, one_part);
  EXPECT_LT(free.max_momentum, 1e-12 * one_part);
}

// (b) Every self-contact force has its reaction: the forces of one pass sum
// to zero, to the round-off of the barycentric split (sum w_k = 1 to a few
// ulp, so |sum f| <= a few 1e-16 of sum |f|; 1e-14 leaves margin), here with
// tangential velocities so that friction acts too.
TEST(MembraneSelfContact, ForcesSumToZero) {
  Membrane m = two_sheets(0.5 * goetz_membrane().thickness);
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> u(-1, 1);
  for (std::size_t i = kLower; i < m.x.size(); ++i) {
    m.x[i].z() += 0.1 * goetz_membrane().thickness * u(rng);
    m.v[i] = Vec3(0.1 * u(rng), 0.1 * u(rng), -0.1);
  }
  const SelfExclusion ex = self_contact_exclusion(m.mesh);
  TriangleGrid grid;
  grid.build(m.mesh, m.x, 2.0 * self_contact_radius(m));
  ContactMemory mem;
  SelfContactScratch scratch;
  mem.begin_step(1);
  const int n = add_self_contact_forces(m, grid, ex, self_contact_radius(m), membrane_on_membrane(),
                                        1e-7, mem, scratch);
  EXPECT_GT(n,
            60);  // every upper particle over a lower face, and lower particles under upper faces
  Vec3 sum = Vec3::Zero();
  double abs = 0;
  for (const Vec3& f : m.f) sum += f, abs += f.norm();
  std::printf("%d contacts, |sum f| / sum |f| = %.3g\n", n, sum.norm() / abs);
  EXPECT_LT(sum.norm(), 1e-14 * abs);
}

// (c) At rest, no self-contact: a flat sheet, even with a contact radius of
// 1.5 spacings (the nearest triangle outside the excluded two rings is sqrt(3)
// spacings away), and a closed geodesic sphere with a radius of one shortest
// edge. Without the exclusion every particle would touch its own triangles.
TEST(MembraneSelfContact, NoSpuriousContactsAtRest) {
  ContactMemory mem;
  SelfContactScratch scratch;
  auto contacts = [&](Membrane& m, const SelfExclusion& ex, double radius) {
    std::fill(m.f.begin(), m.f.end(), Vec3::Zero());
    TriangleGrid grid;
    grid.build(m.mesh, m.x, 2.0 * radius);
    mem.begin_step(1);
    const int n =
        add_self_contact_forces(m, grid, ex, radius, membrane_on_membrane(), 1e-7, mem, scratch);
    for (const Vec3& f : m.f) EXPECT_EQ(f, Vec3::Zero());
    return n;
  };
  Membrane sheet = make_membrane(flat_sheet(15, 15, kSpacing), goetz_membrane());
  const SelfExclusion sheet_ex = self_contact_exclusion(sheet.mesh);
  EXPECT_EQ(contacts(sheet, sheet_ex, self_contact_radius(sheet)), 0);
  EXPECT_EQ(contacts(sheet, sheet_ex, 1.5 * kSpacing), 0);

  Membrane sphere = make_membrane(geodesic_sphere(0.04, 8), goetz_membrane());
  double shortest = 1e300;
  for (double l : sphere.rest.length) shortest = std::min(shortest, l);
  const SelfExclusion sphere_ex = self_contact_exclusion(sphere.mesh);
  EXPECT_EQ(contacts(sphere, sphere_ex, self_contact_radius(sphere)), 0);
  EXPECT_EQ(contacts(sphere, sphere_ex, shortest), 0);

  // The same sheet with nothing excluded: each particle on its own triangles.
  SelfExclusion none;
  none.start.assign(sheet.x.size() + 1, 0);
  std::fill(sheet.f.begin(), sheet.f.end(), Vec3::Zero());
  TriangleGrid grid;
  grid.build(sheet.mesh, sheet.x, 2.0 * self_contact_radius(sheet));
  mem.begin_step(1);
  EXPECT_EQ(add_self_contact_forces(sheet, grid, none, self_contact_radius(sheet),
                                    membrane_on_membrane(), 1e-7, mem, scratch),
            static_cast<int>(sheet.x.size()));
}
