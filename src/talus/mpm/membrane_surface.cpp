// 3D FE membranes (membrane.hpp): meshing a sheet, a box surface or a sphere
// into triangles with edges about `spacing` long, and their rest shapes,
// masses, slack and fixed nodes.
#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "talus/core/error.hpp"
#include "talus/mpm/membrane.hpp"

namespace talus::mpm {

namespace {

struct Mesh {
  std::vector<Vec3> x;
  std::vector<std::array<uint32_t, 3>> triangles;
  std::vector<char> boundary;  // on the edge of a sheet
};

int pieces(double length, double spacing) {
  return std::max(1, static_cast<int>(std::round(length / spacing)));
}

// The quad a b c d (counter-clockwise) as two triangles; the diagonal
// alternates like a chequerboard so that the mesh has no preferred direction.
void add_quad(Mesh& m, bool flip, uint32_t a, uint32_t b, uint32_t c, uint32_t d) {
  if (flip) {
    m.triangles.push_back({a, b, d});
    m.triangles.push_back({b, c, d});
  } else {
    m.triangles.push_back({a, b, c});
    m.triangles.push_back({a, c, d});
  }
}

// The bilinear surface through the corners c0 c1 c2 c3 (in order).
Mesh sheet(const std::vector<Vec3>& c, double spacing) {
  const int nu = pieces(std::max((c[1] - c[0]).norm(), (c[2] - c[3]).norm()), spacing);
  const int nv = pieces(std::max((c[3] - c[0]).norm(), (c[2] - c[1]).norm()), spacing);
  Mesh m;
  for (int j = 0; j <= nv; ++j)
    for (int i = 0; i <= nu; ++i) {
      const double u = static_cast<double>(i) / nu, v = static_cast<double>(j) / nv;
      m.x.push_back((1 - u) * (1 - v) * c[0] + u * (1 - v) * c[1] + u * v * c[2] +
                    (1 - u) * v * c[3]);
      m.boundary.push_back(i == 0 || i == nu || j == 0 || j == nv);
    }
  auto id = [nu](int i, int j) { return static_cast<uint32_t>(j * (nu + 1) + i); };
  for (int j = 0; j < nv; ++j)
    for (int i = 0; i < nu; ++i)
      add_quad(m, (i + j) % 2 == 1, id(i, j), id(i + 1, j), id(i + 1, j + 1), id(i, j + 1));
  return m;
}

// The surface of the lattice box [0, n0] x [0, n1] x [0, n2], its nodes
// placed by `place(i, j, k)`; triangles oriented with outward normals.
template <class Place>
Mesh lattice_surface(const std::array<int, 3>& n, Place place) {
  Mesh m;
  const auto lin = [&](const std::array<int, 3>& q) {
    return (static_cast<std::size_t>(q[2]) * (n[1] + 1) + q[1]) * (n[0] + 1) + q[0];
  };
  std::vector<int64_t> id(static_cast<std::size_t>(n[0] + 1) * (n[1] + 1) * (n[2] + 1), -1);
  for (int k = 0; k <= n[2]; ++k)
    for (int j = 0; j <= n[1]; ++j)
      for (int i = 0; i <= n[0]; ++i) {
        if (i > 0 && i < n[0] && j > 0 && j < n[1] && k > 0 && k < n[2]) continue;
        id[lin({i, j, k})] = static_cast<int64_t>(m.x.size());
        m.x.push_back(place(i, j, k));
        m.boundary.push_back(0);
      }
  for (int a = 0; a < 3; ++a) {
    const int b = (a + 1) % 3, c = (a + 2) % 3;  // e_b x e_c = e_a
    for (int side : {0, n[a]}) {
      for (int p = 0; p < n[b]; ++p)
        for (int q = 0; q < n[c]; ++q) {
          auto node = [&](int dp, int dq) {
            std::array<int, 3> l{};
            l[a] = side, l[b] = p + dp, l[c] = q + dq;
            return static_cast<uint32_t>(id[lin(l)]);
          };
          const bool flip = (p + q) % 2 == 1;
          if (side > 0)
            add_quad(m, flip, node(0, 0), node(1, 0), node(1, 1), node(0, 1));
          else
            add_quad(m, flip, node(0, 0), node(0, 1), node(1, 1), node(1, 0));
        }
    }
  }
  return m;
}

Mesh box(const Vec3& lo, const Vec3& hi, double spacing) {
  std::array<int, 3> n;
  for (int d = 0; d < 3; ++d) n[d] = pieces(hi[d] - lo[d], spacing);
  return lattice_surface(n, [&](int i, int j, int k) {
    const Vec3 f(static_cast<double>(i) / n[0], static_cast<double>(j) / n[1],
                 static_cast<double>(k) / n[2]);
    return Vec3(lo + f.cwiseProduct(hi - lo));
  });
}

// A cube surface projected onto the sphere, equal-angle (tan) spacing so that
// the triangles near the cube's corners are not much smaller than the rest.
Mesh sphere(const Vec3& centre, double radius, double spacing) {
  const int n = std::max(2, pieces(0.5 * M_PI * radius, spacing));
  return lattice_surface({n, n, n}, [&](int i, int j, int k) {
    auto s = [n](int l) { return std::tan(0.25 * M_PI * (2.0 * l / n - 1.0)); };
    return Vec3(centre + radius * Vec3(s(i), s(j), s(k)).normalized());
  });
}

bool in_box(const Vec3& y, const MembraneParams& p) {
  for (int d = 0; d < 3; ++d)
    if (y[d] < p.slack_min[d] || y[d] > p.slack_max[d]) return false;
  return true;
}

}  // namespace

Membrane<3> build_surface_membrane(const MembraneParams& p, double cell_size) {
  const double spacing = p.spacing > 0.0 ? p.spacing : 0.5 * cell_size;
  Mesh mesh;
  switch (p.shape) {
    case MembraneShape::Sheet:
      if (p.points.size() != 4)
        throw InputError(fmt::format("membrane '{}': a sheet has 4 corners", p.name));
      mesh = sheet(p.points, spacing);
      break;
    case MembraneShape::Box:
      mesh = box(p.box_min, p.box_max, spacing);
      break;
    case MembraneShape::Sphere:
      mesh = sphere(p.centre, p.radius, spacing);
      break;
    case MembraneShape::Polyline:
      throw InputError(fmt::format("membrane '{}': not a surface", p.name));
  }
  Membrane<3> m;
  m.name = p.name;
  m.model = p.model;
  m.closed = p.shape != MembraneShape::Sheet;
  m.stiffness = p.stiffness;
  m.areal_mass = p.areal_mass;
  m.poisson_ratio = p.poisson_ratio;
  m.x = mesh.x;
  m.triangles = mesh.triangles;
  m.v.assign(m.x.size(), p.velocity);
  m.fixed.assign(m.x.size(), 0);
  if (p.fixed == MembraneFixed::Edges) m.fixed = mesh.boundary;
  m.mass.assign(m.x.size(), 0.0);
  for (const auto& t : m.triangles) {
    const Vec3 &a = m.x[t[0]], &b = m.x[t[1]], &c = m.x[t[2]];
    const bool slack = p.slack > 0.0 && (p.slack_everywhere || in_box((a + b + c) / 3.0, p));
    TriangleRest rest;
    try {
      rest = triangle_rest(a, b, c, slack ? 1.0 + p.slack : 1.0);
    } catch (const InputError&) {
      throw InputError(fmt::format(
          "membrane '{}': a degenerate triangle at ({:.4g}, {:.4g}, {:.4g}) (corners in a line?)",
          p.name, a.x(), a.y(), a.z()));
    }
    m.rest_inverse.push_back(rest.inverse);
    m.rest_area.push_back(rest.area);
    // A third of each triangle's mass to each of its nodes.
    for (uint32_t i : t) m.mass[i] += p.areal_mass * rest.area / 3.0;
  }
  return m;
}

}  // namespace talus::mpm
