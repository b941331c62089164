// MPM scenario files: a valid file resolves to the expected parameters and
// reads back to the same values from its resolved form; bad input names the
// file, the line and the key. The bundled column scenario parses and builds.
#include <gtest/gtest.h>

#include "mpm_scenario_cases.hpp"
#include "talus/core/error.hpp"
#include "talus/mpm/scenario.hpp"
#include "talus/scenario/scenario_mpm.hpp"

namespace talus::io {
namespace {

using mpm_cases::edit;
using mpm_cases::expect_error;

const std::string kBase = R"(method = "mpm"
[run]
dimension = 2
duration = 0.5
gravity = [0, -10]
shape = "cubic_bspline"
[grid]
min = [0, 0]
max = [1, 0.5]
cell_size = 0.05
boundaries = { x_min = "fixed", y_min = "fixed", y_max = "free" }
[[materials]]
name = "clay"
model = "drucker_prager"
density = 2400
youngs_modulus = 21.6e6
poisson_ratio = 0.24
friction_angle = 28
cohesion = 26.7e3
critical_volume_strain = 0.01
[[bodies]]
material = "clay"
box = { min = [0, 0], max = [0.3, 0.2] }
initial_stress = "geostatic"
)";

TEST(MpmScenario, ParsesAndRoundTrips) {
  const auto sc = parse_mpm_scenario(load_scenario_text(kBase, "base.toml"));
  EXPECT_EQ(sc.dimension, 2);
  EXPECT_EQ(sc.solver.shape, mpm::ShapeKind::CubicBSpline);
  EXPECT_EQ(sc.solver.scheme, mpm::Scheme::Musl);  // default
  EXPECT_EQ(sc.grid.faces[0], mpm::BoundaryKind::Fixed);
  EXPECT_EQ(sc.grid.faces[1], mpm::BoundaryKind::Roller);  // default
  EXPECT_EQ(sc.grid.faces[3], mpm::BoundaryKind::Free);
  EXPECT_NEAR(sc.materials[0].friction_angle, 28.0 * M_PI / 180.0, 1e-15);
  EXPECT_TRUE(sc.bodies[0].geostatic);
  // Resolved k0 = nu / (1 - nu).
  EXPECT_NEAR(mpm::resolved_k0(sc.bodies[0], sc.materials[0]), 0.24 / 0.76, 1e-15);
  const std::string resolved = mpm_scenario_to_toml(sc);
  const auto again = parse_mpm_scenario(load_scenario_text(resolved, "resolved.toml"));
  EXPECT_EQ(mpm_scenario_to_json(again).dump(), mpm_scenario_to_json(sc).dump()) << resolved;
}

// k0 = 0 is a value, not "from nu": given with nu = 0.24 it stays 0, and a
// body whose nu = 0 resolves to it reads back (found by the scenario fuzzer,
// tests/fuzz/regressions/geostatic_k0_zero_from_poisson_zero).
TEST(MpmScenario, GeostaticK0OfZeroIsAValue) {
  const auto given = parse_mpm_scenario(load_scenario_text(
      edit(kBase, "initial_stress = \"geostatic\"", "initial_stress = \"geostatic\"\nk0 = 0"),
      "k0.toml"));
  EXPECT_EQ(mpm::resolved_k0(given.bodies[0], given.materials[0]), 0.0);
  const std::string nu0 = edit(kBase, "poisson_ratio = 0.24", "poisson_ratio = 0");
  const auto sc = parse_mpm_scenario(load_scenario_text(nu0, "nu0.toml"));
  EXPECT_EQ(mpm::resolved_k0(sc.bodies[0], sc.materials[0]), 0.0);
  const std::string resolved = mpm_scenario_to_toml(sc);
  const auto again = parse_mpm_scenario(load_scenario_text(resolved, "resolved.toml"));
  EXPECT_EQ(mpm::resolved_k0(again.bodies[0], again.materials[0]), 0.0);
}

TEST(MpmScenario, BadInputNamesFileLineAndKey) {
  expect_error(edit(kBase, "shape = \"cubic_bspline\"", "shape = \"quadratic\""),
               "bad.toml:6: [run] 'shape'");
  expect_error(edit(kBase, "friction_angle = 28", "friction_angle = 28\nviscosity = 1"),
               "'viscosity'");
  expect_error(edit(kBase, "cohesion = 26.7e3", "cohesoin = 26.7e3"), "did you mean 'cohesion'");
  expect_error(edit(kBase, "max = [0.3, 0.2]", "max = [1.3, 0.2]"), "[[bodies]] 'box'");
  expect_error(edit(kBase, "material = \"clay\"", "material = \"sand\""), "'material'");
  expect_error(edit(kBase, "cell_size = 0.05", "cell_size = -1"),
               "bad.toml:10: [grid] 'cell_size'");
  expect_error(edit(kBase, "x_min = \"fixed\"", "x_min = \"sticky\""), "'x_min'");
}

// A Coulomb grid face: y_min = { friction = mu } next to the named kinds;
// it reads back from the resolved file and builds; a negative or non-number
// mu, a mu-less "friction" and a bare number are refused naming the key.
TEST(MpmScenario, FrictionFaceParsesRoundTripsAndRefusesBadMu) {
  const std::string text =
      edit(edit(kBase, "y_min = \"fixed\"", "y_min = { friction = 0.3 }, x_max = \"roller\""),
           "shape = \"cubic_bspline\"", "shape = \"gimp\"");
  const auto sc = parse_mpm_scenario(load_scenario_text(text, "friction.toml"));
  EXPECT_EQ(sc.grid.faces[0], mpm::BoundaryKind::Fixed);
  EXPECT_EQ(sc.grid.faces[2], mpm::BoundaryKind::Friction);
  EXPECT_EQ(sc.grid.friction[2], 0.3);
  EXPECT_EQ(sc.grid.faces[3], mpm::BoundaryKind::Free);
  const std::string resolved = mpm_scenario_to_toml(sc);
  const auto again = parse_mpm_scenario(load_scenario_text(resolved, "resolved.toml"));
  EXPECT_EQ(mpm_scenario_to_json(again).dump(), mpm_scenario_to_json(sc).dump()) << resolved;
  EXPECT_EQ(again.grid.friction[2], 0.3);
  const auto solver = mpm::build_mpm<2>(sc);
  // The 25 nodes of y = 0 (20 cells of 0.05 m and 2 + 2 ghost columns), mu = 0.3.
  ASSERT_EQ(solver.grid.friction_nodes.size(), 25u);
  EXPECT_EQ(solver.grid.friction_nodes[0].mu, 0.3);
  expect_error(edit(text, "friction = 0.3", "friction = -0.3"),
               "bad.toml:11: [grid.boundaries.y_min] 'friction'");
  expect_error(edit(text, "friction = 0.3", "friction = \"rough\""),
               "[grid.boundaries.y_min] 'friction'");
  expect_error(edit(text, "friction = 0.3", "mu = 0.3"), "'friction'");
  expect_error(edit(text, "{ friction = 0.3 }", "\"friction\""), "'y_min'");
  expect_error(edit(text, "{ friction = 0.3 }", "0.3"), "'y_min'");
  expect_error(edit(text, "shape = \"gimp\"", "shape = \"cubic_bspline\""),
               "[grid.boundaries] 'y_min': expected \"roller\"");
  // The sea bed of the bundled bag made frictional from the command line, as
  // docs/scenario-format.md shows.
  const auto bag = parse_mpm_scenario(
      load_scenario_file(std::string(TALUS_SOURCE_DIR) + "/scenarios/mpm/mpm_geotextile_bag.toml",
                         {"grid.boundaries.y_min={friction = 0.5}"}));
  EXPECT_EQ(bag.grid.faces[2], mpm::BoundaryKind::Friction);
  EXPECT_EQ(bag.grid.friction[2], 0.5);
  EXPECT_EQ(bag.grid.faces[0], mpm::BoundaryKind::Free);
}

const std::string kRigid = R"(
[[rigid_bodies]]
box = { min = [0.1, 0.3], max = [0.9, 0.35] }
friction = 0.4
angle = 10
motion = { angular_velocity = 30, hinge = [0.5, 0.35], stop = 0.2 }
)";

TEST(MpmScenario, RigidBodiesParseRoundTripAndBuild) {
  const auto sc = parse_mpm_scenario(load_scenario_text(kBase + kRigid, "rigid.toml"));
  ASSERT_EQ(sc.rigid_bodies.size(), 1u);
  const auto& r = sc.rigid_bodies[0];
  EXPECT_EQ(r.contact, mpm::RigidContact::Friction);  // default
  EXPECT_EQ(r.friction, 0.4);
  EXPECT_NEAR(r.angle, 10.0 * M_PI / 180.0, 1e-15);                        // degrees in the file
  EXPECT_NEAR(r.motion.angular_velocity.z(), 30.0 * M_PI / 180.0, 1e-15);  // degrees per second
  EXPECT_EQ(r.motion.stop, 0.2);
  const auto again = parse_mpm_scenario(load_scenario_text(mpm_scenario_to_toml(sc), "r.toml"));
  EXPECT_EQ(mpm_scenario_to_json(again).dump(), mpm_scenario_to_json(sc).dump());
  const auto solver = mpm::build_mpm<2>(sc);
  // 16 x 1 cells of 0.05 m, 2 x 2 points each.
  ASSERT_EQ(solver.rigid_bodies[0].x.size(), 64u);
  // Points of the top layer face up, turned by the initial 10 degrees.
  const auto& body = solver.rigid_bodies[0];
  EXPECT_NEAR(body.normal[40].dot(Eigen::Vector2d(-std::sin(r.angle), std::cos(r.angle))), 1.0,
              1e-12);
  expect_error(edit(kBase + kRigid, "friction = 0.4", "contact = \"stick\"\nfriction = 0.4"),
               "'friction'");
  expect_error(edit(kBase + kRigid, "stop = 0.2", "start = 0.3, stop = 0.2"), "'stop'");
  expect_error(edit(kBase + kRigid, "max = [0.9, 0.35]", "max = [1.9, 0.35]"),
               "[[rigid_bodies]] 'box'");
  // In 2D too: a plate across the block's corner overlaps it by 0.1 m in x
  // and in y. (Resting on a plate is fine: the bundled clay block's bottom
  // y = 0 lies on its incline's top y = 0.)
  expect_error(kBase + "[[rigid_bodies]]\nbox = { min = [0.2, 0.1], max = [0.5, 0.3] }\n",
               "overlaps [[bodies]] #1 by 0.1 m");
}

// 3D rigid bodies turned about an axis (the clay block's run-out and obstacle,
// scenarios/mpm/mpm_clay_block.toml): the boundary particles and their normals
// are turned about the hinge; the turned box must lie inside the grid; a
// body one particle thick is refused (its top and bottom normals would cancel).
TEST(MpmScenario, TurnedRigidBodiesIn3D) {
  const auto file =
      load_scenario_file(std::string(TALUS_SOURCE_DIR) + "/scenarios/mpm/mpm_clay_block.toml", {});
  const auto sc = parse_mpm_scenario(file);
  ASSERT_EQ(sc.rigid_bodies.size(), 3u);
  const auto& runout = sc.rigid_bodies[1];
  EXPECT_NEAR(runout.angle, 30.0 * M_PI / 180.0, 1e-15);
  EXPECT_EQ(runout.axis, Vec3::UnitZ());
  const auto again = parse_mpm_scenario(load_scenario_text(mpm_scenario_to_toml(sc), "r.toml"));
  EXPECT_EQ(mpm_scenario_to_json(again).dump(), mpm_scenario_to_json(sc).dump());
  const auto body = mpm::build_rigid_body<3>(runout, sc.grid.cell_size);
  // Every particle lies below the turned surface through the hinge (1, 0, 0)
  // with normal (-sin 30, cos 30, 0), within the plate's 0.08 m thickness.
  const Eigen::Vector3d n(-0.5, std::sqrt(3.0) / 2.0, 0.0), hinge(1.0, 0.0, 0.0);
  std::size_t up = 0;
  for (std::size_t i = 0; i < body.x.size(); ++i) {
    const double depth = -n.dot(body.x[i] - hinge);
    EXPECT_GT(depth, 0.0);
    EXPECT_LT(depth, 0.08);
    if (body.normal[i].dot(n) > 1.0 - 1e-12) ++up;
  }
  EXPECT_GT(up, 0u);  // the top layer faces up the turned plate
  const std::string text = R"(
method = "mpm"
[run]
dimension = 3
duration = 0.1
gravity = [0.0, -10.0, 0.0]
[grid]
min = [0.0, 0.0, 0.0]
max = [1.0, 1.0, 1.0]
cell_size = 0.1
[[materials]]
name = "clay"
model = "linear_elastic"
density = 2000
youngs_modulus = 1e6
poisson_ratio = 0.3
[[bodies]]
material = "clay"
box = { min = [0.4, 0.5, 0.4], max = [0.6, 0.7, 0.6] }
[[rigid_bodies]]
box = { min = [0.1, 0.2, 0.1], max = [0.9, 0.4, 0.9] }
angle = 20
axis = [0, 0, 2]
motion = { hinge = [0.5, 0.4, 0.5] }
)";
  const auto ok = parse_mpm_scenario(load_scenario_text(text, "t.toml"));
  EXPECT_NEAR(ok.rigid_bodies[0].axis.norm(), 1.0, 1e-15);  // normalised
  expect_error(edit(text, "axis = [0, 0, 2]", "axis = [0, 0, 0]"), "'axis'");
  expect_error(edit(text, "angle = 20", "angle = 80"), "once turned by angle about the hinge");
  // Material starting inside a rigid body is refused. The plate's top face
  // through the hinge (0.5, 0.4) turned 20 deg: at the block's corner x = 0.6
  // it is at y = 0.4 + 0.1 tan 20 = 0.436, so a block from y = 0.45 clears
  // it and one from y = 0.42 does not.
  EXPECT_NO_THROW(parse_mpm_scenario(
      load_scenario_text(edit(text, "min = [0.4, 0.5, 0.4]", "min = [0.4, 0.45, 0.4]"), "t.toml")));
  expect_error(edit(text, "min = [0.4, 0.5, 0.4]", "min = [0.4, 0.42, 0.4]"),
               "'box': expected a rigid body clear of the material: it overlaps [[bodies]] #1");
  auto thin = ok.rigid_bodies[0];
  thin.max.y() = thin.min.y() + 0.1;  // one cell, one particle per cell
  thin.per_cell = 1;
  try {
    mpm::build_rigid_body<3>(thin, 0.1);
    FAIL() << "a one-particle-thick body was accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("one particle thick"), std::string::npos) << e.what();
  }
}

TEST(MpmScenario, BundledColumnBuilds) {
  const auto file = load_scenario_file(
      std::string(TALUS_SOURCE_DIR) + "/scenarios/mpm/mpm_column_collapse.toml", {});
  const auto sc = parse_mpm_scenario(file);
  const auto solver = mpm::build_mpm<2>(sc);
  // 8 cells x 2 points across 91 mm, 56 cells x 2 up 634 mm (rounded).
  EXPECT_EQ(solver.particles.size(), 16u * 111u);
}

// The transfer, smoothing and checkpoint keys, and the [flume] of an MPM
// scenario: parsed, round-tripped through the resolved file, bad
// combinations refused with the key named.
// The bundled plan-view clay block: its bed friction, normal gravity and
// non-local cohesion loss are read and round-trip; the bed is refused in 3D or
// without a value, the crack-band opening beside a critical volume strain
// (unless that is 0: switched off).
TEST(MpmScenario, PlanViewBed) {
  const auto file = load_scenario_file(
      std::string(TALUS_SOURCE_DIR) + "/scenarios/mpm/mpm_clay_block_plan_strong.toml", {});
  const auto sc = parse_mpm_scenario(file);
  EXPECT_EQ(sc.dimension, 2);
  EXPECT_EQ(sc.solver.basal_friction, 0.4);
  EXPECT_EQ(sc.solver.bed_normal_gravity, 9.7727);
  EXPECT_EQ(sc.materials[0].cohesion, 26.7e3);
  const auto again = parse_mpm_scenario(load_scenario_text(mpm_scenario_to_toml(sc), "r.toml"));
  EXPECT_EQ(mpm_scenario_to_json(again).dump(), mpm_scenario_to_json(sc).dump());
  const std::string bed = "plan_view = { basal_friction = 0.4, normal_gravity = 9.8 }\n";
  std::string in3d = edit(kBase, "dimension = 2", "dimension = 3");
  in3d = edit(in3d, "gravity = [0, -10]", "gravity = [0, 0, -10]");
  in3d = edit(in3d, "min = [0, 0]", "min = [0, 0, 0]");
  in3d = edit(in3d, "max = [1, 0.5]", "max = [1, 0.5, 0.5]");
  in3d = edit(in3d, "box = { min = [0, 0], max = [0.3, 0.2] }",
              "box = { min = [0, 0, 0], max = [0.3, 0.2, 0.2] }");
  parse_mpm_scenario(load_scenario_text(in3d, "3d.toml"));  // valid without the bed
  expect_error(edit(in3d, "shape =", bed + "shape ="), "no plan_view in dimension = 3");
  EXPECT_EQ(sc.materials[0].critical_volume_strain, 0.01);
  EXPECT_EQ(sc.materials[0].nonlocal_length, 0.02);
  const auto band = parse_mpm_scenario(
      load_scenario_text(edit(kBase, "critical_volume_strain = 0.01",
                              "critical_volume_strain = 0\ncritical_opening = 2e-4"),
                         "band.toml"));
  EXPECT_EQ(band.materials[0].critical_opening, 2e-4);
  expect_error(edit(kBase, "critical_volume_strain = 0.01",
                    "critical_volume_strain = 0.01\ncritical_opening = 2e-4"),
               "either critical_volume_strain or critical_opening");
  expect_error(edit(kBase, "critical_volume_strain = 0.01", "nonlocal_length = 0.01"),
               "'nonlocal_length'");
  const auto nonlocal = parse_mpm_scenario(
      load_scenario_text(edit(kBase, "critical_volume_strain = 0.01",
                              "critical_volume_strain = 0.01\nnonlocal_length = 0.02"),
                         "nonlocal.toml"));
  EXPECT_EQ(nonlocal.materials[0].nonlocal_length, 0.02);
  EXPECT_EQ(mpm::build_mpm<2>(nonlocal).cohesion_length, std::vector<double>{0.02});
  expect_error(edit(kBase, "shape =", "plan_view = { basal_friction = 0.4 }\nshape ="),
               "'normal_gravity'");
  expect_error(
      edit(kBase, "shape =", "plan_view = { basal_friction = -1, normal_gravity = 9.8 }\nshape ="),
      "'basal_friction'");
}

TEST(MpmScenario, TransferSmoothingCheckpointKeys) {
  const auto text =
      edit(kBase, "shape = \"cubic_bspline\"",
           "shape = \"cubic_bspline\"\ntransfer = \"apic\"\nvolumetric_smoothing = true") +
      "[output]\ncheckpoint_interval = 0.1\n";
  const auto sc = parse_mpm_scenario(load_scenario_text(text, "apic.toml"));
  EXPECT_EQ(sc.solver.transfer, mpm::Transfer::Apic);
  EXPECT_TRUE(sc.solver.volumetric_smoothing);
  EXPECT_EQ(sc.output.checkpoint_interval, 0.1);
  const auto again =
      parse_mpm_scenario(load_scenario_text(mpm_scenario_to_toml(sc), "resolved.toml"));
  EXPECT_EQ(mpm_scenario_to_json(again).dump(), mpm_scenario_to_json(sc).dump());
  // APIC needs a stencil whose inertia tensor is invertible; flip is the blend's key.
  expect_error(edit(text, "shape = \"cubic_bspline\"", "shape = \"linear\""), "'transfer'");
  expect_error(edit(text, "transfer = \"apic\"", "transfer = \"apic\"\nflip = 0.9"), "'flip'");
  expect_error(edit(text, "checkpoint_interval = 0.1", "checkpoint_interval = -1"),
               "'checkpoint_interval'");
}

const std::string kFlume = R"(method = "mpm"
[run]
dimension = 2
duration = 1.0
[grid]
min = [-0.05, 0]
max = [2.6, 1.3]
cell_size = 0.02
boundaries = { x_min = "free", x_max = "free", y_min = "free", y_max = "free" }
[[materials]]
name = "sand"
model = "mohr_coulomb"
density = 1630
youngs_modulus = 1e6
poisson_ratio = 0.3
friction_angle = 30.9
[flume]
beta = 33
arc_radius = 0.10
wall_friction = 21.7
release = { material = "sand" }
)";

TEST(MpmScenario, FlumeParsesRoundTripsAndBuilds) {
  const auto sc = parse_mpm_scenario(load_scenario_text(kFlume, "flume.toml"));
  ASSERT_TRUE(sc.flume.has_value());
  EXPECT_NEAR(sc.flume->wall_friction, 21.7 * M_PI / 180.0, 1e-15);
  EXPECT_EQ(sc.flume->release_material_index, 0);
  EXPECT_TRUE(sc.bodies.empty());  // the release fills the triangle instead
  // Kuen's Table 2 row for 33 deg, R = 0.10 (flume.hpp) is resolved into the file.
  EXPECT_GT(*sc.flume->shape.l_star, 1.0);
  const auto again =
      parse_mpm_scenario(load_scenario_text(mpm_scenario_to_toml(sc), "resolved.toml"));
  EXPECT_EQ(mpm_scenario_to_json(again).dump(), mpm_scenario_to_json(sc).dump());
  const auto solver = mpm::build_mpm<2>(sc);
  ASSERT_EQ(solver.rigid_bodies.size(), 1u);  // the bed
  EXPECT_NEAR(solver.rigid_bodies[0].friction, std::tan(21.7 * M_PI / 180.0), 1e-15);
  // Release area (flume.hpp) over the point area (10 mm spacing), within the
  // lattice cells the triangle's edges cut.
  const auto g = geometry::make_flume(sc.flume->shape);
  EXPECT_NEAR(solver.particles.size() * 1e-4, g.release_area(), 3.0 * 0.01);

  expect_error(edit(kFlume, "release = { material = \"sand\" }", ""), "'bodies'");
  expect_error(
      edit(kFlume, "release = { material = \"sand\" }", "release = { material = \"mud\" }"),
      "'material'");
  expect_error(edit(kFlume, "wall_friction = 21.7", "wall_friction = 95"), "'wall_friction'");
  // A grid that does not hold the bed is refused when the solver is built.
  const auto small = parse_mpm_scenario(
      load_scenario_text(edit(kFlume, "max = [2.6, 1.3]", "max = [2.0, 1.3]"), "small.toml"));
  EXPECT_THROW(mpm::build_mpm<2>(small), InputError);
}

}  // namespace
}  // namespace talus::io
