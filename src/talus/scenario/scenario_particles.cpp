// [[particles]]: where the initial particles come from, per source type.
#include <fmt/format.h>

#include <algorithm>
#include <climits>

#include "talus/scenario/scenario_detail.hpp"

namespace talus::io::detail {
namespace {

using dem::SourceKind;

const std::vector<std::string_view> kSourceKeys = {
    "list",       "box",        "spacing",  "radius",           "jitter", "polygon",
    "radius_min", "radius_max", "porosity", "packing_fraction", "shrink", "count",
    "file",       "cylinder",   "shell",    "edge_radius"};

dem::ParticleSpec read_particle(TomlReader& r, const std::string& source_material,
                                const DemContext& ctx) {
  dem::ParticleSpec p;
  p.position = required_point(r, "position", ctx);
  p.velocity = point_or(r, "velocity", ctx, Vec3::Zero());
  p.angular_velocity = spin_or_zero(r, "angular_velocity", ctx);
  p.radius = required_number_in(r, "radius", positive());
  p.material = r.string("material", source_material);
  if (p.material.empty()) {
    r.missing("material", "missing: give it here or in the [[particles]] table above");
  }
  check_material(r, "material", p.material, ctx);
  r.finish();
  return p;
}

// A box (in 3D optionally with edges rounded by edge_radius), in 2D a polygon (stored
// counter-clockwise, with its bounding box), in 3D a vertical cylinder {center (of its base),
// radius, height} (stored as its bounding box and radius) or a spherical shell {center,
// inner_radius, outer_radius} (stored as the outer sphere's bounding box and both radii).
void read_region(TomlReader& r, dem::ParticleSourceParams& s, const DemContext& ctx) {
  const int given = r.has("box") + r.has("polygon") + r.has("cylinder") + r.has("shell");
  if (given != 1) {
    const char* key = given == 0          ? "box"
                      : r.has("cylinder") ? "cylinder"
                      : r.has("shell")    ? "shell"
                                          : "polygon";
    r.fail(key, "expected exactly one of 'box', 'polygon' (2D), 'cylinder' or 'shell' (3D)");
  }
  if (auto cyl = r.optional_table("cylinder")) {
    if (ctx.dimension != 3) r.fail("cylinder", "cylinders are for 3D runs; use 'polygon' in 2D");
    const Vec3 c = required_point(*cyl, "center", ctx);
    s.cylinder_radius = required_number_in(*cyl, "radius", positive());
    const double h = required_number_in(*cyl, "height", positive());
    cyl->finish();
    s.box_min = c - Vec3(s.cylinder_radius, s.cylinder_radius, 0.0);
    s.box_max = c + Vec3(s.cylinder_radius, s.cylinder_radius, h);
    return;
  }
  if (auto sh = r.optional_table("shell")) {
    if (ctx.dimension != 3) r.fail("shell", "spherical shells are for 3D runs");
    const Vec3 c = required_point(*sh, "center", ctx);
    s.shell_inner_radius = required_number_in(*sh, "inner_radius", non_negative());
    s.shell_outer_radius = required_number_in(*sh, "outer_radius", positive());
    sh->expect(s.shell_outer_radius > s.shell_inner_radius, "outer_radius",
               fmt::format("an outer radius above inner_radius ({} m)", s.shell_inner_radius));
    sh->finish();
    s.box_min = c - Vec3::Constant(s.shell_outer_radius);
    s.box_max = c + Vec3::Constant(s.shell_outer_radius);
    return;
  }
  if (r.has("box")) {
    read_box(r, "box", ctx, s.box_min, s.box_max);
    if (r.has("edge_radius")) {  // the inside of a rounded-box membrane
      if (ctx.dimension != 3) r.fail("edge_radius", "rounded boxes are for 3D runs");
      s.edge_radius = required_number_in(r, "edge_radius", positive());
      const double half = 0.5 * (s.box_max - s.box_min).minCoeff();
      r.expect(s.edge_radius <= half, "edge_radius",
               fmt::format("at most half the box's smallest side ({} m)", half));
    }
    return;
  }
  if (ctx.dimension != 2) r.fail("polygon", "polygons are for 2D runs; use 'box' in 3D");
  s.polygon = r.vec3_list("polygon");
  r.expect(s.polygon.size() >= 3, "polygon", "at least three points [[x, y], ...]");
  double twice_area = 0.0;
  for (std::size_t i = 0; i < s.polygon.size(); ++i) {
    const Vec3& p = s.polygon[i];
    const Vec3& q = s.polygon[(i + 1) % s.polygon.size()];
    if (p.z() != 0.0) r.expect(false, "polygon", "points [x, y] in a 2D run");
    twice_area += p.x() * q.y() - q.x() * p.y();
  }
  r.expect(twice_area != 0.0, "polygon", "a polygon with a non-zero area");
  if (twice_area < 0.0) std::reverse(s.polygon.begin(), s.polygon.end());
  set_polygon_bounds(s);
}

void read_kind(TomlReader& r, dem::ParticleSourceParams& s, const DemContext& ctx) {
  switch (s.kind) {
    case SourceKind::List: {
      for (TomlReader& p : r.tables("list"))
        s.particles.push_back(read_particle(p, s.material, ctx));
      if (s.particles.empty()) {
        r.missing("list", "missing: a \"list\" source needs at least one [[particles.list]] entry");
      }
      break;
    }
    case SourceKind::Lattice:
      read_box(r, "box", ctx, s.box_min, s.box_max);
      s.spacing = required_number_in(r, "spacing", positive());
      s.radius = required_number_in(r, "radius", positive());
      if (2.0 * s.radius > s.spacing) {
        r.expect(false, "radius", fmt::format("at most spacing / 2 = {}", s.spacing / 2.0));
      }
      s.jitter = r.string("jitter", "none");
      if (std::find(kJitterNames.begin(), kJitterNames.end(), s.jitter) == kJitterNames.end()) {
        r.expect(false, "jitter", "one of \"none\" or \"peer\"");
      }
      break;
    case SourceKind::RandomFill:
      read_region(r, s, ctx);
      read_radius_range(r, s);
      // The target porosity; the count, when given, replaces N = A(1-n)/(pi rbar^2).
      s.porosity = required_number_in(r, "porosity", between(0.0, 1.0, true, true));
      s.count = read_count(r);
      s.shrink = number_in(r, "shrink", 0.0, between(0.0, 1.0, false, true));
      break;
    case SourceKind::Grow:
      read_region(r, s, ctx);
      read_radius_range(r, s);
      s.packing_fraction = required_number_in(r, "packing_fraction", between(0.0, 1.0, true, true));
      s.count = read_count(r);
      s.shrink = number_in(r, "shrink", 0.0, between(0.0, 1.0, false, true));
      break;
    case SourceKind::File:
      s.file = required_file(r, "file", ctx);
      break;
  }
}

}  // namespace

void set_polygon_bounds(dem::ParticleSourceParams& s) {
  s.box_min = s.box_max = s.polygon.front();
  for (const Vec3& p : s.polygon) {
    s.box_min = s.box_min.cwiseMin(p);
    s.box_max = s.box_max.cwiseMax(p);
  }
}

void read_radius_range(TomlReader& r, dem::ParticleSourceParams& s) {
  s.radius_min = required_number_in(r, "radius_min", positive());
  s.radius_max = required_number_in(r, "radius_max", positive());
  if (s.radius_min > s.radius_max) {
    r.fail("radius_min", fmt::format("radius_min = {} is larger than radius_max = {}",
                                     r.text("radius_min"), r.text("radius_max")));
  }
}

std::optional<int> read_count(TomlReader& r) {
  const auto count = r.optional_integer("count");
  if (count) r.expect(*count > 0 && *count <= INT_MAX, "count", "a positive integer");
  return count ? std::optional<int>(static_cast<int>(*count)) : std::nullopt;
}

dem::SettleParams read_settle(TomlReader& r) {
  dem::SettleParams settle;
  if (!r.has("settle")) return settle;
  if (r.table().get("settle")->is_boolean()) {
    settle.enabled = r.boolean("settle", false);
    return settle;
  }
  if (!r.table().get("settle")->is_table()) {
    r.expect(false, "settle", "true, false or a table {ke_ratio = .., max_time = ..}");
  }
  TomlReader t = *r.optional_table("settle");
  settle.enabled = true;
  settle.ke_ratio = number_in(t, "ke_ratio", settle.ke_ratio, positive());
  settle.max_time = number_in(t, "max_time", settle.max_time, positive());
  t.finish();
  return settle;
}

dem::ParticleSourceParams read_source(TomlReader& r, const DemContext& ctx) {
  dem::ParticleSourceParams s;
  s.kind = r.required_enum("type", kSourceKinds);
  // A list may name the material per particle instead.
  if (s.kind == SourceKind::List)
    s.material = r.string("material", "");
  else
    s.material = r.required_string("material");
  if (!s.material.empty()) check_material(r, "material", s.material, ctx);
  read_kind(r, s, ctx);
  r.reject(kSourceKeys,
           fmt::format("not used by particles of type \"{}\"", name_of(kSourceKinds, s.kind)));
  s.settle = read_settle(r);
  r.finish();
  return s;
}

}  // namespace talus::io::detail
