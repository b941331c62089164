// Membrane meshes (spec/membranes-and-jamming.md, Götz 2024 ch. 3-5): topology
// (Euler characteristic, closed surfaces, consistent outward orientation) and
// the particle counts the source documents use.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "talus/core/error.hpp"
#include "talus/dem/membrane/mesh.hpp"
#include "talus/geometry/primitive.hpp"
#include "talus/geometry/stl.hpp"

using namespace talus;
using namespace talus::dem::membrane;

namespace {

// Divergence theorem: sum over triangles of a . (b x c) / 6 is the enclosed
// volume, positive when the normals point outwards.
double signed_volume(const Mesh& m) {
  double v = 0;
  for (const auto& t : m.triangles)
    v += m.vertices[t[0]].dot(m.vertices[t[1]].cross(m.vertices[t[2]])) / 6.0;
  return v;
}

// Fraction of the triangles whose normal points away from the point c.
double outward_fraction(const Mesh& m, const Vec3& c) {
  int out = 0;
  for (const auto& t : m.triangles) {
    const Vec3 &a = m.vertices[t[0]], &b = m.vertices[t[1]], &d = m.vertices[t[2]];
    out += (b - a).cross(d - a).dot((a + b + d) / 3.0 - c) > 0;
  }
  return double(out) / m.triangles.size();
}

void expect_every_edge_twice(const Mesh& m) {
  for (const auto& e : m.edges) {
    ASSERT_TRUE(e.interior());
    // The two triangles traverse the edge in opposite directions.
    const auto& t1 = m.triangles[e.t1];
    bool reversed = false;
    for (int k = 0; k < 3; ++k) reversed |= t1[k] == e.b && t1[(k + 1) % 3] == e.a;
    EXPECT_TRUE(reversed);
  }
}

}  // namespace

// A flat sheet is a disc: V - E + F = 1; nx * ny vertices and
// 2 (nx - 1)(ny - 1) triangles, all with normal +z and equilateral.
TEST(MembraneMesh, FlatSheetTopologyAndShape) {
  const Mesh m = flat_sheet(7, 5, 1.0e-3);
  EXPECT_EQ(m.num_vertices(), 35u);
  EXPECT_EQ(m.num_triangles(), 48u);
  EXPECT_EQ(m.euler_characteristic(), 1);
  EXPECT_FALSE(m.closed());
  for (const auto& t : m.triangles) {
    const Vec3 n = (m.vertices[t[1]] - m.vertices[t[0]]).cross(m.vertices[t[2]] - m.vertices[t[0]]);
    EXPECT_GT(n.z(), 0.0);
    for (int k = 0; k < 3; ++k)
      EXPECT_NEAR((m.vertices[t[k]] - m.vertices[t[(k + 1) % 3]]).norm(), 1.0e-3, 1e-15);
  }
  // Area: 48 equilateral triangles of side 1 mm.
  EXPECT_NEAR(m.area(), 48 * std::sqrt(3.0) / 4 * 1e-6, 1e-18);
}

// Icosahedral geodesic spheres have 10 n^2 + 2 vertices, 30 n^2 edges and
// 20 n^2 triangles: the spec's outer membrane of the hollow-sphere test (2562 =
// frequency 16) and its inner one (162 = frequency 4).
TEST(MembraneMesh, GeodesicSphereCountsAndOrientation) {
  for (int n : {1, 4, 16}) {
    const Mesh m = geodesic_sphere(0.04, n, Vec3(0.1, 0.2, 0.3));
    EXPECT_EQ(m.num_vertices(), 10u * n * n + 2);
    EXPECT_EQ(m.edges.size(), 30u * n * n);
    EXPECT_EQ(m.num_triangles(), 20u * n * n);
    EXPECT_EQ(m.euler_characteristic(), 2);
    EXPECT_TRUE(m.closed());
    expect_every_edge_twice(m);
    EXPECT_EQ(outward_fraction(m, Vec3(0.1, 0.2, 0.3)), 1.0);
    for (const auto& v : m.vertices) EXPECT_NEAR((v - Vec3(0.1, 0.2, 0.3)).norm(), 0.04, 1e-15);
  }
  EXPECT_EQ(geodesic_sphere(0.04, 16).num_vertices(), 2562u);
  EXPECT_EQ(geodesic_sphere(0.01, 4).num_vertices(), 162u);
  // Inscribed polyhedron: its volume approaches 4/3 pi R^3 from below; at
  // frequency 16 the deficit is about 3 (h/R)^2 / 8 ~ 0.5 % (h ~ R / 14 the
  // edge length), so within 1 %.
  const double R = 0.04, exact = 4.0 / 3.0 * M_PI * R * R * R;
  const double v16 = signed_volume(geodesic_sphere(R, 16));
  EXPECT_LT(v16, exact);
  EXPECT_GT(v16, 0.99 * exact);
}

// The gripper membrane: lower half of a frequency-16 sphere, 1321 particles
// (spec, granular gripper), an open disc (chi = 1) whose rim is the equator
// (5 n = 80 boundary edges at z = 0).
TEST(MembraneMesh, GeodesicHemisphereIsTheGrippersMembrane) {
  const Mesh m = geodesic_hemisphere(0.04, 16);
  EXPECT_EQ(m.num_vertices(), 1321u);
  EXPECT_EQ(m.euler_characteristic(), 1);
  EXPECT_EQ(m.boundary_edges(), 80);
  for (const auto& e : m.edges)
    if (!e.interior()) {
      EXPECT_NEAR(m.vertices[e.a].z(), 0.0, 1e-12);
      EXPECT_NEAR(m.vertices[e.b].z(), 0.0, 1e-12);
    }
  for (const auto& v : m.vertices) EXPECT_LE(v.z(), 1e-12);
  EXPECT_EQ(outward_fraction(m, Vec3::Zero()), 1.0);
  EXPECT_THROW(geodesic_hemisphere(0.04, 5), InputError);
}

// Triaxial membranes of Götz Table 3 (spacing 4 mm): case 1 (R 25 mm, h 100 mm)
// has 1131 particles, case 2 (R 35 mm, h 140 mm) 2214. An open cylinder is an
// annulus (chi = 0); with caps it is a closed sphere-like surface (chi = 2).
TEST(MembraneMesh, CylinderCountsAndOrientation) {
  EXPECT_EQ(cylinder(0.025, 0.100, 0.004, false).num_vertices(), 1131u);
  EXPECT_EQ(cylinder(0.035, 0.140, 0.004, false).num_vertices(), 2214u);
  const Mesh open = cylinder(0.025, 0.1, 0.004, false);
  EXPECT_EQ(open.euler_characteristic(), 0);
  EXPECT_EQ(open.boundary_edges(), 2 * 39);
  for (const auto& t : open.triangles) {
    const Vec3 &a = open.vertices[t[0]], &b = open.vertices[t[1]], &c = open.vertices[t[2]];
    Vec3 radial = (a + b + c) / 3.0;
    radial.z() = 0;
    EXPECT_GT((b - a).cross(c - a).dot(radial), 0.0);
  }
  const Mesh closed = cylinder(0.025, 0.1, 0.004, true);
  EXPECT_EQ(closed.euler_characteristic(), 2);
  EXPECT_TRUE(closed.closed());
  expect_every_edge_twice(closed);
  // Every vertex lies on the cylinder, and the rings (39-gons) bound a prism
  // that the twisted side surface encloses: prism < V < pi R^2 h.
  const int n = 39;
  const double R = 0.025, h = 0.1;
  const double prism = 0.5 * n * R * R * std::sin(2 * M_PI / n) * h;
  EXPECT_GT(signed_volume(closed), prism);
  EXPECT_LT(signed_volume(closed), M_PI * R * R * h);
  // Cap triangles are not degenerate and not much longer than the spacing.
  for (const auto& t : closed.triangles)
    for (int k = 0; k < 3; ++k) {
      const double len = (closed.vertices[t[k]] - closed.vertices[t[(k + 1) % 3]]).norm();
      EXPECT_GT(len, 0.4 * 0.004);
      EXPECT_LT(len, 2.0 * 0.004);
    }
}

TEST(MembraneMesh, BadTopologyIsAnInputError) {
  Mesh m;
  m.vertices = {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0), Vec3(1, 1, 0)};
  m.triangles = {{0, 1, 2}, {0, 1, 3}};  // shared edge 0-1 traversed twice the same way
  EXPECT_THROW(m.build_topology(), InputError);
  m.triangles = {{0, 1, 1}};
  EXPECT_THROW(m.build_topology(), InputError);
  m.vertices.push_back(Vec3(0, 0, 1));
  m.triangles = {{0, 1, 2}, {1, 0, 3}, {1, 0, 4}};  // three triangles on edge 0-1
  EXPECT_THROW(m.build_topology(), InputError);
}

// An STL of a closed sphere (vertices repeated per facet, as STL stores them)
// merges back into the same mesh.
TEST(MembraneMesh, StlRoundTripMergesVertices) {
  const Mesh sphere = geodesic_sphere(0.01, 4);
  const std::string path = ::testing::TempDir() + "membrane_sphere.stl";
  std::vector<geometry::Primitive> facets(sphere.num_triangles());
  for (std::size_t k = 0; k < facets.size(); ++k) {
    const auto& t = sphere.triangles[k];
    ASSERT_TRUE(geometry::make_triangle(sphere.vertices[t[0]], sphere.vertices[t[1]],
                                        sphere.vertices[t[2]], facets[k]));
  }
  geometry::write_stl(path, facets, false);
  const Mesh m = read_stl_mesh(path);
  EXPECT_EQ(m.num_vertices(), 162u);
  EXPECT_EQ(m.num_triangles(), 320u);
  EXPECT_TRUE(m.closed());
  EXPECT_EQ(m.euler_characteristic(), 2);
  EXPECT_EQ(outward_fraction(m, Vec3::Zero()), 1.0);
  std::remove(path.c_str());
}
