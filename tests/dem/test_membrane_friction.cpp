// Friction test of Götz 2024 §3.3.2 (spec/membranes-and-jamming.md), reduced:
// a sphere R = 2 mm, rotation locked, free only vertically, pulled horizontally
// at 0.05 m/s over a flat membrane of 1.33 mm triangles. Here the membrane is
// pinned (every particle fixed), which isolates what the triangle model is
// about: the contact geometry and the friction history as the contact passes
// faces, edges and vertices. On a flat surface the normal force equals the
// weight at one overlap, and sliding friction is mu m g, so height and
// friction must stay constant; a membrane of touching particles makes both
// oscillate with the mesh period (the source's Fig. 8), which this rules out.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <vector>

#include "membrane_case.hpp"
#include "talus/dem/membrane/contact.hpp"
#include "talus/dem/membrane/forces.hpp"

using namespace talus;
using namespace talus::dem;
using namespace talus::dem::membrane;

namespace {

struct DragResult {
  double z_min = 1e300, z_max = -1e300, f_min = 1e300, f_max = -1e300;
  int features[4] = {0, 0, 0, 0};  // steps with a vertex, edge, face contact
};

// Symplectic Euler for the sphere's height (as the DEM stepper), position along
// the path prescribed; the sphere starts at its static overlap.
DragResult drag(const Vec3& start, const Vec3& dir, double mu) {
  const double s = 1.33e-3, R = 2e-3, rho = 2000, gravity = 9.81, speed = 0.05, dt = 1e-5;
  const Mesh sheet = flat_sheet(20, 14, s);                             // 25 x 15 mm
  const ViscoelasticHertz::Coeffs c = cases::goetz_grain_membrane(mu);  // Götz Table 2
  Grain g;
  g.radius = R;
  g.mass = rho * 4.0 / 3.0 * M_PI * R * R * R;
  const double weight = g.mass * gravity;
  const double delta = std::pow(weight / (4.0 / 3.0 * c.h.e_star * std::sqrt(R)), 2.0 / 3.0);
  g.x = start + Vec3(0, 0, R - delta);
  g.v = speed * dir;
  TriangleGrid grid;
  grid.build(sheet, sheet.vertices, 2 * R);
  const std::vector<Vec3> v_mem(sheet.num_vertices(), Vec3::Zero());
  std::vector<Vec3> f_mem(sheet.num_vertices(), Vec3::Zero());
  std::vector<int> candidates;
  std::vector<TriangleContact> contacts;
  ContactMemory memory;
  DragResult out;
  const int steps = static_cast<int>(std::lround(8e-3 / speed / dt));  // 8 mm: 6 triangles
  for (int step = 0; step < steps; ++step) {
    memory.begin_step();
    grid.query(g.x, R, candidates);
    select_contacts(sheet, sheet.vertices, g.x, R, candidates, contacts);
    for (const auto& k : contacts) ++out.features[static_cast<int>(k.kind)];
    const GrainForce f =
        grain_membrane_forces(sheet, sheet.vertices, v_mem, f_mem, 0, g, contacts, c, dt, memory);
    // Vertical only; the path velocity is imposed.
    g.v.z() += dt * (f.force.z() / g.mass - gravity);
    g.x += dt * g.v;
    if (step > 10) {  // after the spring has reached the Coulomb cap
      const double friction = -f.force.dot(dir);
      out.f_min = std::min(out.f_min, friction);
      out.f_max = std::max(out.f_max, friction);
      out.z_min = std::min(out.z_min, g.x.z() - (R - delta));
      out.z_max = std::max(out.z_max, g.x.z() - (R - delta));
    }
  }
  return out;
}

// Bound for the height: a thousandth of the static overlap (about 4 nm) -- the
// test asks for a constant height, and on an exactly flat sheet nothing but
// round-off may move it. Friction: mu m g within 0.1 % at every step.
void expect_constant(const DragResult& r, double mu) {
  const double R = 2e-3, m = 2000 * 4.0 / 3.0 * M_PI * R * R * R, weight = m * 9.81;
  std::printf(
      "height - static height in [%.3g, %.3g] m; friction in [%.9g, %.9g] N, mu m g = %.9g N\n",
      r.z_min, r.z_max, r.f_min, r.f_max, mu * weight);
  EXPECT_LT(std::max(std::abs(r.z_min), std::abs(r.z_max)), 4e-9);
  EXPECT_NEAR(r.f_min, mu * weight, 1e-3 * mu * weight);
  EXPECT_NEAR(r.f_max, mu * weight, 1e-3 * mu * weight);
}

}  // namespace

// A path at 17 degrees to the lattice rows crosses faces and edges anywhere.
TEST(MembraneFriction, ConstantHeightAndFrictionOblique) {
  const double a = 17 * M_PI / 180;
  const DragResult r = drag(Vec3(5e-3, 5e-3, 0), Vec3(std::cos(a), std::sin(a), 0), 0.5);
  expect_constant(r, 0.5);
  EXPECT_GT(r.features[3], 0);
}

// Along a row of vertices the contact runs exactly over vertices and edges,
// where six or two triangles touch the sphere at once.
TEST(MembraneFriction, ConstantHeightAndFrictionAlongAVertexRow) {
  const double h = 1.33e-3 * std::sqrt(3.0) / 2;
  const DragResult r = drag(Vec3(4 * 1.33e-3, 6 * h, 0), Vec3::UnitX(), 0.5);
  expect_constant(r, 0.5);
  EXPECT_GT(r.features[1] + r.features[2], 0);
}

// The same drag over a soft membrane (E_m 1.25 MPa, d 0.3 mm, rho_m 1000,
// gamma_sp 0.15, k_el 1e-3, k_diss 1e-5; rim pinned, interior free), leapfrog
// at dt = 2 us. A measurement harness (about 10 s, so disabled in the suite:
// run with --gtest_also_run_disabled_tests): the run stays stable (dt below
// critical_time_step; k_diss = 1e-4 at this spacing would need dt < 0.38 us)
// and the mean friction of steady sliding is mu times the mean normal force,
// i.e. mu m g, within 1 %.
TEST(MembraneFriction, DISABLED_SoftMembraneDrag) {
  const double s = 1.33e-3, R = 2e-3, gravity = 9.81, speed = 0.05, dt = 2e-6, mu = 0.5;
  Membrane m = make_membrane(flat_sheet(24, 18, s), {1.25e6, 0.3e-3, 1000, 0.15, 1e-3, 1e-5, 0.0});
  for (const auto& e : m.mesh.edges)
    if (!e.interior()) m.fixed[e.a] = m.fixed[e.b] = 1;
  ASSERT_GT(critical_time_step(m), dt);
  const ViscoelasticHertz::Coeffs c = cases::goetz_grain_membrane(mu);
  Grain g;
  g.radius = R;
  g.mass = 2000 * 4.0 / 3.0 * M_PI * R * R * R;
  g.x = Vec3(6e-3, 11e-3, R - 4e-6);
  TriangleGrid grid;
  std::vector<int> candidates;
  std::vector<TriangleContact> contacts;
  ContactMemory memory;
  const int settle = 50000, drag = 80000, skip = 20000;
  double sum_f = 0, sum_f2 = 0, sum_z = 0, sum_z2 = 0;
  int n = 0;
  for (int step = 0; step < settle + drag; ++step) {
    g.v.x() = step >= settle ? speed : 0.0;
    for (auto& f : m.f) f.setZero();
    add_internal_forces(m);
    if (step % 20 == 0) grid.build(m.mesh, m.x, 2 * R);
    memory.begin_step();
    grid.query(g.x, R, candidates);
    select_contacts(m.mesh, m.x, g.x, R, candidates, contacts);
    const GrainForce gf =
        grain_membrane_forces(m.mesh, m.x, m.v, m.f, 0, g, contacts, c, dt, memory);
    for (std::size_t i = 0; i < m.x.size(); ++i)
      if (!m.fixed[i]) {
        m.v[i] += dt * m.f[i] / m.mass[i];
        m.x[i] += dt * m.v[i];
      }
    g.v.z() += dt * (gf.force.z() / g.mass - gravity);
    g.x += dt * g.v;
    if (step >= settle + skip) {
      const double fr = -gf.force.x();
      sum_f += fr;
      sum_f2 += fr * fr;
      sum_z += g.x.z();
      sum_z2 += g.x.z() * g.x.z();
      ++n;
    }
  }
  const double f_mean = sum_f / n, z_mean = sum_z / n;
  const double f_sd = std::sqrt(std::max(0.0, sum_f2 / n - f_mean * f_mean));
  const double z_sd = std::sqrt(std::max(0.0, sum_z2 / n - z_mean * z_mean));
  std::printf("soft membrane: height %.6g m (sd %.3g), friction %.6g N (sd %.3g), mu m g %.6g N\n",
              z_mean, z_sd, f_mean, f_sd, mu * g.mass * gravity);
  EXPECT_NEAR(f_mean, mu * g.mass * gravity, 0.01 * mu * g.mass * gravity);
  EXPECT_NEAR(z_mean, R, 0.1 * R);  // on the sheet, not through it
}
