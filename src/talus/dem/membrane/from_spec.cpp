#include "talus/dem/membrane/from_spec.hpp"

#include <fmt/core.h>

#include <algorithm>
#include <cmath>

#include "talus/core/error.hpp"
#include "talus/core/memory_limit.hpp"

namespace talus::dem::membrane {
namespace {

// A mesh of the given area at this spacing is a triangular lattice: one
// vertex per spacing^2 sqrt(3)/2. Checked against the memory there is before
// the mesh is made; about 1 KiB per vertex with its springs, triangles,
// contact memory and output (measured order of magnitude, not a bound).
void check_mesh_memory(const MembraneSpec& s, double area) {
  const double vertices = area / (s.spacing * s.spacing * std::sqrt(3.0) / 2);
  check_memory(1024.0 * vertices,
               fmt::format("[[membranes]] '{}' at spacing = {:.3g} m: {:.3g} vertices", s.name,
                           s.spacing, vertices));
}

Mesh generate(const MembraneSpec& s) {
  switch (s.mesh) {
    case MembraneMeshKind::FlatSheet:
      check_mesh_memory(s, s.size_x * s.size_y);
      break;
    case MembraneMeshKind::Cylinder:
      check_mesh_memory(s, 2 * M_PI * s.radius * (s.height + (s.caps ? s.radius : 0.0)));
      break;
    case MembraneMeshKind::Box:
      check_mesh_memory(s, 2 * (s.size_x * s.size_y + s.size_y * s.size_z + s.size_z * s.size_x));
      break;
    default:
      break;
  }
  switch (s.mesh) {
    case MembraneMeshKind::FlatSheet: {
      // Rows of nx vertices spacing apart, ny rows spacing sqrt(3)/2 apart:
      // the largest lattice that fits in size_x x size_y.
      const int nx = 1 + static_cast<int>(std::floor(s.size_x / s.spacing + 1e-9));
      const int ny =
          1 + static_cast<int>(std::floor(s.size_y / (s.spacing * std::sqrt(3.0) / 2) + 1e-9));
      Mesh m = flat_sheet(nx, ny, s.spacing);
      for (Vec3& v : m.vertices) v += s.origin;
      return m;
    }
    case MembraneMeshKind::Cylinder: {
      Mesh m = cylinder(s.radius, s.height, s.spacing, s.caps);
      for (Vec3& v : m.vertices) v += s.origin;
      return m;
    }
    case MembraneMeshKind::GeodesicSphere:
      return geodesic_sphere(s.radius, s.frequency, s.origin);
    case MembraneMeshKind::GeodesicHemisphere:
      return geodesic_hemisphere(s.radius, s.frequency, s.origin);
    case MembraneMeshKind::Box:
      return rounded_box(Vec3(s.size_x, s.size_y, s.size_z), s.edge_radius, s.spacing, s.origin);
    case MembraneMeshKind::Stl:
      return read_stl_mesh(s.file, s.scale, s.offset);
  }
  return {};
}

// The end ring of a cylinder: vertices on its mantle (at the radius) at its
// lowest or highest z (caps have smaller radii except their outer ring).
std::vector<int> ring(const MembraneSpec& s, const Membrane& m, bool top) {
  const double tol = 1e-9 * std::max(s.radius, s.height);
  const double z_end = s.origin.z() + (top ? s.height : 0.0);
  std::vector<int> out;
  for (std::size_t i = 0; i < m.x.size(); ++i) {
    const Vec3 d = m.x[i] - s.origin;
    const double r = std::hypot(d.x(), d.y());
    if (std::abs(r - s.radius) < tol && std::abs(m.x[i].z() - z_end) < tol)
      out.push_back(static_cast<int>(i));
  }
  return out;
}

void fix_ring(const MembraneSpec& s, Membrane& m, bool top) {
  for (int i : ring(s, m, top)) m.fixed[i] = 1;
}

}  // namespace

MembraneBody make_membrane_body(const MembraneSpec& s, int material) {
  MembraneParams mp;
  mp.youngs_modulus = s.youngs_modulus;
  mp.thickness = s.thickness;
  mp.density = s.density;
  mp.spring_damping = s.spring_damping;
  mp.bending_elastic = s.bending_stiffness;
  mp.bending_dissipative = s.bending_damping;
  mp.pressure = s.pressure;
  MembraneBody b;
  b.name = s.name;
  b.material = material;
  b.self_contact = s.self_contact;
  b.pressure = s.pressure;
  b.ramp_start = s.pressure_ramp_start;
  b.ramp_end = s.pressure_ramp_end;
  b.core_radius = s.core_radius;
  b.core_centre = s.origin;
  b.body = make_membrane(generate(s), mp);
  auto& m = b.body;
  // Rest lengths and angles stay those of the generated sphere: a sphere
  // scaled about its centre keeps its dihedral angles, only the springs stretch.
  if (s.stretch != 1.0)
    for (Vec3& x : m.x) x = s.origin + s.stretch * (x - s.origin);
  switch (s.fixed) {
    case MembraneFixed::None:
      break;
    case MembraneFixed::Edge:
      for (const Edge& e : m.mesh.edges)
        if (!e.interior()) m.fixed[e.a] = m.fixed[e.b] = 1;
      break;
    case MembraneFixed::BottomRing:
      fix_ring(s, m, false);
      break;
    case MembraneFixed::TopRing:
      fix_ring(s, m, true);
      break;
    case MembraneFixed::BothRings:
      fix_ring(s, m, false);
      fix_ring(s, m, true);
      break;
    case MembraneFixed::All:
      std::fill(m.fixed.begin(), m.fixed.end(), 1);
      break;
  }
  if (s.fixed != MembraneFixed::None &&
      std::none_of(m.fixed.begin(), m.fixed.end(), [](char f) { return f != 0; }))
    throw InputError(fmt::format(
        "[[membranes]] '{}': 'fixed' selects no membrane particle (a closed mesh has no edge)",
        s.name));
  return b;
}

}  // namespace talus::dem::membrane

namespace talus::dem::membrane {

void attach_rings(MembraneBody& b, const MembraneSpec& s,
                  const std::vector<geometry::Wall>& walls) {
  auto& m = b.body;
  for (const bool top : {false, true}) {
    const std::string& name = top ? s.top_ring_wall : s.bottom_ring_wall;
    if (name.empty()) continue;
    auto it = std::find_if(walls.begin(), walls.end(),
                           [&](const geometry::Wall& w) { return w.name == name; });
    if (it == walls.end())
      throw InputError(fmt::format("[[membranes]] '{}': {}_ring_wall: no wall named '{}'", s.name,
                                   top ? "top" : "bottom", name));
    const int w = static_cast<int>(it - walls.begin());
    for (int i : ring(s, m, top)) {
      m.fixed[i] = 1;
      m.follows[i] = w;
      m.anchor[i] = m.x[i] - it->displacement(0.0);
    }
  }
}

NamedMembrane named_membrane(const std::vector<MembraneSpec>& specs,
                             std::vector<MembraneBody>& bodies, const std::string& name,
                             const std::string& section) {
  auto spec = std::find_if(specs.begin(), specs.end(),
                           [&](const MembraneSpec& m) { return m.name == name; });
  auto body = std::find_if(bodies.begin(), bodies.end(),
                           [&](const MembraneBody& m) { return m.name == name; });
  if (spec == specs.end() || body == bodies.end())
    throw InputError(fmt::format("{}: no membrane named '{}'", section, name));
  return {*spec, *body};
}

}  // namespace talus::dem::membrane
