// Valid scenario files parse to the expected values (degrees converted,
// defaults filled in), and the resolved scenario written back as TOML parses
// to the same values. Expected numbers are the values typed in
// tests/data/scenarios/full_{2d,3d}.toml unless a comment says otherwise.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "talus/dem/contact/laws.hpp"
#include "talus/scenario/scenario.hpp"

namespace talus::io {
namespace {

using dem::DemScenario;

const std::string kData = std::string(TALUS_TEST_DATA) + "/scenarios/";

DemScenario parse_file(const std::string& name) {
  return parse_dem_scenario(load_scenario_file(kData + name, {}));
}

void expect_vec(const Vec3& actual, const Vec3& expected, double tol = 1e-12) {
  EXPECT_NEAR(actual.x(), expected.x(), tol);
  EXPECT_NEAR(actual.y(), expected.y(), tol);
  EXPECT_NEAR(actual.z(), expected.z(), tol);
}

TEST(Scenario, Full2dFileParsesToTheTypedValues) {
  const DemScenario s = parse_file("full_2d.toml");
  EXPECT_EQ(s.name, "flume_a");
  EXPECT_EQ(s.description, "Kuen 2011 model 3, geometry A");

  EXPECT_EQ(s.run.dimension, 2);
  EXPECT_DOUBLE_EQ(s.run.duration, 2.5);
  EXPECT_DOUBLE_EQ(s.run.time_step, 2e-6);
  EXPECT_DOUBLE_EQ(s.run.safety_factor, 0.5);
  expect_vec(s.run.gravity, Vec3(0, -9.81, 0));  // default gravity points down y in 2D
  expect_vec(s.run.domain_min, Vec3(-0.1, -0.1, 0));
  expect_vec(s.run.domain_max, Vec3(2.6, 1.3, 0));
  EXPECT_DOUBLE_EQ(s.run.skin, 2e-4);
  EXPECT_EQ(s.run.seed, 42u);
  EXPECT_DOUBLE_EQ(s.run.ke_blowup_factor, 50.0);

  EXPECT_EQ(s.contact.model, dem::LinearSpringDashpot::name);
  EXPECT_EQ(s.contact.rolling, dem::RollingModel::Kuen);
  EXPECT_EQ(s.contact.friction_rule, dem::PairRule::Max);
  EXPECT_FALSE(s.contact.dashpot_may_pull);
  EXPECT_DOUBLE_EQ(s.contact.kuen_wall_depth, 0.15e-3);
  EXPECT_DOUBLE_EQ(s.contact.kuen_particle_factor, 0.5);
  EXPECT_DOUBLE_EQ(s.contact.kuen_reference_step, 3.5e-6);
  // Defaults from dem/params.hpp.
  EXPECT_FALSE(s.contact.lock_rotation);
  EXPECT_DOUBLE_EQ(s.contact.local_damping, 0.0);
  EXPECT_DOUBLE_EQ(s.contact.tangential_damping, 0.3);
  EXPECT_DOUBLE_EQ(s.contact.epsd_stiffness_factor, 2.25);

  ASSERT_EQ(s.contact.pairs.size(), 1u);
  EXPECT_EQ(s.contact.pairs[0].material_a, "sand");
  EXPECT_EQ(s.contact.pairs[0].material_b, "metal");
  // Kuen: wall friction 21.7 degrees is mu = 0.398.
  EXPECT_NEAR(*s.contact.pairs[0].friction, 0.398, 5e-4);
  EXPECT_FALSE(s.contact.pairs[0].rolling_friction.has_value());
  EXPECT_FALSE(s.contact.pairs[0].restitution.has_value());

  ASSERT_EQ(s.materials.size(), 2u);
  const auto& sand = s.materials[0];
  EXPECT_EQ(sand.name, "sand");
  EXPECT_DOUBLE_EQ(sand.density, 2672.0);
  EXPECT_NEAR(sand.friction, 0.277, 5e-4);  // Kuen: 15.5 degrees is mu = 0.277
  EXPECT_DOUBLE_EQ(sand.normal_stiffness, 1e8);
  EXPECT_DOUBLE_EQ(sand.shear_stiffness, 1e8);
  EXPECT_DOUBLE_EQ(sand.damping_ratio, 0.5);
  EXPECT_DOUBLE_EQ(sand.poisson_ratio, 0.3);  // default
  const auto& metal = s.materials[1];
  EXPECT_DOUBLE_EQ(metal.density, 0.0);  // walls only: no density needed
  EXPECT_DOUBLE_EQ(metal.friction, 0.398);
  EXPECT_DOUBLE_EQ(metal.shear_stiffness, 1e8);  // defaults to normal_stiffness

  ASSERT_EQ(s.walls.size(), 3u);
  EXPECT_EQ(s.walls[0].name, "chute");
  EXPECT_EQ(s.walls[0].kind, dem::WallKind::Segment);
  EXPECT_EQ(s.walls[0].material, "metal");
  expect_vec(s.walls[0].a, Vec3(0, 1.115, 0));
  expect_vec(s.walls[0].b, Vec3(1.4486, 0.3121, 0));
  expect_vec(s.walls[0].motion.direction, Vec3::UnitY());  // vibration default: up in 2D
  EXPECT_TRUE(std::isinf(s.walls[0].motion.remove_at));
  const auto& arc = s.walls[1];
  EXPECT_EQ(arc.kind, dem::WallKind::Arc);
  expect_vec(arc.center, Vec3(1.497, 0.3995, 0));
  EXPECT_DOUBLE_EQ(arc.radius, 0.10);
  EXPECT_NEAR(arc.angle_start, 241.0 * M_PI / 180.0, 1e-12);
  EXPECT_NEAR(arc.angle_end, 303.0 * M_PI / 180.0, 1e-12);
  const auto& gate = s.walls[2].motion;
  expect_vec(gate.velocity, Vec3(0, 2.25, 0));
  EXPECT_DOUBLE_EQ(gate.move_start, 0.0);
  EXPECT_DOUBLE_EQ(gate.move_stop, 0.13);
  EXPECT_DOUBLE_EQ(gate.remove_at, 0.2);

  ASSERT_EQ(s.sources.size(), 2u);
  const auto& fill = s.sources[0];
  EXPECT_EQ(fill.kind, dem::SourceKind::RandomFill);
  EXPECT_EQ(fill.material, "sand");
  ASSERT_EQ(fill.polygon.size(), 3u);
  // Given clockwise, stored counter-clockwise: the shoelace area is positive
  // and equals Kuen's release triangle, 0.07714 m^2 (0.5 * 0.5276 * 0.2924).
  double twice_area = 0.0;
  for (std::size_t i = 0; i < 3; ++i) {
    const Vec3& p = fill.polygon[i];
    const Vec3& q = fill.polygon[(i + 1) % 3];
    twice_area += p.x() * q.y() - q.x() * p.y();
  }
  EXPECT_NEAR(0.5 * twice_area, 0.5 * 0.5276 * 0.2924, 1e-12);
  EXPECT_NEAR(0.5 * twice_area, 0.07714, 1e-5);
  expect_vec(fill.box_min, Vec3(0, 0.8226, 0));
  expect_vec(fill.box_max, Vec3(0.5276, 1.115, 0));
  EXPECT_DOUBLE_EQ(fill.radius_min, 1e-3);
  EXPECT_DOUBLE_EQ(fill.radius_max, 2e-3);
  EXPECT_DOUBLE_EQ(fill.porosity, 0.1662);
  EXPECT_DOUBLE_EQ(fill.shrink, 0.03);
  EXPECT_FALSE(fill.count.has_value());
  EXPECT_TRUE(fill.settle.enabled);
  EXPECT_DOUBLE_EQ(fill.settle.ke_ratio, 1e-6);
  EXPECT_DOUBLE_EQ(fill.settle.max_time, 3.0);
  const auto& list = s.sources[1];
  EXPECT_EQ(list.kind, dem::SourceKind::List);
  ASSERT_EQ(list.particles.size(), 1u);
  expect_vec(list.particles[0].position, Vec3(1, 1, 0));
  expect_vec(list.particles[0].velocity, Vec3(0.5, -0.25, 0));
  expect_vec(list.particles[0].angular_velocity, Vec3(0, 0, 3));  // 2D: a number about z
  EXPECT_DOUBLE_EQ(list.particles[0].radius, 1.5e-3);
  EXPECT_EQ(list.particles[0].material, "sand");
  EXPECT_FALSE(list.settle.enabled);

  EXPECT_DOUBLE_EQ(s.output.snapshot_interval, 0.05);
  EXPECT_DOUBLE_EQ(s.output.series_interval, 0.01);
  EXPECT_DOUBLE_EQ(s.output.checkpoint_interval, 0.5);
  EXPECT_FALSE(s.output.write_snapshots);
}

TEST(Scenario, Full3dFileParsesToTheTypedValuesAndDefaults) {
  const DemScenario s = parse_file("full_3d.toml");
  EXPECT_EQ(s.name, "full_3d");  // no name given: the file's stem
  EXPECT_EQ(s.run.dimension, 3);
  EXPECT_DOUBLE_EQ(s.run.time_step, 0.0);  // "auto" when not given
  EXPECT_DOUBLE_EQ(s.run.safety_factor, 0.8);
  expect_vec(s.run.gravity, Vec3(0, 0, -9.81));
  EXPECT_EQ(s.run.seed, 1u);
  EXPECT_DOUBLE_EQ(s.run.skin, 0.0);

  EXPECT_EQ(s.contact.model, dem::HertzMindlin::name);
  EXPECT_EQ(s.contact.rolling, dem::RollingModel::Epsd);
  EXPECT_EQ(s.contact.friction_rule, dem::PairRule::Harmonic);
  EXPECT_TRUE(s.contact.lock_rotation);
  EXPECT_DOUBLE_EQ(s.contact.local_damping, 0.7);
  EXPECT_DOUBLE_EQ(s.contact.tangential_damping, 0.25);
  EXPECT_DOUBLE_EQ(s.contact.epsd_stiffness_factor, 2.0);
  EXPECT_DOUBLE_EQ(s.contact.epsd_damping_ratio, 0.2);
  EXPECT_TRUE(s.contact.dashpot_may_pull);
  ASSERT_EQ(s.contact.pairs.size(), 1u);
  EXPECT_DOUBLE_EQ(*s.contact.pairs[0].friction, 0.2);
  EXPECT_DOUBLE_EQ(*s.contact.pairs[0].rolling_friction, 0.01);
  EXPECT_DOUBLE_EQ(*s.contact.pairs[0].restitution, 0.8);

  const auto& glass = s.materials[0];
  EXPECT_DOUBLE_EQ(glass.youngs_modulus, 4.8e10);
  EXPECT_DOUBLE_EQ(glass.poisson_ratio, 0.2);
  EXPECT_DOUBLE_EQ(glass.restitution, 0.9);
  EXPECT_DOUBLE_EQ(glass.rolling_friction, 0.05);
  EXPECT_DOUBLE_EQ(glass.normal_stiffness, 0.0);
  EXPECT_NEAR(s.materials[1].friction, 1.0, 1e-12);  // tan(45 degrees)

  ASSERT_EQ(s.walls.size(), 4u);
  EXPECT_EQ(s.walls[0].name, "wall0");           // default name: wall<index>
  expect_vec(s.walls[0].normal, Vec3::UnitZ());  // [0, 0, 2] normalised
  ASSERT_EQ(s.walls[1].vertices.size(), 3u);
  expect_vec(s.walls[1].vertices[2], Vec3(0, 1, 0.5));
  const auto& mesh = s.walls[2];
  EXPECT_TRUE(std::filesystem::path(mesh.file).is_absolute());
  EXPECT_TRUE(std::filesystem::equivalent(mesh.file, kData + "tiny.stl"));
  EXPECT_DOUBLE_EQ(mesh.scale, 0.001);
  expect_vec(mesh.offset, Vec3(0, 0, 0.5));
  const auto& cylinder = s.walls[3];
  EXPECT_DOUBLE_EQ(cylinder.radius, 0.5);
  EXPECT_TRUE(cylinder.inside);
  EXPECT_DOUBLE_EQ(cylinder.length, 1.0);
  EXPECT_DOUBLE_EQ(cylinder.motion.amplitude, 1e-3);
  EXPECT_DOUBLE_EQ(cylinder.motion.frequency, 50.0);
  EXPECT_NEAR(cylinder.motion.phase, M_PI / 2.0, 1e-12);  // 90 degrees
  expect_vec(cylinder.motion.angular_velocity, Vec3(0, 0, 1.5));
  expect_vec(cylinder.motion.pivot, Vec3(0, 0, 0.5));
  expect_vec(cylinder.motion.direction, Vec3::UnitZ());
  EXPECT_TRUE(std::isinf(cylinder.motion.move_stop));

  ASSERT_EQ(s.sources.size(), 3u);
  const auto& lattice = s.sources[0];
  EXPECT_EQ(lattice.kind, dem::SourceKind::Lattice);
  expect_vec(lattice.box_min, Vec3(-0.2, -0.2, 0.1));
  EXPECT_DOUBLE_EQ(lattice.spacing, 0.02);
  EXPECT_DOUBLE_EQ(lattice.radius, 0.009);
  EXPECT_EQ(lattice.jitter, "peer");
  const auto& grow = s.sources[1];
  EXPECT_EQ(grow.kind, dem::SourceKind::Grow);
  EXPECT_DOUBLE_EQ(grow.packing_fraction, 0.52);
  EXPECT_EQ(grow.count, 2000);
  EXPECT_TRUE(grow.settle.enabled);  // settle = true: default thresholds
  EXPECT_DOUBLE_EQ(grow.settle.ke_ratio, 1e-5);
  EXPECT_DOUBLE_EQ(grow.settle.max_time, 5.0);
  EXPECT_TRUE(std::filesystem::equivalent(s.sources[2].file, kData + "particles.csv"));

  // No [output] table: defaults.
  EXPECT_DOUBLE_EQ(s.output.snapshot_interval, 0.0);
  EXPECT_TRUE(s.output.write_snapshots);
}

// Field-by-field equality of two scenarios; tolerance for the degree-radian
// round trip of angles.
void expect_same(const DemScenario& a, const DemScenario& b) {
  constexpr double kTol = 1e-12;
  EXPECT_EQ(a.name, b.name);
  EXPECT_EQ(a.description, b.description);
  EXPECT_EQ(a.run.dimension, b.run.dimension);
  EXPECT_DOUBLE_EQ(a.run.duration, b.run.duration);
  EXPECT_DOUBLE_EQ(a.run.time_step, b.run.time_step);
  EXPECT_DOUBLE_EQ(a.run.safety_factor, b.run.safety_factor);
  expect_vec(a.run.gravity, b.run.gravity);
  expect_vec(a.run.domain_min, b.run.domain_min);
  expect_vec(a.run.domain_max, b.run.domain_max);
  EXPECT_DOUBLE_EQ(a.run.skin, b.run.skin);
  EXPECT_EQ(a.run.seed, b.run.seed);
  EXPECT_DOUBLE_EQ(a.run.ke_blowup_factor, b.run.ke_blowup_factor);

  const auto &ca = a.contact, &cb = b.contact;
  EXPECT_EQ(ca.model, cb.model);
  EXPECT_EQ(ca.rolling, cb.rolling);
  EXPECT_EQ(ca.friction_rule, cb.friction_rule);
  EXPECT_EQ(ca.lock_rotation, cb.lock_rotation);
  EXPECT_EQ(ca.dashpot_may_pull, cb.dashpot_may_pull);
  for (auto field :
       {&dem::ContactParams::local_damping, &dem::ContactParams::tangential_damping,
        &dem::ContactParams::kuen_wall_depth, &dem::ContactParams::kuen_particle_factor,
        &dem::ContactParams::kuen_reference_step, &dem::ContactParams::epsd_stiffness_factor,
        &dem::ContactParams::epsd_damping_ratio}) {
    EXPECT_DOUBLE_EQ(ca.*field, cb.*field);
  }
  ASSERT_EQ(ca.pairs.size(), cb.pairs.size());
  for (std::size_t i = 0; i < ca.pairs.size(); ++i) {
    EXPECT_EQ(ca.pairs[i].material_a, cb.pairs[i].material_a);
    EXPECT_EQ(ca.pairs[i].material_b, cb.pairs[i].material_b);
    EXPECT_EQ(ca.pairs[i].friction, cb.pairs[i].friction);
    EXPECT_EQ(ca.pairs[i].rolling_friction, cb.pairs[i].rolling_friction);
    EXPECT_EQ(ca.pairs[i].restitution, cb.pairs[i].restitution);
  }

  ASSERT_EQ(a.materials.size(), b.materials.size());
  for (std::size_t i = 0; i < a.materials.size(); ++i) {
    EXPECT_EQ(a.materials[i].name, b.materials[i].name);
    for (auto field :
         {&dem::MaterialParams::density, &dem::MaterialParams::youngs_modulus,
          &dem::MaterialParams::poisson_ratio, &dem::MaterialParams::restitution,
          &dem::MaterialParams::friction, &dem::MaterialParams::rolling_friction,
          &dem::MaterialParams::normal_stiffness, &dem::MaterialParams::shear_stiffness,
          &dem::MaterialParams::damping_ratio, &dem::MaterialParams::dissipation}) {
      EXPECT_DOUBLE_EQ(a.materials[i].*field, b.materials[i].*field);
    }
  }

  ASSERT_EQ(a.walls.size(), b.walls.size());
  for (std::size_t i = 0; i < a.walls.size(); ++i) {
    const auto &wa = a.walls[i], &wb = b.walls[i];
    EXPECT_EQ(wa.name, wb.name);
    EXPECT_EQ(wa.kind, wb.kind);
    EXPECT_EQ(wa.material, wb.material);
    EXPECT_EQ(wa.file, wb.file);
    EXPECT_EQ(wa.inside, wb.inside);
    for (auto field : {&dem::WallParams::a, &dem::WallParams::b, &dem::WallParams::center,
                       &dem::WallParams::point, &dem::WallParams::normal, &dem::WallParams::axis,
                       &dem::WallParams::offset}) {
      expect_vec(wa.*field, wb.*field);
    }
    ASSERT_EQ(wa.vertices.size(), wb.vertices.size());
    for (std::size_t k = 0; k < wa.vertices.size(); ++k) expect_vec(wa.vertices[k], wb.vertices[k]);
    EXPECT_NEAR(wa.angle_start, wb.angle_start, kTol);
    EXPECT_NEAR(wa.angle_end, wb.angle_end, kTol);
    EXPECT_DOUBLE_EQ(wa.radius, wb.radius);
    EXPECT_DOUBLE_EQ(wa.scale, wb.scale);
    EXPECT_EQ(wa.length, wb.length);  // may be infinite
    const auto &ma = wa.motion, &mb = wb.motion;
    for (auto field : {&dem::WallMotionParams::velocity, &dem::WallMotionParams::angular_velocity,
                       &dem::WallMotionParams::pivot, &dem::WallMotionParams::direction}) {
      expect_vec(ma.*field, mb.*field);
    }
    EXPECT_EQ(ma.move_start, mb.move_start);
    EXPECT_EQ(ma.move_stop, mb.move_stop);
    EXPECT_EQ(ma.remove_at, mb.remove_at);
    EXPECT_DOUBLE_EQ(ma.amplitude, mb.amplitude);
    EXPECT_DOUBLE_EQ(ma.frequency, mb.frequency);
    EXPECT_NEAR(ma.phase, mb.phase, kTol);
  }

  ASSERT_EQ(a.sources.size(), b.sources.size());
  for (std::size_t i = 0; i < a.sources.size(); ++i) {
    const auto &sa = a.sources[i], &sb = b.sources[i];
    EXPECT_EQ(sa.kind, sb.kind);
    EXPECT_EQ(sa.material, sb.material);
    EXPECT_EQ(sa.jitter, sb.jitter);
    EXPECT_EQ(sa.file, sb.file);
    EXPECT_EQ(sa.count, sb.count);
    expect_vec(sa.box_min, sb.box_min);
    expect_vec(sa.box_max, sb.box_max);
    ASSERT_EQ(sa.polygon.size(), sb.polygon.size());
    for (std::size_t k = 0; k < sa.polygon.size(); ++k) expect_vec(sa.polygon[k], sb.polygon[k]);
    for (auto field :
         {&dem::ParticleSourceParams::spacing, &dem::ParticleSourceParams::radius,
          &dem::ParticleSourceParams::radius_min, &dem::ParticleSourceParams::radius_max,
          &dem::ParticleSourceParams::porosity, &dem::ParticleSourceParams::packing_fraction,
          &dem::ParticleSourceParams::shrink}) {
      EXPECT_DOUBLE_EQ(sa.*field, sb.*field);
    }
    EXPECT_EQ(sa.settle.enabled, sb.settle.enabled);
    EXPECT_DOUBLE_EQ(sa.settle.ke_ratio, sb.settle.ke_ratio);
    EXPECT_DOUBLE_EQ(sa.settle.max_time, sb.settle.max_time);
    ASSERT_EQ(sa.particles.size(), sb.particles.size());
    for (std::size_t k = 0; k < sa.particles.size(); ++k) {
      expect_vec(sa.particles[k].position, sb.particles[k].position);
      expect_vec(sa.particles[k].velocity, sb.particles[k].velocity);
      expect_vec(sa.particles[k].angular_velocity, sb.particles[k].angular_velocity);
      EXPECT_DOUBLE_EQ(sa.particles[k].radius, sb.particles[k].radius);
      EXPECT_EQ(sa.particles[k].material, sb.particles[k].material);
    }
  }

  EXPECT_DOUBLE_EQ(a.output.snapshot_interval, b.output.snapshot_interval);
  EXPECT_DOUBLE_EQ(a.output.series_interval, b.output.series_interval);
  EXPECT_DOUBLE_EQ(a.output.checkpoint_interval, b.output.checkpoint_interval);
  EXPECT_EQ(a.output.write_snapshots, b.output.write_snapshots);
}

class RoundTrip : public testing::TestWithParam<std::string> {};

TEST_P(RoundTrip, WrittenTomlParsesBackToTheSameValues) {
  const DemScenario original = parse_file(GetParam());
  const std::string text = scenario_to_toml(original);
  // Written somewhere else than the data folder: file paths must be absolute.
  const DemScenario again = parse_dem_scenario(load_scenario_text(text, "/tmp/elsewhere/x.toml"));
  SCOPED_TRACE(text);
  expect_same(original, again);
}

INSTANTIATE_TEST_SUITE_P(Scenario, RoundTrip,
                         testing::Values("full_2d.toml", "full_3d.toml", "flume_2d.toml"));

// Found by the scenario fuzzer (tests/fuzz/regressions/set_value_control_character):
// text with control characters must be escaped in the resolved scenario.
TEST(Scenario, ControlCharactersInTextSurviveTheResolvedFile) {
  const char raw[] = "tab\there, nul \0, bell \a, del \x7F, \"q\" \\";
  const std::string text(raw, sizeof raw - 1);
  auto file = load_scenario_file(kData + "full_2d.toml", {});
  file.table.insert_or_assign("description", text);
  const DemScenario original = parse_dem_scenario(file);
  const std::string written = scenario_to_toml(original);
  const DemScenario again =
      parse_dem_scenario(load_scenario_text(written, "/tmp/elsewhere/x.toml"));
  EXPECT_EQ(again.description, text);
}

TEST(Scenario, JsonHasTheResolvedValuesWithAnglesInDegrees) {
  const nlohmann::json j2 = scenario_to_json(parse_file("full_2d.toml"));
  EXPECT_EQ(j2["method"], "dem");
  EXPECT_EQ(j2["run"]["dimension"], 2);
  EXPECT_DOUBLE_EQ(j2["run"]["time_step"].get<double>(), 2e-6);
  EXPECT_EQ(j2["run"]["gravity"].size(), 2u);  // 2D vectors are written as [x, y]
  EXPECT_EQ(j2["contact"]["model"], "linear");
  EXPECT_NEAR(j2["walls"][1]["angle_start"].get<double>(), 241.0, 1e-10);
  EXPECT_NEAR(j2["materials"][0]["friction"].get<double>(), std::tan(15.5 * M_PI / 180.0), 1e-15);
  EXPECT_EQ(j2["walls"][2]["motion"]["stop"], 0.13);
  // A static wall writes no motion at all (full_2d.toml, wall 0).
  EXPECT_FALSE(j2["walls"][0].contains("motion"));

  const nlohmann::json j3 = scenario_to_json(parse_file("full_3d.toml"));
  EXPECT_EQ(j3["run"]["time_step"], "auto");
  EXPECT_NEAR(j3["walls"][3]["motion"]["phase"].get<double>(), 90.0, 1e-10);
  // A motion without an end writes no "stop" (full_3d.toml, wall 3).
  EXPECT_FALSE(j3["walls"][3]["motion"].contains("stop"));
  EXPECT_EQ(j3["particles"][1]["count"], 2000);
}

TEST(Scenario, ExampleInTheFormatDocumentationIsValid) {
  std::ifstream in(std::string(TALUS_SOURCE_DIR) + "/docs/scenario-format.md");
  ASSERT_TRUE(in);
  std::stringstream doc;
  doc << in.rdbuf();
  const std::string text = doc.str();
  const auto begin = text.find("```toml\n", text.find("## Example"));
  ASSERT_NE(begin, std::string::npos);
  const auto end = text.find("```", begin + 8);
  const std::string example = text.substr(begin + 8, end - begin - 8);
  const DemScenario s = parse_dem_scenario(load_scenario_text(example, "example.toml"));
  EXPECT_EQ(s.name, "mini_flume");
  EXPECT_EQ(s.walls.size(), 2u);
  EXPECT_NEAR(s.materials[0].friction, 0.277, 5e-4);  // Kuen: 15.5 degrees is mu = 0.277
}

}  // namespace
}  // namespace talus::io
