// One contact per touched point of a triangle mesh (geometry/mesh_contacts.hpp):
// grains over shared edges and vertices of flat meshes, and in a concave corner.
#include <gtest/gtest.h>

#include <vector>

#include "talus/geometry/mesh_contacts.hpp"

namespace talus::geometry {
namespace {

Primitive tri(const Vec3& a, const Vec3& b, const Vec3& c) {
  Primitive p;
  EXPECT_TRUE(make_triangle(a, b, c, p));
  return p;
}

// How many of the triangles touch a grain of radius r at x after the rule.
int contacts(const std::vector<Primitive>& tris, const std::vector<int>& wall, const Vec3& x,
             double r) {
  const int n = static_cast<int>(tris.size());
  std::vector<const Primitive*> prims;
  std::vector<Closest<3>> near(n);
  std::vector<char> hit(n);
  for (int k = 0; k < n; ++k) {
    prims.push_back(&tris[k]);
    hit[k] = closest_point<3>(tris[k], x, r, near[k]) && near[k].distance < r;
  }
  drop_shared_features<3>(prims.data(), wall.data(), near.data(), hit.data(), n, r);
  int count = 0;
  for (char h : hit) count += h;
  return count;
}

// A square of two triangles sharing the diagonal (0,0)-(1,1). Built inside
// each test, so that tri()'s check runs under the test framework.
std::vector<Primitive> square() {
  return {tri(Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(1, 1, 0)),
          tri(Vec3(0, 0, 0), Vec3(1, 1, 0), Vec3(0, 1, 0))};
}

TEST(MeshContacts, SharedDiagonalCountsOnce) {
  const double r = 0.1;
  // On the diagonal: both triangles give the same point (a tie).
  EXPECT_EQ(contacts(square(), {0, 0}, Vec3(0.5, 0.5, 0.09), r), 1);
  // Just inside the first triangle, near the diagonal: the second only reaches
  // its edge, farther away.
  EXPECT_EQ(contacts(square(), {0, 0}, Vec3(0.52, 0.48, 0.09), r), 1);
  // Two different walls keep their own contacts.
  EXPECT_EQ(contacts(square(), {0, 1}, Vec3(0.5, 0.5, 0.09), r), 2);
}

TEST(MeshContacts, VertexOfAFanCountsOnce) {
  std::vector<Primitive> fan;
  for (int k = 0; k < 6; ++k) {
    const double a0 = k * M_PI / 3, a1 = (k + 1) * M_PI / 3;
    fan.push_back(tri(Vec3::Zero(), Vec3(std::cos(a0), std::sin(a0), 0),
                      Vec3(std::cos(a1), std::sin(a1), 0)));
  }
  EXPECT_EQ(contacts(fan, std::vector<int>(6, 0), Vec3(0, 0, 0.09), 0.1), 1);
}

TEST(MeshContacts, ConcaveCornerKeepsBothFaces) {
  // A floor and a wall of one mesh meeting at the edge x = 0; a grain in the
  // corner touches the interior of both faces.
  const std::vector<Primitive> corner = {tri(Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0)),
                                         tri(Vec3(0, 0, 0), Vec3(0, 1, 0), Vec3(0, 0, 1))};
  EXPECT_EQ(contacts(corner, {0, 0}, Vec3(0.09, 0.3, 0.095), 0.1), 2);
}

TEST(MeshContacts, ConvexRidgeCountsOnce) {
  // Two faces folded down from the ridge y = 0 (a roof): a grain on the ridge
  // touches both at the same point of the shared edge.
  const std::vector<Primitive> roof = {tri(Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, -1)),
                                       tri(Vec3(0, 0, 0), Vec3(0, -1, -1), Vec3(1, 0, 0))};
  EXPECT_EQ(contacts(roof, {0, 0}, Vec3(0.5, 0, 0.09), 0.1), 1);
}

}  // namespace
}  // namespace talus::geometry
