#include "talus/io/scenario_mpm_membranes.hpp"

#include <fmt/format.h>

namespace talus::io::detail {
namespace {

const EnumNames<mpm::MembraneModel> kMembraneModels = {{"fe", mpm::MembraneModel::FiniteElement},
                                                       {"york", mpm::MembraneModel::York}};
const EnumNames<mpm::MembraneFixed> kMembraneEnds = {{"none", mpm::MembraneFixed::None},
                                                     {"first", mpm::MembraneFixed::First},
                                                     {"last", mpm::MembraneFixed::Last},
                                                     {"both", mpm::MembraneFixed::Both}};

// J from `stiffness`, or from `youngs_modulus` times `thickness`; mu from
// `mass_per_length`, or from `density` times `thickness`.
void read_stiffness_and_mass(TomlReader& r, mpm::MembraneParams& m) {
  const bool by_modulus = r.has("youngs_modulus");
  if (by_modulus && r.has("stiffness"))
    r.fail("youngs_modulus", "give either stiffness (J, N/m) or youngs_modulus with thickness");
  const bool needs_thickness = by_modulus || r.has("density");
  const double thickness = needs_thickness ? required_number_in(r, "thickness", positive()) : 0.0;
  if (!needs_thickness)
    r.reject({"thickness"},
             "is only used with youngs_modulus or density (else give stiffness "
             "and mass_per_length)");
  m.stiffness = by_modulus ? required_number_in(r, "youngs_modulus", positive()) * thickness
                           : required_number_in(r, "stiffness", positive());
  if (r.has("density") && r.has("mass_per_length"))
    r.fail("density", "give either mass_per_length (kg/m^2) or density with thickness");
  m.mass_per_length = r.has("density") ? required_number_in(r, "density", positive()) * thickness
                                       : required_number_in(r, "mass_per_length", positive());
}

void check_inside_grid(TomlReader& r, const mpm::MpmScenario& s, const DemContext& ctx,
                       const std::vector<Vec3>& points) {
  for (std::size_t i = 0; i < points.size(); ++i)
    for (int d = 0; d < ctx.dimension; ++d)
      if (points[i][d] < s.grid.lo[d] || points[i][d] > s.grid.hi[d])
        r.fail("points", fmt::format("point {} ({}, {}) lies outside the [grid]", i + 1,
                                     points[i].x(), points[i].y()));
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
  if (ctx.dimension != 2)
    r.fail("model", "MPM membranes are 2D only (a chain of cables); this run has dimension 3");
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
  m.spacing = number_in(r, "spacing", 0.5 * s.grid.cell_size, positive());
  read_stiffness_and_mass(r, m);
  m.fixed = r.enumeration("fixed", kMembraneEnds, m.fixed);
  if (m.closed && m.fixed != mpm::MembraneFixed::None)
    r.fail("fixed", "a closed membrane has no ends to fix (use \"none\")");
  m.slack = number_in(r, "slack", 0.0, non_negative());
  if (r.has("slack_box")) {
    if (m.slack == 0.0) r.fail("slack_box", "is only used with slack > 0");
    read_box(r, "slack_box", ctx, m.slack_min, m.slack_max);
    m.slack_everywhere = false;
  }
  m.velocity = point_or(r, "velocity", ctx, Vec3::Zero());
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
  J t = {{"name", m.name},
         {"model", name_of(kMembraneModels, m.model)},
         {"points", points},
         {"closed", m.closed},
         {"spacing", m.spacing},
         {"stiffness", m.stiffness},
         {"mass_per_length", m.mass_per_length},
         {"fixed", name_of(kMembraneEnds, m.fixed)},
         {"slack", m.slack}};
  if (!m.slack_everywhere)
    t["slack_box"] = {{"min", point(m.slack_min)}, {"max", point(m.slack_max)}};
  t["velocity"] = point(m.velocity);
  return t;
}

}  // namespace talus::io::detail
