// "--set key=value" overrides on top of a scenario file, and the errors for
// overrides that do not fit the file or the schema.
#include <gtest/gtest.h>

#include <fstream>
#include <string>

#include "scenario_cases.hpp"
#include "talus/core/error.hpp"
#include "talus/scenario/scenario.hpp"

namespace talus::io {
namespace {

const std::string kFull2d = std::string(TALUS_TEST_DATA) + "/scenarios/full_2d.toml";
const std::string kFull3d = std::string(TALUS_TEST_DATA) + "/scenarios/full_3d.toml";

dem::DemScenario parse_with(const std::string& file, const std::vector<std::string>& sets) {
  return parse_dem_scenario(load_scenario_file(file, sets));
}

// The message of the InputError that parsing with these overrides throws.
std::string error_with(const std::string& file, const std::vector<std::string>& sets) {
  return cases::error_of([&] { parse_with(file, sets); });
}

TEST(Overrides, ReplaceValuesOfEveryKind) {
  const dem::DemScenario s =
      parse_with(kFull2d, {"run.duration=0.1", "name=\"custom run\"", "contact.friction_rule=min",
                           "materials.1.friction=0.25", "run.gravity=[0, -1]", "run.time_step=auto",
                           "walls.2.motion.velocity=[0, 3]", "output.snapshots=true",
                           "run.seed = 7", "run.domain.max.1=2", "particles.1.list.0.radius=2e-3",
                           "materials.0.friction_angle=45"});
  EXPECT_DOUBLE_EQ(s.run.duration, 0.1);
  EXPECT_EQ(s.name, "custom run");
  EXPECT_EQ(s.contact.friction_rule, dem::PairRule::Min);  // unquoted: taken as a string
  EXPECT_DOUBLE_EQ(s.materials[1].friction, 0.25);
  EXPECT_DOUBLE_EQ(s.run.gravity.y(), -1.0);
  EXPECT_DOUBLE_EQ(s.run.time_step, 0.0);  // "auto"
  EXPECT_DOUBLE_EQ(s.walls[2].motion.velocity.y(), 3.0);
  EXPECT_TRUE(s.output.write_snapshots);
  EXPECT_EQ(s.run.seed, 7u);
  EXPECT_DOUBLE_EQ(s.run.domain_max.y(), 2.0);  // one element of an array, by index
  EXPECT_DOUBLE_EQ(s.run.domain_max.x(), 2.6);  // the others unchanged
  EXPECT_DOUBLE_EQ(s.sources[1].particles[0].radius, 2e-3);
  EXPECT_NEAR(s.materials[0].friction, 1.0, 1e-12);  // tan(45 degrees)
  // Untouched values stay as in the file.
  EXPECT_DOUBLE_EQ(s.run.skin, 2e-4);
}

TEST(Overrides, CreateMissingTables) {
  // full_3d.toml has no [output] and no motion on its first wall.
  const dem::DemScenario s =
      parse_with(kFull3d, {"output.series_interval=0.02", "walls.0.motion.remove_at=0.3"});
  EXPECT_DOUBLE_EQ(s.output.series_interval, 0.02);
  EXPECT_DOUBLE_EQ(s.walls[0].motion.remove_at, 0.3);
}

TEST(Overrides, UnknownKeyIsReportedAsComingFromSet) {
  const std::string message = error_with(kFull2d, {"run.duraton=0.1"});
  EXPECT_NE(message.find(kFull2d + ": --set run.duraton: unknown key; did you mean 'duration'?"),
            std::string::npos)
      << message;
}

TEST(Overrides, UnknownTopLevelTable) {
  const std::string message = error_with(kFull2d, {"ouptut.snapshots=true"});
  EXPECT_NE(message.find("--set ouptut"), std::string::npos) << message;
  EXPECT_NE(message.find("did you mean 'output'?"), std::string::npos) << message;
}

TEST(Overrides, BadValueIsReportedAsComingFromSet) {
  const std::string message = error_with(kFull2d, {"materials.0.density=-3"});
  EXPECT_NE(
      message.find(kFull2d + ": --set materials.0.density: expected a positive number, got -3"),
      std::string::npos)
      << message;
}

TEST(Overrides, BadEnumNameFromSet) {
  const std::string message = error_with(kFull2d, {"contact.model=hertz"});
  EXPECT_NE(message.find("--set contact.model: expected one of"), std::string::npos) << message;
  EXPECT_NE(message.find("did you mean \"hertz_mindlin\"?"), std::string::npos) << message;
}

TEST(Overrides, ConflictWithTheFileIsReported) {
  // materials.0 has friction_angle in the file; adding friction gives both.
  const std::string message = error_with(kFull2d, {"materials.0.friction=0.3"});
  EXPECT_NE(message.find("'friction_angle': give either 'friction' or 'friction_angle'"),
            std::string::npos)
      << message;
  // The line of friction_angle in the file's first [[materials]].
  std::ifstream in(kFull2d);
  std::string line;
  int number = 0, at = 0;
  bool in_materials = false;
  while (std::getline(in, line) && at == 0) {
    ++number;
    in_materials = in_materials || line.rfind("[[materials]]", 0) == 0;
    if (in_materials && line.rfind("friction_angle", 0) == 0) at = number;
  }
  ASSERT_GT(at, 0);
  EXPECT_NE(message.find(kFull2d + ":" + std::to_string(at) + ":"), std::string::npos) << message;
}

TEST(Overrides, MalformedOverridesNameTheFileAndTheOverride) {
  struct Case {
    std::string set, expected;
  };
  for (const Case& c : std::vector<Case>{
           {"run.duration", "--set run.duration: expected key=value"},
           {"=3", "--set =3: expected key=value"},
           {"run..duration=1", "--set run..duration=1: empty key component"},
           {"materials.5.friction=0.3",
            "--set materials.5.friction=0.3: 'materials' has 2 entries, there is no entry '5'"},
           {"materials.x.friction=0.3", "there is no entry 'x'"},
           {"run.duration.x=1",
            "--set run.duration.x=1: 'run.duration' is a value, not a table"}}) {
    const std::string message = cases::error_of([&] { load_scenario_file(kFull2d, {c.set}); });
    EXPECT_EQ(message.rfind(kFull2d + ": ", 0), 0u) << "--set " << c.set << ": " << message;
    EXPECT_NE(message.find(c.expected), std::string::npos) << message;
  }
}

TEST(Overrides, MethodCanBeOverriddenAndIsChecked) {
  EXPECT_THROW(load_scenario_file(kFull2d, {"method=sph"}), InputError);
  EXPECT_EQ(load_scenario_file(kFull2d, {"method=dem"}).method, "dem");
}

}  // namespace
}  // namespace talus::io
