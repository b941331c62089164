#include "talus/scenario/scenario_mpm_membranes.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <array>

namespace talus::io::detail {
namespace {

const EnumNames<mpm::MembraneModel> kMembraneModels = {{"fe", mpm::MembraneModel::FiniteElement},
                                                       {"york", mpm::MembraneModel::York}};
const EnumNames<mpm::MembraneFixed> kMembraneEnds = {{"none", mpm::MembraneFixed::None},
                                                     {"first", mpm::MembraneFixed::First},
                                                     {"last", mpm::MembraneFixed::Last},
                                                     {"both", mpm::MembraneFixed::Both},
                                                     {"edges", mpm::MembraneFixed::Edges}};
const EnumNames<mpm::MembraneShape> kMembraneShapes = {{"polyline", mpm::MembraneShape::Polyline},
                                                       {"sheet", mpm::MembraneShape::Sheet},
                                                       {"box", mpm::MembraneShape::Box},
                                                       {"sphere", mpm::MembraneShape::Sphere}};

// J from `stiffness`, or from `youngs_modulus` times `thickness`; mu from
// `areal_mass`, or from `density` times `thickness`.
void read_stiffness_and_mass(TomlReader& r, mpm::MembraneParams& m) {
  // The key's old name said "per length" for what is a mass per area.
  r.reject({"mass_per_length"},
           "was renamed areal_mass (kg/m^2; in 2D per m of line and m of depth)");
  const bool by_modulus = r.has("youngs_modulus");
  if (by_modulus && r.has("stiffness"))
    r.fail("youngs_modulus", "give either stiffness (J, N/m) or youngs_modulus with thickness");
  const bool needs_thickness = by_modulus || r.has("density");
  const double thickness = needs_thickness ? required_number_in(r, "thickness", positive()) : 0.0;
  if (!needs_thickness)
    r.reject({"thickness"},
             "is only used with youngs_modulus or density (else give stiffness "
             "and areal_mass)");
  m.stiffness = by_modulus ? required_number_in(r, "youngs_modulus", positive()) * thickness
                           : required_number_in(r, "stiffness", positive());
  if (r.has("density") && r.has("areal_mass"))
    r.fail("density", "give either areal_mass (kg/m^2) or density with thickness");
  m.areal_mass = r.has("density") ? required_number_in(r, "density", positive()) * thickness
                                  : required_number_in(r, "areal_mass", positive());
}

void check_inside_grid(TomlReader& r, const mpm::MpmScenario& s, const DemContext& ctx,
                       const std::vector<Vec3>& points, std::string_view key = "points") {
  for (std::size_t i = 0; i < points.size(); ++i)
    for (int d = 0; d < ctx.dimension; ++d)
      if (points[i][d] < s.grid.lo[d] || points[i][d] > s.grid.hi[d])
        r.fail(key,
               fmt::format("point {} ({}) lies outside the [grid]", i + 1,
                           fmt::join(points[i].data(), points[i].data() + ctx.dimension, ", ")));
}

// 2D: a polyline, open (ends may be fixed) or closed.
void read_polyline(TomlReader& r, mpm::MembraneParams& m, const mpm::MpmScenario& s,
                   const DemContext& ctx) {
  m.points = r.vec3_list("points");
  for (std::size_t i = 0; i < m.points.size(); ++i)
    if (m.points[i].z() != 0.0)
      r.fail("points", fmt::format("expected [x, y] points in a 2D run (point {})", i + 1));
  m.closed = r.boolean("closed", false);
  const std::size_t least = m.closed ? 3 : 2;
  if (m.points.size() < least)
    r.fail("points", fmt::format("expected at least {} points [x, y] for {} membrane", least,
                                 m.closed ? "a closed" : "an open"));
  for (std::size_t i = 0; i + 1 < m.points.size(); ++i)
    if ((m.points[i + 1] - m.points[i]).norm() == 0.0)
      r.fail("points", fmt::format("points {} and {} coincide", i + 1, i + 2));
  check_inside_grid(r, s, ctx, m.points);
  m.fixed = r.enumeration("fixed", kMembraneEnds, m.fixed);
  if (m.fixed == mpm::MembraneFixed::Edges)
    r.fail("fixed", "\"edges\" is for 3D sheets; a line has ends: \"first\", \"last\", \"both\"");
  if (m.closed && m.fixed != mpm::MembraneFixed::None)
    r.fail("fixed", "a closed membrane has no ends to fix (use \"none\")");
}

// 3D: a sheet of 4 corners (its edges may be fixed), or the closed surface of
// a box or a sphere (a bag).
void read_surface(TomlReader& r, mpm::MembraneParams& m, const mpm::MpmScenario& s,
                  const DemContext& ctx) {
  if (m.model != mpm::MembraneModel::FiniteElement)
    r.fail("model", "York's membrane is 2D only; a 3D membrane is model = \"fe\" (triangles)");
  if (!r.has("shape"))
    r.missing("shape", "a 3D membrane is a surface: shape = \"sheet\", \"box\" or \"sphere\"");
  m.shape = r.required_enum("shape", kMembraneShapes);
  if (m.shape == mpm::MembraneShape::Polyline)
    r.fail("shape", "a 3D membrane is a surface: \"sheet\", \"box\" or \"sphere\"");
  r.reject({"closed"}, "is not used in 3D: a sheet is open, a box or a sphere closed");
  if (m.shape != mpm::MembraneShape::Sheet) {
    r.reject({"points"}, "is only used by shape = \"sheet\" (its 4 corners)");
    r.reject({"fixed"}, "is only used by shape = \"sheet\" (a closed surface has no edges)");
  }
  if (m.shape != mpm::MembraneShape::Box) r.reject({"box"}, "is only used by shape = \"box\"");
  if (m.shape != mpm::MembraneShape::Sphere)
    r.reject({"centre", "radius"}, "is only used by shape = \"sphere\"");
  m.closed = m.shape != mpm::MembraneShape::Sheet;
  switch (m.shape) {
    case mpm::MembraneShape::Sheet: {
      m.points = r.vec3_list("points");
      if (m.points.size() != 4)
        r.fail("points", fmt::format("expected the sheet's 4 corners [x, y, z] in order, got {}",
                                     m.points.size()));
      check_inside_grid(r, s, ctx, m.points);
      const auto& c = m.points;
      // Each half of the quad must be a proper triangle.
      for (auto [a, b, d] : {std::array{0, 1, 2}, std::array{0, 2, 3}}) {
        const Vec3 u = c[b] - c[a], w = c[d] - c[a];
        if (!(u.cross(w).norm() > 1e-9 * u.norm() * w.norm()))
          r.fail("points", fmt::format("corners {}, {} and {} are in a line or coincide", a + 1,
                                       b + 1, d + 1));
      }
      m.fixed = r.enumeration("fixed", kMembraneEnds, m.fixed);
      if (m.fixed != mpm::MembraneFixed::None && m.fixed != mpm::MembraneFixed::Edges)
        r.fail("fixed", "a sheet is held by all its edges (\"edges\") or not at all (\"none\")");
      break;
    }
    case mpm::MembraneShape::Box:
      read_box(r, "box", ctx, m.box_min, m.box_max);
      check_inside_grid(r, s, ctx, {m.box_min, m.box_max}, "box");
      break;
    case mpm::MembraneShape::Sphere: {
      m.centre = required_point(r, "centre", ctx);
      m.radius = required_number_in(r, "radius", positive());
      const Vec3 e = Vec3::Constant(m.radius);
      check_inside_grid(r, s, ctx, {m.centre - e, m.centre + e}, "radius");
      break;
    }
    case mpm::MembraneShape::Polyline:
      break;
  }
  m.poisson_ratio = number_in(r, "poisson_ratio", 0.0, between(0.0, 1.0, false, true));
}

}  // namespace

mpm::MembraneParams read_mpm_membrane(TomlReader& r, std::size_t index, const mpm::MpmScenario& s,
                                      const DemContext& ctx) {
  mpm::MembraneParams m;
  m.name = r.string("name", fmt::format("membrane{}", index));
  // The name heads columns of membranes.csv.
  r.expect(
      !m.name.empty() && m.name.find_first_not_of("abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMN"
                                                  "OPQRSTUVWXYZ0123456789_-") == std::string::npos,
      "name", "a non-empty name of letters, digits, '_' and '-'");
  m.model = r.enumeration("model", kMembraneModels, m.model);
  if (ctx.dimension == 3) {
    read_surface(r, m, s, ctx);
  } else {
    if (r.enumeration("shape", kMembraneShapes, m.shape) != mpm::MembraneShape::Polyline)
      r.fail("shape", "sheets, boxes and spheres are 3D; a 2D membrane is a polyline");
    r.reject({"poisson_ratio"}, "is only used by 3D membranes (triangles)");
    read_polyline(r, m, s, ctx);
  }
  m.spacing = number_in(r, "spacing", 0.5 * s.grid.cell_size, positive());
  read_stiffness_and_mass(r, m);
  m.slack = number_in(r, "slack", 0.0, non_negative());
  if (r.has("slack_box")) {
    if (m.slack == 0.0) r.fail("slack_box", "is only used with slack > 0");
    read_box(r, "slack_box", ctx, m.slack_min, m.slack_max);
    m.slack_everywhere = false;
  }
  m.velocity = point_or(r, "velocity", ctx, Vec3::Zero());
  // Absent: the membrane shares the soil's velocity field (no slip).
  if (r.has("friction")) {
    if (m.model != mpm::MembraneModel::FiniteElement)
      r.fail("friction", "a membrane slips on the soil in the FE model only (model = \"fe\")");
    m.soil_friction = required_number_in(r, "friction", non_negative());
  }
  r.finish();
  return m;
}

nlohmann::ordered_json mpm_membrane_table(const mpm::MembraneParams& m, int dimension) {
  using J = nlohmann::ordered_json;
  auto point = [dimension](const Vec3& v) {
    J a = J::array();
    for (int d = 0; d < dimension; ++d) a.push_back(v[d]);
    return a;
  };
  J points = J::array();
  for (const auto& p : m.points) points.push_back(point(p));
  J t = {{"name", m.name}, {"model", name_of(kMembraneModels, m.model)}};
  if (dimension == 3) {
    t["shape"] = name_of(kMembraneShapes, m.shape);
    if (m.shape == mpm::MembraneShape::Sheet) t["points"] = points;
    if (m.shape == mpm::MembraneShape::Box)
      t["box"] = {{"min", point(m.box_min)}, {"max", point(m.box_max)}};
    if (m.shape == mpm::MembraneShape::Sphere)
      t["centre"] = point(m.centre), t["radius"] = m.radius;
  } else {
    t["points"] = points;
    t["closed"] = m.closed;
  }
  t["spacing"] = m.spacing;
  t["stiffness"] = m.stiffness;
  t["areal_mass"] = m.areal_mass;
  if (dimension == 3) t["poisson_ratio"] = m.poisson_ratio;
  if (dimension == 2 || m.shape == mpm::MembraneShape::Sheet)
    t["fixed"] = name_of(kMembraneEnds, m.fixed);
  t["slack"] = m.slack;
  if (!m.slack_everywhere)
    t["slack_box"] = {{"min", point(m.slack_min)}, {"max", point(m.slack_max)}};
  t["velocity"] = point(m.velocity);
  if (m.soil_friction >= 0.0) t["friction"] = m.soil_friction;
  return t;
}

}  // namespace talus::io::detail
