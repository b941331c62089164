// What may be read as a scenario file (issue 28, section 4): devices, pipes,
// folders and huge files are refused at once, by the file itself or as the
// base of `extends`; and an error in a file that extends another names the
// file and line where the key was written, not --set.
#include <gtest/gtest.h>
#include <unistd.h>

#include <chrono>
#include <filesystem>
#include <fstream>

#include "scenario_cases.hpp"
#include "talus/core/error.hpp"
#include "talus/scenario/scenario.hpp"

namespace talus::io {
namespace {

namespace fs = std::filesystem;
using cases::error_of;

const std::string kCollapse = std::string(TALUS_SOURCE_DIR) + "/scenarios/dem/collapse_2d.toml";

fs::path folder() {
  const auto* test = ::testing::UnitTest::GetInstance()->current_test_info();
  const fs::path dir = fs::path(testing::TempDir()) /
                       ("talus_files_" + std::to_string(::getpid()) + "_" + test->name());
  fs::create_directories(dir / "sub");
  return dir;
}

std::string write(const fs::path& path, const std::string& text) {
  std::ofstream(path) << text;
  return path.string();
}

bool contains(const std::string& text, const std::string& part) {
  return text.find(part) != std::string::npos;
}

// The message of load_scenario_file(path), which must come within seconds.
std::string load_error(const std::string& path) {
  const auto start = std::chrono::steady_clock::now();
  const std::string message = error_of([&] { load_scenario_file(path, {}); });
  EXPECT_LT(std::chrono::steady_clock::now() - start, std::chrono::seconds(2)) << path;
  return message;
}

TEST(ScenarioFiles, DevicesAndFoldersAreRefused) {
  for (const char* device : {"/dev/zero", "/dev/urandom"}) {
    const std::string message = load_error(device);
    EXPECT_TRUE(contains(message, std::string(device) + ": is not a regular file")) << message;
  }
  const fs::path dir = folder();
  EXPECT_TRUE(contains(load_error(dir.string()), "is a folder")) << load_error(dir.string());
  EXPECT_TRUE(contains(load_error((dir / "none.toml").string()), "does not exist"));
}

TEST(ScenarioFiles, FilesOver16MiBAreRefused) {
  const fs::path dir = folder();
  const std::string big = write(dir / "big.toml", "method = \"dem\"\n");
  fs::resize_file(big, (16u << 20) + 1);  // sparse: no 16 MiB written
  const std::string message = load_error(big);
  EXPECT_TRUE(contains(message, big + ": has 16777217 bytes")) << message;
  EXPECT_TRUE(contains(message, "16 MiB")) << message;
  const std::string child = write(dir / "child.toml", "extends = \"big.toml\"\n");
  EXPECT_TRUE(contains(load_error(child), "16 MiB")) << load_error(child);
}

TEST(ScenarioFiles, ExtendsNeedsARegularFile) {
  const fs::path dir = folder();
  const std::vector<std::pair<std::string, std::string>> cases = {
      {"/dev/zero", "base scenario /dev/zero is not a regular file"},
      {"/dev/urandom", "base scenario /dev/urandom is not a regular file"},
      {".", "is a folder"},
      {"sub", "is a folder"},
      {"", "expected the path of a base scenario file, got \"\""},
      {"nowhere.toml", "does not exist"}};
  for (const auto& [base, expected] : cases) {
    const std::string child =
        write(dir / "child.toml", "name = \"c\"\nextends = \"" + base + "\"\n");
    const std::string message = load_error(child);
    EXPECT_TRUE(contains(message, child + ":2: 'extends': ")) << message;
    EXPECT_TRUE(contains(message, expected)) << message;
  }
}

TEST(ScenarioFiles, ErrorsInAChildNameItsFileAndLine) {
  const fs::path dir = folder();
  // The report of issue 28: a typo in a table the base also has.
  const std::string child =
      write(dir / "c.toml", "extends = \"" + kCollapse + "\"\nname = \"c\"\n[run]\nduraton = 1\n");
  std::string message = error_of([&] { parse_dem_scenario(load_scenario_file(child, {})); });
  EXPECT_TRUE(contains(message, child + ":4: [run] 'duraton': unknown key")) << message;
  EXPECT_FALSE(contains(message, "--set")) << message;

  // A bad value in a table the base does not have, and in an array of tables
  // that replaces the base's.
  write(dir / "c2.toml", "extends = \"" + kCollapse + "\"\n[contact]\nlock_rotation = 3\n");
  message =
      error_of([&] { parse_dem_scenario(load_scenario_file((dir / "c2.toml").string(), {})); });
  EXPECT_TRUE(contains(message, "c2.toml:3: [contact] 'lock_rotation'")) << message;
  const std::string walls = write(dir / "c3.toml", "extends = \"" + kCollapse +
                                                       "\"\n[[walls]]\nname = \"floor\"\n"
                                                       "type = \"segment\"\nmaterial = \"stone\"\n"
                                                       "a = [0, 0]\nb = [1, 0]\n");
  message = error_of([&] { parse_dem_scenario(load_scenario_file(walls, {})); });
  EXPECT_TRUE(contains(message, walls + ":5: [[walls]] 'material'")) << message;

  // Values from the base still name the base, and --set still names --set.
  const std::string good = write(dir / "good.toml", "extends = \"" + kCollapse + "\"\n");
  message = error_of([&] { parse_dem_scenario(load_scenario_file(good, {"run.duraton=2"})); });
  EXPECT_TRUE(contains(message, good + ": --set run.duraton: unknown key")) << message;
  message =
      error_of([&] { parse_dem_scenario(load_scenario_file(good, {"materials.0.density=-1"})); });
  EXPECT_TRUE(contains(message, "--set materials.0.density")) << message;
  const std::string nested = write(dir / "sub" / "n.toml", "extends = \"../c2.toml\"\n");
  message = error_of([&] { parse_dem_scenario(load_scenario_file(nested, {})); });
  EXPECT_TRUE(contains(message, "c2.toml:3: [contact] 'lock_rotation'")) << message;
}

TEST(ScenarioFiles, ChildValuesStillWin) {
  const fs::path dir = folder();
  const std::string child =
      write(dir / "c.toml", "extends = \"" + kCollapse + "\"\n[run]\nduration = 0.25\n[output]\n" +
                                "snapshots = false\n");
  const auto s = parse_dem_scenario(load_scenario_file(child, {}));
  EXPECT_DOUBLE_EQ(s.run.duration, 0.25);
  EXPECT_FALSE(s.output.write_snapshots);
  EXPECT_DOUBLE_EQ(s.output.snapshot_interval, 0.05);  // from the base's [output]
  EXPECT_EQ(s.walls.size(), 3u);
}

}  // namespace
}  // namespace talus::io
