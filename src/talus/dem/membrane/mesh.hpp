#pragma once
// Triangle meshes of DEM membranes (Götz 2024 ch. 3): the vertices are the
// membrane particles, the edges carry the stretching springs and, where two
// triangles meet, the bending elements; the triangles are the contact surfaces.
//
// Orientation: every generator returns triangles whose right-hand normals
// (p0 -> p1 -> p2) point outwards (closed meshes, cylinders) or along +z (flat
// sheets); adjacent triangles traverse a shared edge in opposite directions.
#include <array>
#include <string>
#include <vector>

#include "talus/core/space.hpp"

namespace talus::dem::membrane {

// Edge a -> b as traversed by triangle t0; t1 (if any) traverses it b -> a.
// opp0/opp1 are the vertices of t0/t1 opposite the edge, so (opp0, a, b) and
// (opp1, b, a) are the triangles (1,3,4) and (2,4,3) of Bridson's bending
// element with r3 = a, r4 = b.
struct Edge {
  int a = -1, b = -1;
  int t0 = -1, t1 = -1;  // t1 = -1 on the boundary
  int opp0 = -1, opp1 = -1;
  bool interior() const { return t1 >= 0; }
};

struct Mesh {
  std::vector<Vec3> vertices;
  std::vector<std::array<int, 3>> triangles;
  // Filled by build_topology():
  std::vector<Edge> edges;
  std::vector<std::array<int, 3>> triangle_edges;  // edge k is opposite corner k
  std::vector<int> vertex_triangle_start;          // CSR: triangles around vertex v are
  std::vector<int> vertex_triangle_list;           //   list[start[v] .. start[v + 1])

  std::size_t num_vertices() const { return vertices.size(); }
  std::size_t num_triangles() const { return triangles.size(); }

  // Edges, edge-triangle and vertex-triangle adjacency from `triangles`.
  // Throws InputError (naming `source`) for an edge shared by more than two
  // triangles, or traversed twice in the same direction (inconsistent
  // orientation), or for a triangle with a repeated vertex.
  void build_topology(const std::string& source = "membrane mesh");

  int euler_characteristic() const;
  bool closed() const;  // every edge has two triangles
  int boundary_edges() const;
  // Barycentric area of each vertex: a third of the area of every triangle
  // around it (sums to area()).
  std::vector<double> vertex_areas() const;
  double area() const;
};

// Flat sheet in the plane z = 0 on an equilateral triangular lattice: nx
// vertices per row (alternate rows shifted by spacing / 2), ny rows spaced
// spacing * sqrt(3) / 2, first vertex at the origin; normals along +z.
Mesh flat_sheet(int nx, int ny, double spacing);

// Cylinder around the z axis from z = 0 to z = height: floor(H / (spacing
// sqrt(3) / 2)) + 1 rings of floor(2 pi R / spacing) vertices, alternate rings
// rotated by half a step so that the triangles are nearly equilateral. With caps, the end discs are
// closed by concentric rings stitched to each other.
Mesh cylinder(double radius, double height, double spacing, bool caps);

// Geodesic sphere of frequency n around `centre`: each face of an icosahedron
// with vertices at the poles (0, 0, +-R) split into n^2 triangles, the new
// vertices projected onto the sphere (10 n^2 + 2 vertices).
Mesh geodesic_sphere(double radius, int frequency, const Vec3& centre = Vec3::Zero());

// The lower half (z <= centre.z) of geodesic_sphere; needs an even frequency,
// whose subdivision has an edge ring on the equator (5 n of its vertices):
// frequency 16 gives the gripper's 1321 membrane particles.
Mesh geodesic_hemisphere(double radius, int frequency, const Vec3& centre = Vec3::Zero());

// Closed box of size `size` centred on `centre` whose edges and corners are
// rounded with radius r (0 <= r <= half the smallest side; 0: sharp edges):
// the outer box's faces carry quad grids split into triangles (diagonals
// alternating), each grid point p mapped to q + r (p - q) / |p - q| with q its
// closest point on the inner box (half sides minus r). Along each axis the flat
// part gets round(flat / spacing) intervals and each rounded band
// round(pi r / (4 spacing)) intervals, spaced uniformly in angle
// (tan-spaced on the outer box), so edges and corners get the equiangular
// cube-sphere grid. Throws InputError for a spacing too coarse for the radius
// (r > 0 with pi r / 4 < spacing / 2) or a flat part shorter than half the
// spacing (but not zero): both would give triangles far shorter than the rest.
Mesh rounded_box(const Vec3& size, double edge_radius, double spacing,
                 const Vec3& centre = Vec3::Zero());

// Triangles given as vertex triples (e.g. from an STL file): vertices closer
// than `tolerance` are merged, degenerate triangles dropped, topology built.
Mesh mesh_from_triangles(const std::vector<std::array<Vec3, 3>>& triangles, double tolerance,
                         const std::string& source = "membrane mesh");

// Reads an STL file (read_stl) with the given scale and offset, merging vertices
// closer than tolerance (relative to the longest bounding-box side).
Mesh read_stl_mesh(const std::string& path, double scale = 1.0, const Vec3& offset = Vec3::Zero(),
                   double relative_tolerance = 1e-9);

}  // namespace talus::dem::membrane
