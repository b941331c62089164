// PvdSeries and CsvSeries: files on disk, collections, and truncation on resume.
// tests/io/vtk_readback.py checks that VTK itself reads the .vtu files.
#include <gtest/gtest.h>
#include <unistd.h>

#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <stdexcept>

#include "talus/core/error.hpp"
#include "talus/io/csv_writer.hpp"
#include "talus/io/vtk_writer.hpp"

namespace fs = std::filesystem;
using talus::io::CsvSeries;
using talus::io::ParticleFrame;
using talus::io::PvdSeries;
using talus::io::WallFrame;

namespace {

class WritersTest : public ::testing::Test {
 protected:
  void SetUp() override {
    const auto* test = ::testing::UnitTest::GetInstance()->current_test_info();
    dir_ = fs::temp_directory_path() /
           ("talus_writers_" + std::to_string(::getpid()) + "_" + test->name());
    fs::remove_all(dir_);
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }
  fs::path dir_;
};

std::string read_text(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

// The text between `key="` and the next quote, searching from `from`.
std::string quoted_after(const std::string& text, const std::string& key, std::size_t from) {
  const std::size_t start = text.find(key + "=\"", from) + key.size() + 2;
  return text.substr(start, text.find('"', start) - start);
}

// (time, file) of every DataSet of a .pvd, in file order.
std::vector<std::pair<double, std::string>> collection(const fs::path& pvd) {
  const std::string xml = read_text(pvd);
  std::vector<std::pair<double, std::string>> out;
  for (auto at = xml.find("<DataSet"); at != std::string::npos; at = xml.find("<DataSet", at + 1)) {
    out.emplace_back(std::strtod(quoted_after(xml, "timestep", at).c_str(), nullptr),
                     quoted_after(xml, "file", at));
  }
  return out;
}

// The raw bytes of one appended array of a .vtu: the offset attribute points
// past the '_' marker to a UInt64 byte count followed by the data.
template <class T>
std::vector<T> appended_array(const fs::path& vtu, const std::string& name) {
  const std::string file = read_text(vtu);
  const std::size_t declared = file.find("Name=\"" + name + "\"");
  if (declared == std::string::npos) return {};
  const std::size_t start = file.find("encoding=\"raw\">") + 15;
  const std::size_t base =
      file.find('_', start) + 1 + std::stoull(quoted_after(file, "offset", declared));
  uint64_t bytes = 0;
  std::memcpy(&bytes, file.data() + base, sizeof(bytes));
  std::vector<T> values(bytes / sizeof(T));
  std::memcpy(values.data(), file.data() + base + sizeof(bytes), bytes);
  return values;
}

ParticleFrame particles(int n, double t) {
  ParticleFrame frame;
  for (int i = 0; i < n; ++i) {
    frame.position.emplace_back(i, t, 0.0);
    frame.velocity.emplace_back(t, -i, 0.0);
    frame.angular_velocity.emplace_back(0.0, 0.0, i);
    frame.radius.push_back(0.1 * (i + 1));
    frame.id.push_back(i);
    frame.material.push_back(0);
    frame.contacts.push_back(i % 3);
  }
  return frame;
}

TEST_F(WritersTest, PvdListsEveryFrameWithItsTime) {
  PvdSeries series(dir_, "particles");
  const std::vector<double> times{0.0, 0.1, 0.25};
  for (std::size_t k = 0; k < times.size(); ++k) {
    series.add(times[k], particles(4, times[k]));
    // The collection is complete after each frame, not only at the end.
    EXPECT_EQ(collection(dir_ / "particles.pvd").size(), k + 1);
  }
  const auto listed = collection(dir_ / "particles.pvd");
  ASSERT_EQ(listed.size(), 3u);
  for (std::size_t k = 0; k < 3; ++k) {
    // Times are printed as shortest round-trip text, so they compare exactly.
    EXPECT_EQ(listed[k].first, times[k]);
    EXPECT_EQ(listed[k].second, "particles_00000" + std::to_string(k) + ".vtu");
    EXPECT_TRUE(fs::exists(dir_ / listed[k].second));
  }
  EXPECT_FALSE(fs::exists(dir_ / "particles.pvd.tmp"));
}

TEST_F(WritersTest, VtuHoldsTheParticleArraysVerbatim) {
  PvdSeries series(dir_, "particles");
  ParticleFrame frame = particles(3, 0.5);
  frame.extra_scalars["layer"] = {1.0, 2.0, 3.0};
  series.add(0.5, frame);
  const fs::path vtu = dir_ / "particles_000000.vtu";
  const std::string text = read_text(vtu);
  EXPECT_NE(text.find("NumberOfPoints=\"3\" NumberOfCells=\"3\""), std::string::npos);
  EXPECT_NE(text.find("header_type=\"UInt64\""), std::string::npos);
  // Expected values: particles() above, radius 0.1 (i + 1), velocity (t, -i, 0).
  EXPECT_EQ(appended_array<double>(vtu, "radius"),
            (std::vector<double>{0.1, 0.2, 0.30000000000000004}));
  EXPECT_EQ(appended_array<double>(vtu, "velocity"),
            (std::vector<double>{0.5, 0, 0, 0.5, -1, 0, 0.5, -2, 0}));
  EXPECT_EQ(appended_array<int64_t>(vtu, "id"), (std::vector<int64_t>{0, 1, 2}));
  EXPECT_EQ(appended_array<int>(vtu, "contacts"), (std::vector<int>{0, 1, 2}));
  EXPECT_EQ(appended_array<double>(vtu, "layer"), (std::vector<double>{1, 2, 3}));
  EXPECT_EQ(appended_array<uint8_t>(vtu, "types"), (std::vector<uint8_t>{1, 1, 1}));  // VTK_VERTEX
}

TEST_F(WritersTest, WallFrameWritesLinesThenTrianglesWithWallIndex) {
  PvdSeries series(dir_, "walls");
  WallFrame walls;
  walls.points = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}};
  walls.lines = {{0, 1}, {2, 3}};
  walls.line_wall = {4, 5};
  walls.triangles = {{0, 1, 2}};
  walls.triangle_wall = {6};
  series.add(0.0, walls);
  const fs::path vtu = dir_ / "walls_000000.vtu";
  EXPECT_NE(read_text(vtu).find("NumberOfPoints=\"4\" NumberOfCells=\"3\""), std::string::npos);
  // VTK_LINE = 3, VTK_TRIANGLE = 5; offsets are the running ends of the cells.
  EXPECT_EQ(appended_array<uint8_t>(vtu, "types"), (std::vector<uint8_t>{3, 3, 5}));
  EXPECT_EQ(appended_array<int64_t>(vtu, "offsets"), (std::vector<int64_t>{2, 4, 7}));
  EXPECT_EQ(appended_array<int64_t>(vtu, "connectivity"),
            (std::vector<int64_t>{0, 1, 2, 3, 0, 1, 2}));
  EXPECT_EQ(appended_array<int>(vtu, "wall"), (std::vector<int>{4, 5, 6}));

  walls.triangles = {{0, 1, 4}};  // point 4 does not exist
  EXPECT_THROW(series.add(1.0, walls), std::invalid_argument);
}

TEST_F(WritersTest, MismatchedParticleArraysAreRejected) {
  PvdSeries series(dir_, "particles");
  ParticleFrame frame = particles(3, 0.0);
  frame.radius.pop_back();
  EXPECT_THROW(series.add(0.0, frame), std::invalid_argument);
  frame = particles(3, 0.0);
  frame.extra_scalars["layer"] = {1.0};
  EXPECT_THROW(series.add(0.0, frame), std::invalid_argument);
  EXPECT_TRUE(series.entries().empty());
}

TEST_F(WritersTest, TruncateAfterDropsLaterFramesAndTheirFiles) {
  PvdSeries series(dir_, "particles");
  for (double t : {0.0, 1.0, 2.0, 3.0}) series.add(t, particles(2, t));
  series.truncate_after(1.0);
  const auto listed = collection(dir_ / "particles.pvd");
  ASSERT_EQ(listed.size(), 2u);
  EXPECT_EQ(listed[1].first, 1.0);
  EXPECT_TRUE(fs::exists(dir_ / "particles_000001.vtu"));
  EXPECT_FALSE(fs::exists(dir_ / "particles_000002.vtu"));
  EXPECT_FALSE(fs::exists(dir_ / "particles_000003.vtu"));
  // The next frame takes the first freed number, as in an uninterrupted run.
  series.add(2.0, particles(2, 2.0));
  EXPECT_EQ(collection(dir_ / "particles.pvd").back().second, "particles_000002.vtu");
}

TEST_F(WritersTest, ResumeContinuesTheCollectionOnDisk) {
  {
    PvdSeries first_run(dir_, "particles");
    for (double t : {0.0, 0.1, 0.2, 0.30000000000000004}) first_run.add(t, particles(2, t));
  }
  PvdSeries resumed(dir_, "particles", /*resume=*/true);
  ASSERT_EQ(resumed.entries().size(), 4u);
  EXPECT_EQ(resumed.entries()[3].time, 0.30000000000000004);  // read back exactly
  resumed.truncate_after(0.2);                                // checkpoint at t = 0.2
  resumed.add(0.3, particles(2, 0.3));
  const auto listed = collection(dir_ / "particles.pvd");
  ASSERT_EQ(listed.size(), 4u);
  EXPECT_EQ(listed[3].first, 0.3);
  EXPECT_EQ(listed[3].second, "particles_000003.vtu");

  // A fresh series in the same folder starts an empty collection at once.
  PvdSeries fresh(dir_, "particles");
  EXPECT_TRUE(collection(dir_ / "particles.pvd").empty());
}

TEST_F(WritersTest, ResumeRejectsABrokenCollection) {
  std::ofstream(dir_ / "particles.pvd")
      << "<VTKFile type=\"Collection\">\n<Collection>\n"
         "<DataSet timestep=\"abc\" file=\"particles_000000.vtu\"/>\n</Collection></VTKFile>\n";
  try {
    PvdSeries resumed(dir_, "particles", true);
    FAIL() << "expected InputError";
  } catch (const talus::InputError& error) {
    EXPECT_NE(std::string(error.what()).find("particles.pvd:3"), std::string::npos) << error.what();
  }
}

TEST_F(WritersTest, CsvRowsReadBackExactly) {
  const std::vector<double> values{0.1, 1.0 / 3.0, -2.5e10, 1e-300, 123456789.0};
  {
    CsvSeries csv(dir_ / "series.csv", {"time", "a", "b", "c", "d"}, false);
    csv.row(values);
    csv.row({1, 2, 3, 4, 5});
    csv.flush();
    EXPECT_THROW((csv.row({1, 2})), std::invalid_argument);
  }
  std::ifstream in(dir_ / "series.csv");
  std::string header, line;
  std::getline(in, header);
  EXPECT_EQ(header, "time,a,b,c,d");
  std::getline(in, line);
  char* cursor = line.data();
  for (double expected : values) {
    EXPECT_EQ(std::strtod(cursor, &cursor), expected);  // bit-exact round trip
    if (*cursor == ',') ++cursor;
  }
  std::getline(in, line);
  EXPECT_EQ(line, "1,2,3,4,5");
}

TEST_F(WritersTest, CsvAppendContinuesWithoutASecondHeader) {
  const fs::path path = dir_ / "series.csv";
  CsvSeries(path, {"time", "x"}, false).row({0.0, 1.0});
  CsvSeries(path, {"time", "x"}, true).row({1.0, 2.0});
  EXPECT_EQ(read_text(path), "time,x\n0,1\n1,2\n");
  EXPECT_THROW((CsvSeries(path, {"time", "y"}, true)), talus::RunError);
  CsvSeries(dir_ / "new.csv", {"time"}, true).row({5.0});  // append to nothing: header first
  EXPECT_EQ(read_text(dir_ / "new.csv"), "time\n5\n");
}

TEST_F(WritersTest, CsvTruncateKeepsHeaderAndEarlierRows) {
  const fs::path path = dir_ / "series.csv";
  // The last row is torn, as by a run killed while writing it.
  std::ofstream(path) << "time,x\n0,10\n0.5,11\n1,12\n1.5,13\n2,1";
  CsvSeries::truncate_after(path, 1.0);
  EXPECT_EQ(read_text(path), "time,x\n0,10\n0.5,11\n1,12\n");
  CsvSeries::truncate_after(path, -1.0);
  EXPECT_EQ(read_text(path), "time,x\n");
  CsvSeries::truncate_after(dir_ / "missing.csv", 1.0);  // nothing to do
  EXPECT_FALSE(fs::exists(dir_ / "missing.csv"));

  std::ofstream(path) << "time,x\n0,1\nzero,2\n";
  try {
    CsvSeries::truncate_after(path, 1.0);
    FAIL() << "expected InputError";
  } catch (const talus::InputError& error) {
    EXPECT_NE(std::string(error.what()).find("series.csv:3"), std::string::npos) << error.what();
  }
}

TEST_F(WritersTest, CsvAppendDropsATornLastRow) {
  const fs::path path = dir_ / "series.csv";
  std::ofstream(path) << "time,x\n0,1\n1,2";
  CsvSeries(path, {"time", "x"}, true).row({1.0, 3.0});
  EXPECT_EQ(read_text(path), "time,x\n0,1\n1,3\n");
}

TEST_F(WritersTest, CsvIoFailureIsARunError) {
  EXPECT_THROW((CsvSeries(dir_ / "no" / "such" / "dir.csv", {"time"}, false)), talus::RunError);
  if (fs::exists("/dev/full")) {  // a device that accepts opening but not writing
    CsvSeries full("/dev/full", {"time"}, false);
    full.row({1.0});
    EXPECT_THROW(full.flush(), talus::RunError);
  }
}

// A table written once appears whole at close() or not at all (issue 28 §3:
// a full disk left a cut file behind without a word).
TEST_F(WritersTest, CsvWholeTableAppearsOnlyWhenClosed) {
  const fs::path path = dir_ / "deposit.csv", temp = dir_ / "deposit.csv.tmp";
  {
    auto table = CsvSeries::whole(path, {"s", "depth"});
    table.row({0.5, 0.1});
    EXPECT_FALSE(fs::exists(path));
    table.close();
  }
  EXPECT_EQ(read_text(path), "s,depth\n0.5,0.1\n");
  EXPECT_FALSE(fs::exists(temp));
  {
    auto interrupted = CsvSeries::whole(path, {"s", "depth"});
    interrupted.row({9.0, 9.0});
  }  // an exception on the way: the old file stays, no temporary file
  EXPECT_EQ(read_text(path), "s,depth\n0.5,0.1\n");
  EXPECT_FALSE(fs::exists(temp));
}

}  // namespace
