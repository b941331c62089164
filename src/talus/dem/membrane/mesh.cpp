#include "talus/dem/membrane/mesh.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <unordered_map>

#include "talus/core/error.hpp"
#include "talus/geometry/stl.hpp"

namespace talus::dem::membrane {

namespace {

uint64_t edge_key(int i, int j) {
  const auto lo = static_cast<uint64_t>(std::min(i, j)), hi = static_cast<uint64_t>(std::max(i, j));
  return (lo << 32) | hi;
}

// Vertices closer than tol become one (uniform hash grid of cell 2 tol,
// neighbouring cells searched); returns the new index of every input point.
std::vector<int> merge_points(const std::vector<Vec3>& points, double tol,
                              std::vector<Vec3>& merged) {
  const double cell = 2.0 * tol;
  auto cell_of = [&](const Vec3& p) {
    return Eigen::Vector3i(static_cast<int>(std::floor(p.x() / cell)),
                           static_cast<int>(std::floor(p.y() / cell)),
                           static_cast<int>(std::floor(p.z() / cell)));
  };
  auto hash = [](const Eigen::Vector3i& c) {
    return (static_cast<uint64_t>(static_cast<uint32_t>(c.x())) * 73856093ULL) ^
           (static_cast<uint64_t>(static_cast<uint32_t>(c.y())) * 19349663ULL) ^
           (static_cast<uint64_t>(static_cast<uint32_t>(c.z())) * 83492791ULL);
  };
  std::unordered_multimap<uint64_t, int> grid;  // cell hash -> merged index
  std::vector<int> index(points.size());
  merged.clear();
  for (std::size_t k = 0; k < points.size(); ++k) {
    const Vec3& p = points[k];
    const Eigen::Vector3i c = cell_of(p);
    int found = -1;
    for (int dx = -1; dx <= 1 && found < 0; ++dx)
      for (int dy = -1; dy <= 1 && found < 0; ++dy)
        for (int dz = -1; dz <= 1 && found < 0; ++dz) {
          auto range = grid.equal_range(hash(c + Eigen::Vector3i(dx, dy, dz)));
          for (auto it = range.first; it != range.second; ++it)
            if ((merged[it->second] - p).norm() <= tol) {
              found = it->second;
              break;
            }
        }
    if (found < 0) {
      found = static_cast<int>(merged.size());
      merged.push_back(p);
      grid.emplace(hash(c), found);
    }
    index[k] = found;
  }
  return index;
}

// Triangulates the annulus between two closed rings of vertices ordered by
// increasing angle about the z axis: always advance along the ring whose next
// vertex comes first in angle. `up`: normals along +z.
void stitch_rings(const std::vector<int>& inner, const std::vector<int>& outer,
                  const std::vector<Vec3>& v, bool up, std::vector<std::array<int, 3>>& tris) {
  auto angle = [&](int i) { return std::atan2(v[i].y(), v[i].x()); };
  const double a0 = angle(inner[0]);
  auto unwrap = [&](double a) {  // into [a0 - pi, a0 + pi)
    while (a < a0 - M_PI) a += 2 * M_PI;
    while (a >= a0 + M_PI) a -= 2 * M_PI;
    return a;
  };
  const int na = static_cast<int>(inner.size()), nb = static_cast<int>(outer.size());
  int k0 = 0;
  for (int k = 1; k < nb; ++k)
    if (std::abs(unwrap(angle(outer[k])) - a0) < std::abs(unwrap(angle(outer[k0])) - a0)) k0 = k;
  const double b0 = unwrap(angle(outer[k0]));
  auto after = [](double start, double a) {  // start + (a - start) mod 2 pi
    const double d = std::fmod(a - start, 2 * M_PI);
    return start + (d < 0 ? d + 2 * M_PI : d);
  };
  auto a_at = [&](int i) { return i == na ? a0 + 2 * M_PI : after(a0, angle(inner[i])); };
  auto b_at = [&](int k) {
    return k == nb ? b0 + 2 * M_PI : after(b0, angle(outer[(k0 + k) % nb]));
  };
  auto emit = [&](int p, int q, int r) {
    tris.push_back(up ? std::array<int, 3>{p, q, r} : std::array<int, 3>{p, r, q});
  };
  int i = 0, k = 0;
  while (i < na || k < nb) {
    const int ai = inner[i % na], bk = outer[(k0 + k) % nb];
    if (i == na || (k < nb && b_at(k + 1) <= a_at(i + 1))) {
      emit(ai, bk, outer[(k0 + k + 1) % nb]);
      ++k;
    } else {
      emit(ai, bk, inner[(i + 1) % na]);
      ++i;
    }
  }
}

// Closes the ring (ordered by angle, at height z) with concentric rings and a
// centre vertex.
void add_cap(const std::vector<int>& rim, double radius, double z, double spacing, bool up,
             std::vector<Vec3>& v, std::vector<std::array<int, 3>>& tris) {
  const int n = static_cast<int>(rim.size());
  const int m = std::max(1, static_cast<int>(std::lround(radius / spacing)));
  const int centre = static_cast<int>(v.size());
  v.emplace_back(0.0, 0.0, z);
  std::vector<int> inner{centre};
  for (int j = 1; j <= m; ++j) {
    std::vector<int> ring;
    if (j == m) {
      ring = rim;
    } else {
      const int nj = std::max(3, static_cast<int>(std::lround(double(n) * j / m)));
      const double r = radius * j / m, offset = (j % 2) * M_PI / nj;
      for (int i = 0; i < nj; ++i) {
        ring.push_back(static_cast<int>(v.size()));
        const double phi = 2 * M_PI * i / nj + offset;
        v.emplace_back(r * std::cos(phi), r * std::sin(phi), z);
      }
    }
    if (j == 1) {
      const int nj = static_cast<int>(ring.size());
      for (int i = 0; i < nj; ++i)
        tris.push_back(up ? std::array<int, 3>{centre, ring[i], ring[(i + 1) % nj]}
                          : std::array<int, 3>{centre, ring[(i + 1) % nj], ring[i]});
    } else {
      stitch_rings(inner, ring, v, up, tris);
    }
    inner = ring;
  }
}

// Triangles between row `lo` and row `hi` (index(i, row)) of a lattice whose
// odd rows are shifted by half a step; `periodic` wraps i (cylinders).
template <class Index>
void lattice_strip(int n, int row, bool periodic, Index index,
                   std::vector<std::array<int, 3>>& tris) {
  const int last = periodic ? n : n - 1;
  for (int i = 0; i < last; ++i) {
    const int i1 = (i + 1) % n;
    if (row % 2 == 0) {
      tris.push_back({index(i, row), index(i1, row), index(i, row + 1)});
      tris.push_back({index(i1, row), index(i1, row + 1), index(i, row + 1)});
    } else {
      tris.push_back({index(i, row), index(i1, row + 1), index(i, row + 1)});
      tris.push_back({index(i, row), index(i1, row), index(i1, row + 1)});
    }
  }
}

}  // namespace

void Mesh::build_topology(const std::string& source) {
  edges.clear();
  triangle_edges.assign(triangles.size(), {-1, -1, -1});
  std::unordered_map<uint64_t, int> edge_index;
  edge_index.reserve(triangles.size() * 2);
  const int nv = static_cast<int>(vertices.size());
  for (std::size_t t = 0; t < triangles.size(); ++t) {
    const auto& tri = triangles[t];
    for (int c : tri)
      if (c < 0 || c >= nv)
        throw InputError(source + ": triangle " + std::to_string(t) + " has no vertex " +
                         std::to_string(c));
    if (tri[0] == tri[1] || tri[1] == tri[2] || tri[0] == tri[2])
      throw InputError(source + ": triangle " + std::to_string(t) + " repeats a vertex");
    for (int k = 0; k < 3; ++k) {
      const int from = tri[(k + 1) % 3], to = tri[(k + 2) % 3];
      auto [it, fresh] = edge_index.emplace(edge_key(from, to), static_cast<int>(edges.size()));
      if (fresh) {
        edges.push_back({from, to, static_cast<int>(t), -1, tri[k], -1});
      } else {
        Edge& e = edges[it->second];
        if (e.t1 >= 0)
          throw InputError(source + ": edge " + std::to_string(from) + "-" + std::to_string(to) +
                           " is shared by more than two triangles (non-manifold)");
        if (e.a == from)
          throw InputError(source + ": triangles " + std::to_string(e.t0) + " and " +
                           std::to_string(t) +
                           " traverse a shared edge in the same direction "
                           "(inconsistent orientation)");
        e.t1 = static_cast<int>(t);
        e.opp1 = tri[k];
      }
      triangle_edges[t][k] = it->second;
    }
  }
  vertex_triangle_start.assign(vertices.size() + 1, 0);
  for (const auto& tri : triangles)
    for (int c : tri) ++vertex_triangle_start[c + 1];
  for (std::size_t v = 0; v < vertices.size(); ++v)
    vertex_triangle_start[v + 1] += vertex_triangle_start[v];
  vertex_triangle_list.assign(vertex_triangle_start.back(), -1);
  std::vector<int> fill(vertex_triangle_start.begin(), vertex_triangle_start.end() - 1);
  for (std::size_t t = 0; t < triangles.size(); ++t)
    for (int c : triangles[t]) vertex_triangle_list[fill[c]++] = static_cast<int>(t);
}

int Mesh::euler_characteristic() const {
  return static_cast<int>(vertices.size()) - static_cast<int>(edges.size()) +
         static_cast<int>(triangles.size());
}

int Mesh::boundary_edges() const {
  return static_cast<int>(
      std::count_if(edges.begin(), edges.end(), [](const Edge& e) { return !e.interior(); }));
}

bool Mesh::closed() const { return !edges.empty() && boundary_edges() == 0; }

std::vector<double> Mesh::vertex_areas() const {
  std::vector<double> a(vertices.size(), 0.0);
  for (const auto& t : triangles) {
    const double third =
        (vertices[t[1]] - vertices[t[0]]).cross(vertices[t[2]] - vertices[t[0]]).norm() / 6.0;
    for (int c : t) a[c] += third;
  }
  return a;
}

double Mesh::area() const {
  double sum = 0.0;
  for (double a : vertex_areas()) sum += a;
  return sum;
}

Mesh flat_sheet(int nx, int ny, double spacing) {
  if (nx < 2 || ny < 2 || !(spacing > 0))
    throw InputError("flat_sheet: needs nx, ny >= 2 and spacing > 0");
  Mesh m;
  const double h = spacing * std::sqrt(3.0) / 2.0;
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i) m.vertices.emplace_back(spacing * (i + 0.5 * (j % 2)), h * j, 0);
  auto index = [nx](int i, int j) { return j * nx + i; };
  for (int j = 0; j + 1 < ny; ++j) lattice_strip(nx, j, false, index, m.triangles);
  m.build_topology("flat_sheet");
  return m;
}

Mesh cylinder(double radius, double height, double spacing, bool caps) {
  if (!(radius > 0) || !(height > 0) || !(spacing > 0))
    throw InputError("cylinder: radius, height and spacing must be > 0");
  Mesh m;
  // Rounded down, as Götz's triaxial membranes (1131 = 39 x 29 and 2214 = 54 x 41
  // particles for R 25 and 35 mm, heights 100 and 140 mm, spacing 4 mm).
  const int n = std::max(3, static_cast<int>(std::floor(2 * M_PI * radius / spacing)));
  const int rings =
      1 + std::max(1, static_cast<int>(std::floor(height / (spacing * std::sqrt(3.0) / 2))));
  for (int k = 0; k < rings; ++k) {
    const double z = height * k / (rings - 1), offset = (k % 2) * M_PI / n;
    for (int i = 0; i < n; ++i) {
      const double phi = 2 * M_PI * i / n + offset;
      m.vertices.emplace_back(radius * std::cos(phi), radius * std::sin(phi), z);
    }
  }
  auto index = [n](int i, int k) { return k * n + i; };
  for (int k = 0; k + 1 < rings; ++k) lattice_strip(n, k, true, index, m.triangles);
  if (caps) {
    std::vector<int> bottom, top;
    for (int i = 0; i < n; ++i) {
      bottom.push_back(index(i, 0));
      top.push_back(index(i, rings - 1));
    }
    add_cap(bottom, radius, 0.0, spacing, false, m.vertices, m.triangles);
    add_cap(top, radius, height, spacing, true, m.vertices, m.triangles);
  }
  m.build_topology("cylinder");
  return m;
}

Mesh geodesic_sphere(double radius, int frequency, const Vec3& centre) {
  if (!(radius > 0) || frequency < 1)
    throw InputError("geodesic_sphere: radius must be > 0 and frequency >= 1");
  // Icosahedron with vertices at the poles and two rings of five at z = +-1/sqrt 5.
  std::vector<Vec3> ico{Vec3(0, 0, 1), Vec3(0, 0, -1)};
  const double zr = 1.0 / std::sqrt(5.0), rr = 2.0 / std::sqrt(5.0);
  for (int k = 0; k < 5; ++k)
    ico.emplace_back(rr * std::cos(0.4 * M_PI * k), rr * std::sin(0.4 * M_PI * k), zr);
  for (int k = 0; k < 5; ++k)
    ico.emplace_back(rr * std::cos(0.4 * M_PI * (k + 0.5)), rr * std::sin(0.4 * M_PI * (k + 0.5)),
                     -zr);
  std::vector<std::array<int, 3>> faces;
  for (int k = 0; k < 5; ++k) {
    const int u0 = 2 + k, u1 = 2 + (k + 1) % 5, l0 = 7 + k, l1 = 7 + (k + 1) % 5;
    faces.push_back({0, u0, u1});
    faces.push_back({u0, l0, u1});
    faces.push_back({u1, l0, l1});
    faces.push_back({1, l1, l0});
  }
  const int n = frequency;
  std::vector<Vec3> points;
  std::vector<std::array<int, 3>> tris;
  for (auto f : faces) {
    const Vec3 &A0 = ico[f[0]], &B0 = ico[f[1]], &C0 = ico[f[2]];
    if ((B0 - A0).cross(C0 - A0).dot(A0 + B0 + C0) < 0) std::swap(f[1], f[2]);  // outwards
    const Vec3 &A = ico[f[0]], &B = ico[f[1]], &C = ico[f[2]];
    const int base = static_cast<int>(points.size());
    std::vector<int> row_start;  // P(i, j) = base + row_start[j] + i, i + j <= n
    for (int j = 0, count = 0; j <= n; ++j) {
      row_start.push_back(count);
      for (int i = 0; i + j <= n; ++i, ++count)
        points.push_back((A + (double(i) / n) * (B - A) + (double(j) / n) * (C - A)).normalized());
    }
    auto P = [&](int i, int j) { return base + row_start[j] + i; };
    for (int j = 0; j < n; ++j)
      for (int i = 0; i + j < n; ++i) {
        tris.push_back({P(i, j), P(i + 1, j), P(i, j + 1)});
        if (i + j + 1 < n) tris.push_back({P(i + 1, j), P(i + 1, j + 1), P(i, j + 1)});
      }
  }
  Mesh m;
  const std::vector<int> index = merge_points(points, 1e-9, m.vertices);
  for (auto& t : tris) m.triangles.push_back({index[t[0]], index[t[1]], index[t[2]]});
  for (auto& v : m.vertices) v = centre + radius * v;
  m.build_topology("geodesic_sphere");
  return m;
}

Mesh geodesic_hemisphere(double radius, int frequency, const Vec3& centre) {
  if (frequency % 2 != 0)
    throw InputError("geodesic_hemisphere: the frequency must be even (equator edge ring)");
  const Mesh full = geodesic_sphere(radius, frequency, centre);
  const double tol = 1e-9 * radius;
  std::vector<int> index(full.vertices.size(), -1);
  Mesh m;
  for (const auto& t : full.triangles) {
    if (full.vertices[t[0]].z() > centre.z() + tol || full.vertices[t[1]].z() > centre.z() + tol ||
        full.vertices[t[2]].z() > centre.z() + tol)
      continue;
    std::array<int, 3> nt;
    for (int k = 0; k < 3; ++k) {
      int& id = index[t[k]];
      if (id < 0) {
        id = static_cast<int>(m.vertices.size());
        m.vertices.push_back(full.vertices[t[k]]);
      }
      nt[k] = id;
    }
    m.triangles.push_back(nt);
  }
  m.build_topology("geodesic_hemisphere");
  return m;
}

namespace {

// Outer-box coordinates of the grid lines along one axis of a rounded box with
// half side `half`: the flat part [-a, a] (a = half - r) in equal intervals,
// each band [a, half] at a + r tan(theta), theta uniform in [0, pi / 4].
std::vector<double> box_axis_nodes(double half, double r, double spacing, const char* axis) {
  const double a = half - r, tol = 1e-12 * half;
  if (a > tol && 2 * a < 0.5 * spacing)
    throw InputError(fmt::format(
        "rounded_box: the flat part of the {} side ({} m) is shorter than half the spacing "
        "({} m); use an edge radius of half that side or a smaller spacing",
        axis, 2 * a, spacing));
  const int flat = a > tol ? std::max(1, static_cast<int>(std::lround(2 * a / spacing))) : 0;
  const int band = r > 0 ? std::max(1, static_cast<int>(std::lround(M_PI * r / (4 * spacing)))) : 0;
  std::vector<double> t;
  for (int k = band; k >= 1; --k) t.push_back(-(a + r * std::tan(M_PI / 4 * k / band)));
  for (int k = 0; k <= flat; ++k) t.push_back(flat == 0 ? 0.0 : -a + 2 * a * k / flat);
  for (int k = 1; k <= band; ++k) t.push_back(a + r * std::tan(M_PI / 4 * k / band));
  t.front() = -half;  // exactly on the outer box, so that faces share their rims
  t.back() = half;
  return t;
}

}  // namespace

Mesh rounded_box(const Vec3& size, double edge_radius, double spacing, const Vec3& centre) {
  if (!(size.minCoeff() > 0) || !(spacing > 0) || !(edge_radius >= 0))
    throw InputError("rounded_box: the sides and the spacing must be > 0, the edge radius >= 0");
  const double r = edge_radius;
  if (r > 0.5 * size.minCoeff() * (1 + 1e-12))
    throw InputError(
        fmt::format("rounded_box: edge radius {} m is larger than half the smallest "
                    "side ({} m)",
                    r, 0.5 * size.minCoeff()));
  if (r > 0 && M_PI * r / 4 < 0.5 * spacing)
    throw InputError(
        fmt::format("rounded_box: spacing {} m is too coarse for edge radius {} m "
                    "(needs spacing <= pi r / 2 = {} m)",
                    spacing, r, M_PI * r / 2));
  const Vec3 half = 0.5 * size, inner = (half.array() - r).max(0.0).matrix();
  std::array<std::vector<double>, 3> nodes;
  for (int d = 0; d < 3; ++d)
    nodes[d] = box_axis_nodes(half[d], r, spacing, d == 0 ? "x" : d == 1 ? "y" : "z");
  // The rounded surface point of outer-box point p.
  auto round_point = [&](const Vec3& p) {
    const Vec3 q = p.cwiseMax(-inner).cwiseMin(inner), d = p - q;
    const double n = d.norm();
    return Vec3(n > 0 ? Vec3(q + r * d / n) : q);
  };
  std::vector<Vec3> points;
  std::vector<std::array<int, 3>> tris;
  for (int k = 0; k < 3; ++k)
    for (const double sign : {-1.0, 1.0}) {
      // (i, j, k) cyclic, so e_i x e_j = e_k: counterclockwise in (i, j) is
      // outwards on the + face.
      const int i = (k + 1) % 3, j = (k + 2) % 3;
      const int ni = static_cast<int>(nodes[i].size()), nj = static_cast<int>(nodes[j].size());
      const int base = static_cast<int>(points.size());
      for (int b = 0; b < nj; ++b)
        for (int a = 0; a < ni; ++a) {
          Vec3 p;
          p[i] = nodes[i][a];
          p[j] = nodes[j][b];
          p[k] = sign * half[k];
          points.push_back(round_point(p));
        }
      auto P = [&](int a, int b) { return base + b * ni + a; };
      auto emit = [&](int p0, int p1, int p2) {
        tris.push_back(sign > 0 ? std::array<int, 3>{p0, p1, p2} : std::array<int, 3>{p0, p2, p1});
      };
      for (int b = 0; b + 1 < nj; ++b)
        for (int a = 0; a + 1 < ni; ++a) {
          // Alternating diagonals: no preferred direction in the spring network.
          if ((a + b) % 2 == 0) {
            emit(P(a, b), P(a + 1, b), P(a + 1, b + 1));
            emit(P(a, b), P(a + 1, b + 1), P(a, b + 1));
          } else {
            emit(P(a, b), P(a + 1, b), P(a, b + 1));
            emit(P(a + 1, b), P(a + 1, b + 1), P(a, b + 1));
          }
        }
    }
  Mesh m;
  const std::vector<int> index = merge_points(points, 1e-9 * size.maxCoeff(), m.vertices);
  // Only the faces' shared rims merge (the map is one-to-one on the outer box),
  // so no triangle collapses; build_topology would reject one that did.
  for (const auto& t : tris) m.triangles.push_back({index[t[0]], index[t[1]], index[t[2]]});
  for (Vec3& v : m.vertices) v += centre;
  m.build_topology("rounded_box");
  return m;
}

Mesh mesh_from_triangles(const std::vector<std::array<Vec3, 3>>& triangles, double tolerance,
                         const std::string& source) {
  std::vector<Vec3> points;
  points.reserve(3 * triangles.size());
  for (const auto& t : triangles) points.insert(points.end(), t.begin(), t.end());
  Mesh m;
  const std::vector<int> index = merge_points(points, tolerance, m.vertices);
  for (std::size_t t = 0; t < triangles.size(); ++t) {
    const std::array<int, 3> tri{index[3 * t], index[3 * t + 1], index[3 * t + 2]};
    if (tri[0] != tri[1] && tri[1] != tri[2] && tri[0] != tri[2]) m.triangles.push_back(tri);
  }
  m.build_topology(source);
  return m;
}

Mesh read_stl_mesh(const std::string& path, double scale, const Vec3& offset,
                   double relative_tolerance) {
  const auto prims = geometry::read_stl(path, scale, offset);
  std::vector<std::array<Vec3, 3>> tris;
  Vec3 lo = Vec3::Constant(geometry::kInf), hi = -lo;
  for (const auto& p : prims) {
    tris.push_back({p.p0, p.p1, p.p2});
    for (const Vec3& q : {p.p0, p.p1, p.p2}) {
      lo = lo.cwiseMin(q);
      hi = hi.cwiseMax(q);
    }
  }
  if (tris.empty()) throw InputError(path + ": the STL file holds no triangles for a membrane");
  return mesh_from_triangles(tris, relative_tolerance * (hi - lo).maxCoeff(), path);
}

}  // namespace talus::dem::membrane
