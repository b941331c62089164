// [[membranes]]: DEM membranes (spec/membranes-and-jamming.md): the mesh per
// kind, the membrane material (Götz 2024 Table 2 names), pressure, pinned
// particles and the contact material; and the writer's table for one.
#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "talus/scenario/scenario_detail.hpp"

namespace talus::io::detail {
namespace {

using dem::MembraneFixed;
using dem::MembraneMeshKind;

// The keys each mesh kind reads, to say which kind a stray key belongs to.
const std::vector<std::string_view> kMeshKeys = {
    "origin",    "size", "center", "radius", "height",  "spacing",     "caps",
    "frequency", "file", "scale",  "offset", "stretch", "core_radius", "edge_radius"};

void read_mesh(TomlReader& r, dem::MembraneSpec& m, const DemContext& ctx) {
  switch (m.mesh) {
    case MembraneMeshKind::FlatSheet: {
      m.origin = required_point(r, "origin", ctx);
      const auto size = r.required_numbers("size", 2, "[lx, ly] in m");
      m.spacing = required_number_in(r, "spacing", positive());
      r.expect(size[0] >= m.spacing && size[1] >= m.spacing, "size",
               fmt::format("[lx, ly] with both sides at least the spacing ({} m)", m.spacing));
      m.size_x = size[0];
      m.size_y = size[1];
      break;
    }
    case MembraneMeshKind::Cylinder:
      m.origin = point_or(r, "center", ctx, Vec3::Zero());
      m.radius = required_number_in(r, "radius", positive());
      m.height = required_number_in(r, "height", positive());
      m.spacing = required_number_in(r, "spacing", positive());
      r.expect(m.spacing < m.radius, "spacing",
               fmt::format("a spacing below the radius ({} m)", m.radius));
      m.caps = r.boolean("caps", false);
      break;
    case MembraneMeshKind::GeodesicSphere:
    case MembraneMeshKind::GeodesicHemisphere: {
      const bool half = m.mesh == MembraneMeshKind::GeodesicHemisphere;
      m.origin = point_or(r, "center", ctx, Vec3::Zero());
      m.radius = required_number_in(r, "radius", positive());
      const auto f = r.required_integer("frequency");
      r.expect(f >= 1 && f <= 256 && (!half || f % 2 == 0), "frequency",
               half ? "an even integer in [2, 256]" : "an integer in [1, 256]");
      m.frequency = static_cast<int>(f);
      // The hemisphere's fixed rim would have to move with it: spheres only.
      if (!half) {
        m.stretch = number_in(r, "stretch", 1.0, positive());
        m.core_radius = number_in(r, "core_radius", 0.0, non_negative());
        r.expect(m.core_radius <= m.radius, "core_radius",
                 fmt::format("a core no larger than the radius ({} m)", m.radius));
      }
      break;
    }
    case MembraneMeshKind::Box: {
      m.origin = point_or(r, "center", ctx, Vec3::Zero());
      const auto numbers = r.required_numbers("size", 3, "[lx, ly, lz] in m");
      const Vec3 size(numbers[0], numbers[1], numbers[2]);
      r.expect(size.minCoeff() > 0, "size", "[lx, ly, lz] with every side > 0");
      m.size_x = size.x();
      m.size_y = size.y();
      m.size_z = size.z();
      const double half = 0.5 * size.minCoeff();
      m.edge_radius = number_in(r, "edge_radius", 0.0, non_negative());
      r.expect(m.edge_radius <= half, "edge_radius",
               fmt::format("at most half the smallest side ({} m)", half));
      m.spacing = required_number_in(r, "spacing", positive());
      // rounded_box's limits, said here with the file and line: each quarter
      // arc and each flat part gets intervals of at least half the spacing.
      r.expect(m.edge_radius == 0 || M_PI * m.edge_radius / 4 >= 0.5 * m.spacing, "spacing",
               fmt::format("a spacing of at most pi edge_radius / 2 = {} m (coarser cannot "
                           "resolve the rounded edges)",
                           M_PI * m.edge_radius / 2));
      for (int d = 0; d < 3; ++d) {
        const double flat = size[d] - 2 * m.edge_radius;
        r.expect(flat <= 1e-12 * size[d] || flat >= 0.5 * m.spacing, "spacing",
                 fmt::format("a spacing of at most twice the flat part of each side ({} m of "
                             "the side {} m), or edge_radius = half that side",
                             flat, size[d]));
      }
      break;
    }
    case MembraneMeshKind::Stl:
      m.file = required_file(r, "file", ctx);
      m.scale = number_in(r, "scale", 1.0, positive());
      m.offset = point_or(r, "offset", ctx, Vec3::Zero());
      break;
  }
}

void check_fixed(TomlReader& r, const dem::MembraneSpec& m) {
  const bool rings = m.fixed == MembraneFixed::BottomRing || m.fixed == MembraneFixed::TopRing ||
                     m.fixed == MembraneFixed::BothRings;
  if (rings && m.mesh != MembraneMeshKind::Cylinder)
    r.fail("fixed", fmt::format("\"{}\" needs mesh = \"cylinder\"; other meshes use \"edge\" or "
                                "\"none\"",
                                name_of(kMembraneFixed, m.fixed)));
  const bool closed = m.mesh == MembraneMeshKind::GeodesicSphere ||
                      m.mesh == MembraneMeshKind::Box ||
                      (m.mesh == MembraneMeshKind::Cylinder && m.caps);
  if (m.fixed == MembraneFixed::Edge && closed)
    r.fail("fixed",
           "\"edge\": a closed membrane has no edge (use \"none\", or the rings of a "
           "cylinder)");
}

// pressure_ramp = [start, end]: the pressure grows linearly from 0 at start
// to `pressure` at end (Götz applies the vacuum stepwise after relaxing).
void read_pressure_ramp(TomlReader& r, dem::MembraneSpec& m) {
  if (!r.has("pressure_ramp")) return;
  const auto ramp = r.required_numbers("pressure_ramp", 2, "[start, end] in s");
  r.expect(ramp[0] >= 0.0 && ramp[1] > ramp[0], "pressure_ramp",
           "[start, end] in s with 0 <= start < end");
  r.expect(m.pressure != 0.0, "pressure_ramp", "a non-zero 'pressure' to ramp to");
  m.pressure_ramp_start = ramp[0];
  m.pressure_ramp_end = ramp[1];
}

// bottom_ring_wall / top_ring_wall: the pinned ring follows that wall.
void read_ring_walls(TomlReader& r, dem::MembraneSpec& m, const DemContext& ctx) {
  const bool bottom = m.fixed == MembraneFixed::BottomRing || m.fixed == MembraneFixed::BothRings;
  const bool top = m.fixed == MembraneFixed::TopRing || m.fixed == MembraneFixed::BothRings;
  for (const bool is_top : {false, true}) {
    const std::string key = is_top ? "top_ring_wall" : "bottom_ring_wall";
    if (!r.has(key)) continue;
    if (!(is_top ? top : bottom))
      r.fail(key, fmt::format("needs fixed = \"{}\" or \"both_rings\" (the ring it moves is "
                              "pinned)",
                              is_top ? "top_ring" : "bottom_ring"));
    std::string& name = is_top ? m.top_ring_wall : m.bottom_ring_wall;
    name = r.required_string(key);
    if (std::find(ctx.wall_names.begin(), ctx.wall_names.end(), name) == ctx.wall_names.end())
      r.fail(key, fmt::format("no wall named '{}' (expected the name of a [[walls]] entry)", name));
  }
}

}  // namespace

dem::MembraneSpec read_membrane(TomlReader& r, std::size_t index, const DemContext& ctx) {
  dem::MembraneSpec m;
  m.name = r.string("name", fmt::format("membrane{}", index));
  r.expect(
      !m.name.empty() && m.name.find_first_not_of("abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMN"
                                                  "OPQRSTUVWXYZ0123456789_-") == std::string::npos,
      "name", "a non-empty name of letters, digits, '_' and '-'");
  if (ctx.dimension != 3)
    r.fail("mesh",
           fmt::format("membranes need run.dimension = 3 (this run has {})", ctx.dimension));
  m.mesh = r.required_enum("mesh", kMembraneMeshes);
  read_mesh(r, m, ctx);
  r.reject(kMeshKeys, fmt::format("not used by mesh = \"{}\"", name_of(kMembraneMeshes, m.mesh)));
  m.youngs_modulus = required_number_in(r, "youngs_modulus", positive());
  m.thickness = required_number_in(r, "thickness", positive());
  m.density = required_number_in(r, "density", positive());
  m.spring_damping = number_in(r, "spring_damping", 0.0, non_negative());
  m.bending_stiffness = number_in(r, "bending_stiffness", 0.0, non_negative());
  m.bending_damping = number_in(r, "bending_damping", 0.0, non_negative());
  m.pressure = r.number("pressure", 0.0);
  read_pressure_ramp(r, m);
  m.fixed = r.enumeration("fixed", kMembraneFixed, MembraneFixed::None);
  check_fixed(r, m);
  read_ring_walls(r, m, ctx);
  m.material = r.required_string("material");
  check_material(r, "material", m.material, ctx);
  m.self_contact = r.boolean("self_contact", false);
  r.finish();
  return m;
}

nlohmann::ordered_json membrane_table(const dem::MembraneSpec& m) {
  using Json = nlohmann::ordered_json;
  auto vec = [](const Vec3& v) { return Json::array({v.x(), v.y(), v.z()}); };
  Json t{{"name", m.name}, {"mesh", name_of(kMembraneMeshes, m.mesh)}};
  switch (m.mesh) {
    case MembraneMeshKind::FlatSheet:
      t["origin"] = vec(m.origin);
      t["size"] = Json::array({m.size_x, m.size_y});
      t["spacing"] = m.spacing;
      break;
    case MembraneMeshKind::Cylinder:
      t["center"] = vec(m.origin);
      t["radius"] = m.radius;
      t["height"] = m.height;
      t["spacing"] = m.spacing;
      t["caps"] = m.caps;
      break;
    case MembraneMeshKind::GeodesicSphere:
    case MembraneMeshKind::GeodesicHemisphere:
      t["center"] = vec(m.origin);
      t["radius"] = m.radius;
      t["frequency"] = m.frequency;
      if (m.mesh == MembraneMeshKind::GeodesicSphere) {
        t["stretch"] = m.stretch;
        t["core_radius"] = m.core_radius;
      }
      break;
    case MembraneMeshKind::Box:
      t["center"] = vec(m.origin);
      t["size"] = Json::array({m.size_x, m.size_y, m.size_z});
      t["edge_radius"] = m.edge_radius;
      t["spacing"] = m.spacing;
      break;
    case MembraneMeshKind::Stl:
      t["file"] = m.file;
      t["scale"] = m.scale;
      t["offset"] = vec(m.offset);
      break;
  }
  t["youngs_modulus"] = m.youngs_modulus;
  t["thickness"] = m.thickness;
  t["density"] = m.density;
  t["spring_damping"] = m.spring_damping;
  t["bending_stiffness"] = m.bending_stiffness;
  t["bending_damping"] = m.bending_damping;
  t["pressure"] = m.pressure;
  if (m.pressure_ramp_end > 0)
    t["pressure_ramp"] = Json::array({m.pressure_ramp_start, m.pressure_ramp_end});
  t["fixed"] = name_of(kMembraneFixed, m.fixed);
  if (!m.bottom_ring_wall.empty()) t["bottom_ring_wall"] = m.bottom_ring_wall;
  if (!m.top_ring_wall.empty()) t["top_ring_wall"] = m.top_ring_wall;
  t["material"] = m.material;
  t["self_contact"] = m.self_contact;
  return t;
}

}  // namespace talus::io::detail
