// extends = "base.toml": a scenario as the difference to another one. Tables
// merge key by key, other values (arrays of tables too) replace the base's, and
// an error in a value that comes from the base names the base file.
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>

#include "scenario_cases.hpp"
#include "talus/core/error.hpp"
#include "talus/scenario/scenario.hpp"

namespace talus::io {
namespace {

namespace fs = std::filesystem;

const char* kBase = R"(method = "dem"
name = "base"
[run]
dimension = 2
duration = 1.0
[contact]
model = "linear"
rolling = "kuen"
[[materials]]
name = "sand"
density = 2672
friction = 0.3
normal_stiffness = 1e6
[[walls]]
name = "floor"
type = "segment"
material = "sand"
a = [0, 0]
b = [1, 0]
[[particles]]
type = "list"
material = "sand"
[[particles.list]]
position = [0.5, 0.5]
radius = 0.01
)";

// One folder per process and test: ctest runs the tests of this file in parallel
// processes (and other checkouts' suites may run at the same time).
fs::path folder() {
  const auto* test = ::testing::UnitTest::GetInstance()->current_test_info();
  const fs::path dir = fs::path(testing::TempDir()) /
                       ("talus_extends_" + std::to_string(::getpid()) + "_" + test->name());
  fs::create_directories(dir / "sub");
  return dir;
}

std::string write(const fs::path& path, const std::string& text) {
  std::ofstream(path) << text;
  return path.string();
}

TEST(ScenarioExtends, ChildValuesOverTheBase) {
  const fs::path dir = folder();
  write(dir / "base.toml", kBase);
  const auto child = write(dir / "sub" / "child.toml", R"(extends = "../base.toml"
name = "child"
[contact]
lock_rotation = true
[run]
duration = 2.5
)");
  const auto s = parse_dem_scenario(load_scenario_file(child, {"run.duration=3"}));
  EXPECT_EQ(s.name, "child");
  EXPECT_DOUBLE_EQ(s.run.duration, 3.0);  // --set wins over both files
  EXPECT_TRUE(s.contact.lock_rotation);
  EXPECT_EQ(s.contact.rolling, dem::RollingModel::Kuen);  // kept from the base table
  ASSERT_EQ(s.walls.size(), 1u);
  EXPECT_EQ(s.walls[0].name, "floor");
}

TEST(ScenarioExtends, ArraysOfTablesReplaceTheBase) {
  const fs::path dir = folder();
  write(dir / "base.toml", kBase);
  const auto child = write(dir / "child2.toml", R"(extends = "base.toml"
[[walls]]
name = "left"
type = "segment"
material = "sand"
a = [0, 0]
b = [0, 1]
[[walls]]
name = "right"
type = "segment"
material = "sand"
a = [1, 0]
b = [1, 1]
)");
  const auto s = parse_dem_scenario(load_scenario_file(child, {}));
  ASSERT_EQ(s.walls.size(), 2u);
  EXPECT_EQ(s.walls[0].name, "left");
  EXPECT_EQ(s.walls[1].name, "right");
}

TEST(ScenarioExtends, ErrorsNameTheFileTheValueCameFrom) {
  const fs::path dir = folder();
  std::string bad = kBase;
  bad.replace(bad.find("density = 2672"), 14, "density = -1");
  const auto base = write(dir / "bad_base.toml", bad);
  const auto child = write(dir / "child3.toml", "extends = \"bad_base.toml\"\nname = \"c\"\n");
  // density is on line 11 of the base file.
  const std::string message =
      cases::error_of([&] { parse_dem_scenario(load_scenario_file(child, {})); });
  EXPECT_NE(message.find(base + ":11:"), std::string::npos) << message;
  const auto missing = write(dir / "child4.toml", "extends = \"nowhere.toml\"\n");
  EXPECT_THROW(load_scenario_file(missing, {}), InputError);
  const auto loop = write(dir / "loop.toml", "extends = \"loop.toml\"\n");
  const std::string cycle = cases::error_of([&] { load_scenario_file(loop, {}); });
  EXPECT_NE(cycle.find("cycle"), std::string::npos) << cycle;
}

// A base names its files from its own folder; the child's own file names (and
// --set values) are relative to the child's.
TEST(ScenarioExtends, FileNamesResolveAgainstTheFileTheyAreWrittenIn) {
  const fs::path dir = folder();
  std::string base = kBase;
  base.replace(base.find("[[particles.list]]"), std::string::npos, "file = \"grains.csv\"\n");
  base.replace(base.find("type = \"list\""), 13, "type = \"file\"");
  write(dir / "grains.csv", "x,y,radius\n0.5,0.5,0.01\n");
  write(dir / "base.toml", base);
  const auto child = write(dir / "sub" / "child.toml", "extends = \"../base.toml\"\n");
  const auto s = parse_dem_scenario(load_scenario_file(child, {}));
  ASSERT_EQ(s.sources.size(), 1u);
  EXPECT_EQ(fs::path(s.sources[0].file), fs::absolute(dir / "grains.csv").lexically_normal());
  write(dir / "sub" / "grains.csv", "x,y,radius\n0.5,0.5,0.01\n");
  const auto own = parse_dem_scenario(load_scenario_file(child, {"particles.0.file=grains.csv"}));
  EXPECT_EQ(fs::path(own.sources[0].file),
            fs::absolute(dir / "sub" / "grains.csv").lexically_normal());
}

TEST(ScenarioExtends, BundledFlumeVariantsDifferOnlyWhereTheySay) {
  const std::string dir = std::string(TALUS_SOURCE_DIR) + "/scenarios/dem/";
  const auto a3 = parse_dem_scenario(load_scenario_file(dir + "flume_A_model3.toml", {}));
  const auto a1 = parse_dem_scenario(load_scenario_file(dir + "flume_A_model1.toml", {}));
  const auto c3 = parse_dem_scenario(load_scenario_file(dir + "flume_C_model3.toml", {}));
  EXPECT_TRUE(a1.contact.lock_rotation);
  EXPECT_EQ(a1.contact.rolling, dem::RollingModel::None);
  EXPECT_FALSE(a3.contact.lock_rotation);
  EXPECT_EQ(a3.contact.rolling, dem::RollingModel::Kuen);
  EXPECT_NEAR(c3.flume->shape.beta * 180 / M_PI, 61.0, 1e-12);
  EXPECT_EQ(c3.sources[0].count, a3.sources[0].count);
  EXPECT_DOUBLE_EQ(c3.materials[0].friction, a3.materials[0].friction);
  // Kuen §6 ran the particle sizes on Model 3, geometry A, variant II (gate lifted).
  for (const char* name : {"flume_A_scale2.toml", "flume_A_scale20.toml"}) {
    const auto sc = parse_dem_scenario(load_scenario_file(dir + name, {}));
    EXPECT_DOUBLE_EQ(sc.flume->shape.beta, a3.flume->shape.beta) << name;
    EXPECT_EQ(sc.contact.rolling, dem::RollingModel::Kuen) << name;
    EXPECT_TRUE(sc.flume->lift_gate) << name;
    EXPECT_DOUBLE_EQ(sc.flume->gate_speed, a3.flume->gate_speed) << name;
  }
}

}  // namespace
}  // namespace talus::io
