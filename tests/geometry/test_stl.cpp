// STL reading (ASCII and binary, hand-written files) and write/read round trips.
#include <gtest/gtest.h>
#include <unistd.h>

#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>

#include "talus/core/error.hpp"
#include "talus/geometry/stl.hpp"

namespace talus::geometry {
namespace {

// A file name unique to this test (ctest runs tests in parallel processes).
std::string temp_file(const std::string& suffix) {
  const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
  return (std::filesystem::path(::testing::TempDir()) /
          ("talus_geom_" + std::string(info->name()) + "_" + std::to_string(getpid()) + suffix))
      .string();
}

std::string write_file(const std::string& suffix, const std::string& content) {
  const std::string path = temp_file(suffix);
  std::ofstream(path, std::ios::binary) << content;
  return path;
}

void expect_vec(const Vec3& got, const Vec3& want, double tol = 1e-12) {
  EXPECT_NEAR((got - want).norm(), 0.0, tol) << got.transpose() << " vs " << want.transpose();
}

// Normals are recomputed: the first facet's stored normal is deliberately zero.
const char* kTwoFacets = R"(solid two
  facet normal 0 0 0
    outer loop
      vertex 0 0 0
      vertex 1 0 0
      vertex 0 1 0
    endloop
  endfacet
  FACET NORMAL 0 0 -1
    OUTER LOOP
      VERTEX 1.5e0 0 2
      VERTEX 0 0 2
      VERTEX 0 -1 2
    ENDLOOP
  ENDFACET
endsolid two
)";

TEST(Stl, ReadsAsciiWithScaleAndOffset) {
  const std::string path = write_file(".stl", kTwoFacets);
  const auto tris = read_stl(path, 2.0, Vec3(10, 0, 0));
  ASSERT_EQ(tris.size(), 2u);
  // Vertex v maps to 2 v + (10,0,0).
  expect_vec(tris[0].p1, Vec3(12, 0, 0));
  expect_vec(tris[0].n, Vec3(0, 0, 1));  // (1,0,0) x (0,1,0)
  expect_vec(tris[1].p0, Vec3(13, 0, 4));
  // (b - a) x (c - a) = (-1.5,0,0) x (-1.5,-1,0) = (0,0,1.5): +z, not the stored -z.
  expect_vec(tris[1].n, Vec3(0, 0, 1));
  std::filesystem::remove(path);
}

// Binary layout: 80-byte header, uint32 count, per facet 12 float32 + uint16.
std::string binary_stl(const std::vector<std::array<float, 12>>& facets, const char* header) {
  std::string data(80, '\0');
  std::memcpy(data.data(), header, std::strlen(header));
  const auto count = static_cast<std::uint32_t>(facets.size());
  data.append(reinterpret_cast<const char*>(&count), 4);
  for (const auto& f : facets) {
    data.append(reinterpret_cast<const char*>(f.data()), 48);
    data.append(2, '\0');
  }
  return data;
}

TEST(Stl, ReadsBinaryEvenWhenTheHeaderSaysSolid) {
  const std::string path = write_file(
      ".stl", binary_stl({{0, 0, 1, 0, 0, 0, 0.5f, 0, 0, 0, 0.25f, 0}}, "solid exported"));
  const auto tris = read_stl(path);
  ASSERT_EQ(tris.size(), 1u);
  expect_vec(tris[0].p1, Vec3(0.5, 0, 0));
  expect_vec(tris[0].p2, Vec3(0, 0.25, 0));
  std::filesystem::remove(path);
}

TEST(Stl, RoundTripAsciiExactBinaryToFloatPrecision) {
  std::vector<Primitive> tris(2);
  ASSERT_TRUE(
      make_triangle(Vec3(0.1, 0.2, 0.3), Vec3(1.7, -0.4, 0.25), Vec3(0.3, 2.9, -1e-3), tris[0]));
  ASSERT_TRUE(make_triangle(Vec3(-5, 4, 3), Vec3(2, 1e-7, 8), Vec3(3, 3, 3), tris[1]));
  for (bool binary : {false, true}) {
    const std::string path = temp_file(binary ? ".bin.stl" : ".ascii.stl");
    write_stl(path, tris, binary);
    const auto back = read_stl(path);
    ASSERT_EQ(back.size(), tris.size());
    // ASCII is written with 17 significant digits (exact); binary is float32.
    const double tol = binary ? 1e-6 : 0.0;
    for (std::size_t i = 0; i < tris.size(); ++i) {
      expect_vec(back[i].p0, tris[i].p0, tol * 10);
      expect_vec(back[i].p1, tris[i].p1, tol * 10);
      expect_vec(back[i].p2, tris[i].p2, tol * 10);
      expect_vec(back[i].n, tris[i].n, 1e-5);
    }
    std::filesystem::remove(path);
  }
}

TEST(Stl, DropsAndCountsDegenerateFacets) {
  const std::string path = write_file(".stl", binary_stl({{0, 0, 0, 0, 0, 0, 1, 0, 0, 0, 1, 0},
                                                          {0, 0, 0, 0, 0, 0, 1, 1, 1, 2, 2, 2}},
                                                         "degenerate"));
  std::size_t skipped = 99;
  EXPECT_EQ(read_stl(path, 1.0, Vec3::Zero(), &skipped).size(), 1u);
  EXPECT_EQ(skipped, 1u);
  std::filesystem::remove(path);
}

// The message names the file and, for ASCII, the line.
void expect_error(const std::string& content, const std::string& fragment) {
  const std::string path = write_file(".stl", content);
  try {
    read_stl(path);
    ADD_FAILURE() << "accepted: " << content;
  } catch (const InputError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find(path), std::string::npos) << what;
    EXPECT_NE(what.find(fragment), std::string::npos) << what;
  }
  std::filesystem::remove(path);
}

TEST(Stl, MalformedInputNamesFileAndLine) {
  std::string bad_number = kTwoFacets;
  bad_number.replace(bad_number.find("vertex 1 0 0"), 12, "vertex 1 x 0");
  expect_error(bad_number, ":5: expected a number, got 'x'");
  std::string two_vertices = kTwoFacets;
  two_vertices.erase(two_vertices.find("      vertex 0 1 0\n"), 19);
  expect_error(two_vertices, ":6: expected 'vertex', got 'endloop'");
  std::string truncated = kTwoFacets;
  truncated.resize(truncated.find("endsolid"));
  expect_error(truncated, "unexpected end of file");
  expect_error("solid x\n  facet normal 0 0 1\n   inner loop\n", ":3: expected 'outer'");
  expect_error("hello", "not an STL file");
  // Binary header announcing 3 facets but holding one.
  std::string short_binary = binary_stl({{0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1, 0}}, "x");
  const std::uint32_t three = 3;
  std::memcpy(short_binary.data() + 80, &three, 4);
  expect_error(short_binary, "announces 3 facets");
  EXPECT_THROW(read_stl("/nonexistent/dir/none.stl"), InputError);
}

}  // namespace
}  // namespace talus::geometry
