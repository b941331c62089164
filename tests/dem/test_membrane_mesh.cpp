// Membrane meshes (spec/membranes-and-jamming.md, Götz 2024 ch. 3-5): topology
// (Euler characteristic, closed surfaces, consistent outward orientation) and
// the particle counts the source documents use.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "talus/core/error.hpp"
#include "talus/dem/membrane/forces.hpp"
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

namespace {

// Exact rounded box: the box of sides l_i - 2r swept by a ball of radius r
// (Steiner). Subtracting from the sharp box the 12 edge grooves
// (1 - pi/4) r^2 per length of straight edge l_i - 2r and the 8 corners
// r^3 - pi r^3 / 6 gives
//   V = lx ly lz - (4 - pi) r^2 (lx + ly + lz) + (16 - 14 pi / 3) r^3,
//   A = 2 (lx ly + ly lz + lz lx) - (8 - 2 pi) r (lx + ly + lz) + (24 - 8 pi) r^2
// (r = l / 2 on a cube: pi l^3 / 6 and pi l^2, the ball; checked below).
double rounded_box_volume(const Vec3& l, double r) {
  return l.prod() - (4 - M_PI) * r * r * l.sum() + (16 - 14 * M_PI / 3) * r * r * r;
}
double rounded_box_area(const Vec3& l, double r) {
  return 2 * (l.x() * l.y() + l.y() * l.z() + l.z() * l.x()) - (8 - 2 * M_PI) * r * l.sum() +
         (24 - 8 * M_PI) * r * r;
}

std::pair<double, double> edge_length_range(const Mesh& m) {
  double lo = 1e300, hi = 0;
  for (const auto& e : m.edges) {
    const double len = (m.vertices[e.a] - m.vertices[e.b]).norm();
    lo = std::min(lo, len);
    hi = std::max(hi, len);
  }
  return {lo, hi};
}

}  // namespace

// The analytic values themselves: Steiner's formula in the box's inner sides
// (V = abc + 2r(ab+bc+ca) + pi r^2 (a+b+c) + 4/3 pi r^3, A = 2(ab+bc+ca) +
// 2 pi r (a+b+c) + 4 pi r^2) agrees with the closed forms above, and r = l/2
// on a cube is the ball.
TEST(MembraneMesh, RoundedBoxAnalyticValues) {
  const Vec3 l(0.08, 0.05, 0.4);
  const double r = 0.012, a = l.x() - 2 * r, b = l.y() - 2 * r, c = l.z() - 2 * r;
  const double steiner_v = a * b * c + 2 * r * (a * b + b * c + c * a) +
                           M_PI * r * r * (a + b + c) + 4.0 / 3.0 * M_PI * r * r * r;
  const double steiner_a =
      2 * (a * b + b * c + c * a) + 2 * M_PI * r * (a + b + c) + 4 * M_PI * r * r;
  EXPECT_NEAR(rounded_box_volume(l, r), steiner_v, 1e-15);
  EXPECT_NEAR(rounded_box_area(l, r), steiner_a, 1e-15);
  EXPECT_NEAR(rounded_box_volume(Vec3::Constant(0.1), 0.05), M_PI / 6 * 1e-3, 1e-17);
  EXPECT_NEAR(rounded_box_area(Vec3::Constant(0.1), 0.05), M_PI * 1e-2, 1e-16);
}

// Closed, consistently and outwards oriented, close to the exact surface, edge
// lengths near the spacing, for a general box, sharp edges (r = 0), a capsule-
// like box (r = half the smallest side) and a cube that is all corners (the
// equiangular cube sphere).
TEST(MembraneMesh, RoundedBoxClosedOrientedAndAccurate) {
  struct Case {
    Vec3 size;
    double r, s;
  };
  for (const Case& k :
       {Case{Vec3(0.05, 0.03, 0.02), 0.005, 0.002}, Case{Vec3(0.05, 0.03, 0.02), 0.0, 0.002},
        Case{Vec3(0.04, 0.04, 0.1), 0.02, 0.004}, Case{Vec3::Constant(0.03), 0.015, 0.002},
        Case{Vec3(0.08, 0.08, 0.4), 0.01, 0.0089}}) {
    SCOPED_TRACE(::testing::Message() << "size " << k.size.transpose() << " r " << k.r);
    const Vec3 c(0.1, -0.2, 0.3);
    const Mesh m = rounded_box(k.size, k.r, k.s, c);
    EXPECT_TRUE(m.closed());
    EXPECT_EQ(m.euler_characteristic(), 2);
    expect_every_edge_twice(m);
    EXPECT_EQ(outward_fraction(m, c), 1.0);
    // Every vertex on the exact surface: distance r from the inner box.
    const Vec3 inner = (0.5 * k.size.array() - k.r).max(0.0).matrix();
    for (const Vec3& v : m.vertices) {
      const Vec3 d = v - c, q = d.cwiseMax(-inner).cwiseMin(inner);
      if (k.r > 0)
        EXPECT_NEAR((d - q).norm(), k.r, 1e-15);
      else
        EXPECT_NEAR(((d.cwiseAbs() - 0.5 * k.size).cwiseAbs()).minCoeff(), 0.0, 1e-15);
    }
    // Edge lengths: grid intervals are within [s/2, 3s/2] by construction
    // (round(x / s) intervals, x >= s / 2), the curved ones shorter by at most
    // the corner's cube-sphere factor 2 sqrt 2 / 3; diagonals at most sqrt 2
    // times the longest interval.
    const auto [lo, hi] = edge_length_range(m);
    EXPECT_GE(lo, 0.5 * 2 * std::sqrt(2.0) / 3 * k.s);
    EXPECT_LE(hi, 1.5 * std::sqrt(2.0) * k.s);
    // Volume and area: the vertices lie on the convex exact surface, so the
    // mesh is inside it (V_mesh <= V). A triangle with edges up to c over a
    // curved part of radius r lies at most sag = c^2 / (8 r) inside it, so
    // V - V_mesh <= A_round sag, and projecting it radially onto the surface
    // enlarges it at most by (r / (r - sag))^2, so A - A_mesh <= A_round 2 sag / r;
    // A_round = 2 pi r (sum of straight edges) + 4 pi r^2 is the curved area,
    // c the longest edge. Flat parts are exact (to rounding, 1e-12).
    const double V = rounded_box_volume(k.size, k.r), A = rounded_box_area(k.size, k.r);
    const double vol = signed_volume(m);  // closed: independent of the origin
    const Vec3 straight = (k.size.array() - 2 * k.r).matrix();
    const double a_round = 2 * M_PI * k.r * straight.sum() + 4 * M_PI * k.r * k.r;
    EXPECT_LE(vol, V * (1 + 1e-12));
    EXPECT_GE(vol, V - (k.r > 0 ? a_round * hi * hi / (8 * k.r) : 1e-12 * V));
    EXPECT_NEAR(m.area(), A, k.r > 0 ? a_round * hi * hi / (4 * k.r * k.r) : 1e-12 * A);
    // Uniform pressure on the closed mesh: the forces sum to zero (the closed
    // surface integral of n vanishes, exactly for flat triangles; 1e-13 of the
    // sum of |F_i| is rounding).
    std::vector<Vec3> f(m.num_vertices(), Vec3::Zero());
    add_pressure_forces(m.triangles, -90e3, m.vertices, f);
    Vec3 net = Vec3::Zero();
    double sum_abs = 0;
    for (const Vec3& fi : f) {
      net += fi;
      sum_abs += fi.norm();
    }
    EXPECT_LT(net.norm(), 1e-13 * sum_abs);
  }
}

// The granular beam of Götz §5.2 (8 x 8 x 40 cm): spacing 8/9 cm with 1 cm
// edge radius gives 9 x 9 x 45 grid intervals, 2 (81 + 2 * 405) + 2 = 1784
// particles and 2 V - 4 = 3564 triangles, the closest this grid gets to the
// source's 1792 and 3580 (which also satisfy F = 2 V - 4).
TEST(MembraneMesh, RoundedBoxGranularBeam) {
  const Mesh m = rounded_box(Vec3(0.08, 0.08, 0.4), 0.01, 0.08 / 9);
  EXPECT_EQ(m.num_vertices(), 1784u);
  EXPECT_EQ(m.num_triangles(), 3564u);
}

TEST(MembraneMesh, RoundedBoxBadInputs) {
  const Vec3 l(0.08, 0.08, 0.4);
  EXPECT_THROW(rounded_box(Vec3(0.08, 0.0, 0.4), 0.01, 0.01), InputError);  // side 0
  EXPECT_THROW(rounded_box(l, -0.01, 0.01), InputError);                    // r < 0
  EXPECT_THROW(rounded_box(l, 0.041, 0.01), InputError);                    // r > l_min / 2
  EXPECT_THROW(rounded_box(l, 0.005, 0.01), InputError);  // pi r / 4 < s / 2: too coarse
  EXPECT_THROW(rounded_box(l, 0.039, 0.01), InputError);  // flat part 2 mm < s / 2
  EXPECT_NO_THROW(rounded_box(l, 0.04, 0.01));            // flat part exactly 0
  EXPECT_NO_THROW(rounded_box(l, 0.0, 0.01));             // sharp edges
}
