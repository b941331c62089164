// A reduced hollow sphere (Götz 2024 §4.3, spec/membranes-and-jamming.md):
// the object R_obj = 10 mm as in the source, the outer membrane at half the
// source's radius (R_out = 20 mm, frequency 8, 642 particles, stretched to
// 25 mm while the 480 grains are grown), vacuum p_vac = 90 kPa ramped from
// 10 ms to 20 ms, p_obj averaged from 25 ms to 30 ms. Two grain stiffnesses,
// 10 MPa and 1 GPa, run in about 20 s together on one thread.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "talus/analysis/hollow_sphere.hpp"
#include "talus/dem/builder.hpp"
#include "talus/dem/membrane/body.hpp"
#include "talus/dem/packing.hpp"
#include "talus/scenario/scenario.hpp"

namespace talus::dem {
namespace {

constexpr double kPvac = 9e4, kRobj = 0.01, kRout = 0.02;

const std::string kReduced = R"(method = "dem"
[run]
dimension = 3
duration = 0.03
gravity = [0, 0, 0]
seed = 2
[contact]
model = "viscoelastic_hertz"
tangential_damping = 0.3
[[materials]]
name = "grain"
density = 2000
youngs_modulus = 1e8
poisson_ratio = 0.254
friction = 0.25
dissipation = 7e-9
[[materials]]
name = "rubber"
density = 2000
youngs_modulus = 1.25e6
poisson_ratio = 0.333333333333
friction = 1.2
dissipation = 7e-9
[[particles]]
type = "grow"
material = "grain"
shell = { center = [0, 0, 0], inner_radius = 0.0102, outer_radius = 0.0247 }
radius_min = 0.0019
radius_max = 0.0021
packing_fraction = 0.27
count = 480
[[membranes]]
name = "object"
mesh = "geodesic_sphere"
radius = 0.01
frequency = 4
youngs_modulus = 1.25e6
thickness = 3e-4
density = 2000
spring_damping = 0.3
bending_stiffness = 1e-3
bending_damping = 1e-4
core_radius = 0.01
pressure = 9e4
pressure_ramp = [0.01, 0.02]
material = "rubber"
[[membranes]]
name = "outer"
mesh = "geodesic_sphere"
radius = 0.02
frequency = 8
stretch = 1.25
youngs_modulus = 1.25e6
thickness = 3e-4
density = 2000
spring_damping = 0.3
bending_stiffness = 1e-3
bending_damping = 1e-4
pressure = -9e4
pressure_ramp = [0.01, 0.02]
material = "rubber"
[hollow_sphere]
object = "object"
shell = "outer"
)";

struct Plateau {
  double p_obj = 0.0, shell_radius = 0.0;
};

// Mean p_obj from 25 ms to 30 ms, sampled every 50 steps: a single step
// sees the contact chatter of a few dozen grains on the object.
Plateau run_reduced(double youngs_modulus) {
  const auto sc = io::parse_dem_scenario(
      io::load_scenario_text(kReduced, "hollow_reduced.toml",
                             {"materials.0.youngs_modulus=" + std::to_string(youngs_modulus)}));
  auto run = build_dem<3>(sc, {});
  auto& s = run->system;
  const auto setup = analysis::make_hollow_sphere_setup(sc, s);
  run->stepper->prime();
  run->stepper->advance(std::llround(0.025 / s.dt));
  Plateau out;
  int n = 0;
  while (s.time < 0.03) {
    run->stepper->advance(50);
    out.p_obj += analysis::object_pressure(s, setup);
    out.shell_radius += analysis::shell_mean_radius(s, setup);
    ++n;
  }
  out.p_obj /= n;
  out.shell_radius /= n;
  return out;
}

TEST(HollowSphereRun, ObjectPressureIsBoundedAndRisesForSofterGrains) {
  const Plateau soft = run_reduced(1e7), stiff = run_reduced(1e9);
  for (const Plateau& p : {soft, stiff}) {
    // The grains pass the vacuum on: the object is pressed (p_obj > 0; the
    // continuum value at x = 8, nu = 0.254 is 0.63 p_vac).
    EXPECT_GT(p.p_obj, 0.0);
    // Loose force-balance bound of the brief: the outer membrane's whole
    // load p_vac 4 pi R_out^2 on the object's area.
    EXPECT_LT(p.p_obj, kPvac * (kRout / kRobj) * (kRout / kRobj));
    // Virial bound (static grains, repulsive contacts: sum_i F_ext,i . x_i
    // = -sum_contacts f_n l < 0): the object's contact pressure p_obj + p_vac
    // on the grain centres at R_obj + r_max cannot exceed p_vac on the
    // centres at R_s - r_max (R_s the membrane's mean radius; a membrane
    // below its rest radius pushes outwards, which only lowers its load).
    // 5 % for the grains not being exactly static in the plateau.
    const double r = 2.1e-3, rs = p.shell_radius;
    const double bound = kPvac * rs * rs * (rs - r) / (kRobj * kRobj * (kRobj + r)) - kPvac;
    EXPECT_LT(p.p_obj, 1.05 * bound) << "shell radius " << rs;
  }
  // The source's trend (Götz Fig. 14): softer grains press the object harder.
  EXPECT_GT(soft.p_obj, stiff.p_obj)
      << "soft " << soft.p_obj << " Pa, stiff " << stiff.p_obj << " Pa";
  std::printf("p_obj: E = 10 MPa %.0f Pa (shell %.2f mm), E = 1 GPa %.0f Pa (shell %.2f mm)\n",
              soft.p_obj, 1e3 * soft.shell_radius, stiff.p_obj, 1e3 * stiff.shell_radius);
}

// The shell region of the grains: every grown grain lies between the spheres.
TEST(HollowSpherePieces, ShellPackingStaysInTheShell) {
  Region shell;
  shell.dimension = 3;
  shell.shell_inner_radius = 0.01;
  shell.shell_outer_radius = 0.02;
  shell.box_min = Vec3::Constant(-0.02);
  shell.box_max = Vec3::Constant(0.02);
  EXPECT_NEAR(shell.area_or_volume(), 4.0 / 3.0 * M_PI * (8e-6 - 1e-6), 1e-18);
  const GrowResult g = grow_packing(shell, 1.9e-3, 2.1e-3, 0.3, 200, 5);
  ASSERT_EQ(g.particles.size(), 200u);
  for (const auto& q : g.particles) {
    const double r = q.position.norm();
    EXPECT_GE(r - q.radius, 0.01 * (1 - 1e-9));
    EXPECT_LE(r + q.radius, 0.02 * (1 + 1e-9));
    EXPECT_TRUE(shell.contains(q.position, q.radius));
  }
}

TEST(HollowSpherePieces, PressureRamp) {
  membrane::MembraneBody b;
  b.pressure = -9e4;
  b.ramp_start = 0.01;
  b.ramp_end = 0.02;
  EXPECT_EQ(membrane::pressure_at(b, 0.0), 0.0);
  EXPECT_DOUBLE_EQ(membrane::pressure_at(b, 0.015), -4.5e4);
  EXPECT_EQ(membrane::pressure_at(b, 0.03), -9e4);
  b.ramp_end = 0.0;  // no ramp: the pressure at all times
  EXPECT_EQ(membrane::pressure_at(b, 0.0), -9e4);
}

}  // namespace
}  // namespace talus::dem
