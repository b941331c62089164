// [solid], [fluid], [drag], [hydrology] of a two-phase runout scenario, with
// the seed's symbols (van den Bout et al. 2021 §2.3) beside each key.
#include "talus/scenario/scenario_two_phase.hpp"

#include <fmt/format.h>

#include <cmath>

#include "talus/scenario/scenario_grid_rasters.hpp"

namespace talus::io::two_phase_keys {
namespace {

using detail::between;
using detail::non_negative;
using detail::number_in;
using detail::positive;
using detail::required_number_in;
using grid_rasters::GridRole;

// Rates are given in mm/h, the unit of rainfall records; the solver's are m/s.
constexpr double kMmPerHour = 1e-3 / 3600.0;

double deg(double rad) { return rad * 180.0 / M_PI; }

void read_solid(TomlReader& r, runout::TwoPhaseParams& p) {
  p.drag.solid_density = required_number_in(r, "density", positive());  // rho_s
  const double phi = r.required_angle("internal_friction");             // phi
  r.expect(phi > 0 && phi < M_PI / 2, "internal_friction", "an angle in (0, 90) degrees");
  const double delta = r.required_angle("basal_friction");  // delta
  r.expect(delta >= 0 && delta < M_PI / 2, "basal_friction", "an angle in [0, 90) degrees");
  if (delta > phi)
    r.fail("basal_friction",
           fmt::format("{:g} degrees is above internal_friction ({:g}); expected at most it (k_a, "
                       "k_p need delta <= phi)",
                       deg(delta), deg(phi)));
  p.pressure.phi_internal = phi;
  p.tan_basal_friction = p.pressure.tan_phi_basal = std::tan(delta);
  p.drag.grain_diameter = required_number_in(r, "grain_diameter", positive());  // d
  r.finish();
}

void read_fluid(TomlReader& r, runout::TwoPhaseParams& p) {
  const double rho_s = p.drag.solid_density;
  const double rho_f = number_in(r, "density", p.drag.fluid_density, non_negative());  // rho_f
  if (!(rho_f < rho_s))
    r.fail("density", fmt::format("{:g} kg/m^3 is not below the solid's ({:g}); expected a fluid "
                                  "lighter than the solid",
                                  rho_f, rho_s));
  p.drag.fluid_density = rho_f;
  p.manning = required_number_in(r, "manning", non_negative());  // n
  p.viscosity_alpha = number_in(r, "viscosity_alpha", 1e-3, positive());
  p.viscosity_beta = number_in(r, "viscosity_beta", 0.0, between(0.0, 100.0, false, false));
  p.shear_factor = number_in(r, "shear_factor", p.shear_factor, positive());  // chi
  p.lateral_viscosity = r.boolean("lateral_viscosity", p.lateral_viscosity);
  r.finish();
}

void read_drag(TomlReader& r, runout::TwoPhaseParams& p) {
  const auto j = r.integer("exponent", p.drag.exponent);  // J
  r.expect(j == 1 || j == 2, "exponent", "1 (linear drag) or 2 (quadratic)");
  p.drag.exponent = static_cast<int>(j);
  p.drag.mixing_exponent =
      number_in(r, "mixing_exponent", p.drag.mixing_exponent, between(0.0, 10.0, true, false));
  p.drag.smoothing_speed = number_in(r, "smoothing_speed", p.drag.smoothing_speed, positive());
  p.virtual_mass = r.boolean("virtual_mass", p.virtual_mass);
  r.finish();
}

// A rate (mm/h) as a number at `key` or a raster at `key`_file, not both.
void read_rate(TomlReader& r, const std::string& key, const detail::DemContext& ctx,
               runout::GridSpec& g, double& rate, std::vector<double>& map, std::string& file) {
  const std::string file_key = key + "_file";
  if (r.has(key) && r.has(file_key))
    r.fail(file_key, fmt::format("'{}' is also given; expected one of them", key));
  rate = number_in(r, key, 0.0, non_negative()) * kMmPerHour;
  if (!r.has(file_key)) return;
  map = grid_rasters::read_grid(r, file_key, ctx, file, g, GridRole::OnGrid);
  for (double& v : map) v *= kMmPerHour;
}

void read_hydrology(TomlReader& r, const detail::DemContext& ctx, runout::RunoutScenario& s) {
  auto& t = s.two_phase;
  read_rate(r, "rainfall", ctx, s.grid, t.params.rainfall, t.params.rainfall_map, t.rainfall_file);
  read_rate(r, "infiltration", ctx, s.grid, t.params.infiltration, t.params.infiltration_map,
            t.infiltration_file);
  r.finish();
}

}  // namespace

void read_tables(TomlReader& root, const detail::DemContext& ctx, runout::RunoutScenario& s) {
  auto& p = s.two_phase.params;
  TomlReader solid = root.required_table("solid");
  read_solid(solid, p);
  TomlReader fluid = root.required_table("fluid");
  read_fluid(fluid, p);
  const toml::table empty;
  TomlReader drag = detail::table_or_empty(root, "drag", empty);
  read_drag(drag, p);
  TomlReader hydrology = detail::table_or_empty(root, "hydrology", empty);
  read_hydrology(hydrology, ctx, s);
}

void read_release_fractions(TomlReader& r, const detail::DemContext& ctx,
                            runout::RunoutScenario& s) {
  auto& t = s.two_phase;
  if (r.has("solid_fraction") && r.has("solid_fraction_file"))
    r.fail("solid_fraction_file", "'solid_fraction' is also given; expected one of them");
  if (!r.has("solid_fraction") && !r.has("solid_fraction_file"))
    r.missing("solid_fraction",
              "expected one of 'solid_fraction' (alpha_s, a number in [0, 1]) or "
              "'solid_fraction_file' (a raster of it on the terrain's grid)");
  if (r.has("solid_fraction_file")) {
    r.reject({"fluid_fraction"}, "is only checked against a constant 'solid_fraction'");
    t.solid_fraction_map = grid_rasters::read_grid(r, "solid_fraction_file", ctx,
                                                   t.solid_fraction_file, s.grid, GridRole::OnGrid);
    for (std::size_t c = 0; c < t.solid_fraction_map.size(); ++c)
      if (t.solid_fraction_map[c] > 1.0)
        r.fail("solid_fraction_file",
               fmt::format("{}: cell (column {}, row {}) is {}; expected a fraction in [0, 1]",
                           t.solid_fraction_file, c % s.grid.shape.nx, c / s.grid.shape.nx,
                           t.solid_fraction_map[c]));
    return;
  }
  t.solid_fraction = required_number_in(r, "solid_fraction", between(0.0, 1.0, false, false));
  if (const auto f =
          detail::optional_number_in(r, "fluid_fraction", between(0.0, 1.0, false, false));
      f && std::abs(*f + t.solid_fraction - 1.0) > 1e-9)
    r.fail("fluid_fraction",
           fmt::format("{:g} + solid_fraction {:g} = {:g}; expected alpha_s + alpha_f = 1", *f,
                       t.solid_fraction, *f + t.solid_fraction));
}

void write(nlohmann::ordered_json& root, const runout::RunoutScenario& s) {
  const auto& t = s.two_phase;
  const auto& p = t.params;
  root["solid"] = {{"density", p.drag.solid_density},
                   {"internal_friction", deg(p.pressure.phi_internal)},
                   {"basal_friction", deg(std::atan(p.tan_basal_friction))},
                   {"grain_diameter", p.drag.grain_diameter}};
  root["fluid"] = {
      {"density", p.drag.fluid_density},      {"manning", p.manning},
      {"viscosity_alpha", p.viscosity_alpha}, {"viscosity_beta", p.viscosity_beta},
      {"shear_factor", p.shear_factor},       {"lateral_viscosity", p.lateral_viscosity}};
  root["drag"] = {{"exponent", p.drag.exponent},
                  {"mixing_exponent", p.drag.mixing_exponent},
                  {"smoothing_speed", p.drag.smoothing_speed},
                  {"virtual_mass", p.virtual_mass}};
  auto& h = root["hydrology"] = nlohmann::ordered_json::object();
  if (t.rainfall_file.empty())
    h["rainfall"] = p.rainfall / kMmPerHour;
  else
    h["rainfall_file"] = t.rainfall_file;
  if (t.infiltration_file.empty())
    h["infiltration"] = p.infiltration / kMmPerHour;
  else
    h["infiltration_file"] = t.infiltration_file;
  auto& release = root["release"];
  if (t.solid_fraction_file.empty())
    release["solid_fraction"] = t.solid_fraction;
  else
    release["solid_fraction_file"] = t.solid_fraction_file;
}

}  // namespace talus::io::two_phase_keys
