// Checkpoint archive: exact round trips, and every kind of damage is an InputError.
#include <gtest/gtest.h>
#include <unistd.h>

#include <array>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <limits>

#include "talus/core/error.hpp"
#include "talus/core/space.hpp"
#include "talus/io/archive.hpp"

namespace fs = std::filesystem;
using talus::Vec3;
using talus::io::ArchiveReader;
using talus::io::ArchiveWriter;

namespace {

struct Plain {  // a trivially copyable record, as a solver might store
  int32_t step;
  double time;
  bool operator==(const Plain&) const = default;
};

class ArchiveTest : public ::testing::Test {
 protected:
  void SetUp() override {
    const auto* test = ::testing::UnitTest::GetInstance()->current_test_info();
    dir_ = fs::temp_directory_path() /
           ("talus_archive_" + std::to_string(::getpid()) + "_" + test->name());
    fs::remove_all(dir_);
    fs::create_directories(dir_);
    path_ = dir_ / "checkpoint.bin";
  }
  void TearDown() override { fs::remove_all(dir_); }

  std::string bytes() const {
    std::ifstream in(path_, std::ios::binary);
    return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
  }
  void overwrite(const std::string& content) const {
    std::ofstream(path_, std::ios::binary | std::ios::trunc) << content;
  }
  // The InputError message of opening the archive, or "" when it opens.
  std::string open_error() const {
    try {
      ArchiveReader reader(path_);
    } catch (const talus::InputError& error) {
      return error.what();
    }
    return "";
  }
  void save_sample() const {
    ArchiveWriter writer;
    writer.put(int64_t{42});
    writer.put(std::vector<double>(100, 1.5));
    writer.save(path_);
  }

  fs::path dir_, path_;
};

TEST_F(ArchiveTest, RoundTripsManyTypesExactly) {
  const std::vector<Vec3> positions{{0.1, 0.2, 0.3}, {-1e300, 5e-324, 7.0}};
  const Eigen::Matrix3d rotation = (Eigen::Matrix3d() << 1, 2, 3, 4, 5, 6, 7, 8, 9).finished();
  ArchiveWriter writer;
  writer.put(int32_t{-7});
  writer.put(uint64_t{std::numeric_limits<uint64_t>::max()});
  writer.put(0.1);
  writer.put(std::numeric_limits<double>::quiet_NaN());
  writer.put(Plain{3, 2.5});
  writer.put(std::array<double, 3>{1, 2, 3});
  writer.put(Vec3(1.0 / 3.0, 2, 3));
  writer.put(Eigen::Vector2d(4, 5));
  writer.put(rotation);
  writer.put(std::vector<double>{1.5, -2.5});
  writer.put(std::vector<int>{});
  writer.put(positions);
  writer.put(std::vector<Plain>{{1, 0.5}, {2, 1.5}});
  writer.put(std::string("scenario = \"flume\"\n\0binary", 27));
  writer.put("");
  writer.save(path_);

  ArchiveReader reader(path_);
  EXPECT_EQ(reader.get<int32_t>(), -7);
  EXPECT_EQ(reader.get<uint64_t>(), std::numeric_limits<uint64_t>::max());
  EXPECT_EQ(reader.get<double>(), 0.1);
  EXPECT_TRUE(std::isnan(reader.get<double>()));
  EXPECT_EQ(reader.get<Plain>(), (Plain{3, 2.5}));
  EXPECT_EQ((reader.get<std::array<double, 3>>()), (std::array<double, 3>{1, 2, 3}));
  EXPECT_EQ(reader.get<Vec3>(), Vec3(1.0 / 3.0, 2, 3));
  EXPECT_EQ(reader.get<Eigen::Vector2d>(), Eigen::Vector2d(4, 5));
  EXPECT_EQ(reader.get<Eigen::Matrix3d>(), rotation);
  EXPECT_EQ(reader.get<std::vector<double>>(), (std::vector<double>{1.5, -2.5}));
  EXPECT_TRUE(reader.get<std::vector<int>>().empty());
  EXPECT_EQ(reader.get<std::vector<Vec3>>(), positions);
  EXPECT_EQ(reader.get<std::vector<Plain>>(), (std::vector<Plain>{{1, 0.5}, {2, 1.5}}));
  EXPECT_EQ(reader.get<std::string>(), std::string("scenario = \"flume\"\n\0binary", 27));
  EXPECT_FALSE(reader.at_end());
  EXPECT_EQ(reader.get<std::string>(), "");
  EXPECT_TRUE(reader.at_end());
  EXPECT_THROW(reader.get<int>(), talus::InputError);  // nothing left
}

TEST_F(ArchiveTest, SaveReplacesTheFileAtomically) {
  save_sample();
  ArchiveWriter second;
  second.put(std::string("second"));
  second.save(path_);
  EXPECT_FALSE(fs::exists(path_.string() + ".tmp"));
  EXPECT_EQ(ArchiveReader(path_).get<std::string>(), "second");
  EXPECT_THROW(second.save(dir_ / "missing" / "folder" / "c.bin"), talus::RunError);
}

TEST_F(ArchiveTest, MissingFileIsAnInputErrorNamingIt) {
  fs::remove(path_);
  EXPECT_NE(open_error().find(path_.string()), std::string::npos);
}

TEST_F(ArchiveTest, FlippedByteIsDetected) {
  save_sample();
  std::string content = bytes();
  content[content.size() / 2] ^= 0x10;  // inside the vector of 1.5
  overwrite(content);
  EXPECT_NE(open_error().find("checksum"), std::string::npos);
}

TEST_F(ArchiveTest, TruncatedOrPaddedFileIsDetected) {
  save_sample();
  const std::string content = bytes();
  overwrite(content.substr(0, content.size() - 1));
  EXPECT_NE(open_error().find("truncated"), std::string::npos);
  overwrite(content.substr(0, 10));  // not even a whole header
  EXPECT_NE(open_error().find("bad header"), std::string::npos);
  overwrite(content + "x");
  EXPECT_NE(open_error().find("trailing"), std::string::npos);
  overwrite("");
  EXPECT_NE(open_error().find("bad header"), std::string::npos);
}

TEST_F(ArchiveTest, OtherFormatVersionIsRejected) {
  save_sample();
  std::string content = bytes();
  content[8] = 99;  // the u32 version follows the 8-byte magic
  overwrite(content);
  EXPECT_NE(open_error().find("version 99"), std::string::npos) << open_error();
}

TEST_F(ArchiveTest, ReadingOutOfStepIsDetected) {
  save_sample();  // int64_t, then std::vector<double>
  {
    ArchiveReader reader(path_);
    EXPECT_THROW(reader.get<double>(), talus::InputError);  // same size, other type
  }
  {
    ArchiveReader reader(path_);
    EXPECT_THROW(reader.get<int32_t>(), talus::InputError);  // wrong element size
  }
  {
    ArchiveReader reader(path_);
    EXPECT_EQ(reader.get<int64_t>(), 42);
    EXPECT_THROW(reader.get<double>(), talus::InputError);  // a vector read as a scalar
  }
  {
    ArchiveReader reader(path_);
    reader.get<int64_t>();
    EXPECT_THROW(reader.get<std::vector<float>>(), talus::InputError);  // wrong element type size
  }
}

}  // namespace
