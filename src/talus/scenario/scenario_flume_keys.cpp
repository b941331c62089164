// The flume's keys, one reading and one writing for the four methods: the DEM
// flume (scenario_flume.cpp), the MPM flume (scenario_mpm.cpp) and the runout
// path of type flume (scenario_runout.cpp) accept the same values and fail
// with the same messages.
#include <cmath>

#include "talus/core/error.hpp"
#include "talus/geometry/flume.hpp"
#include "talus/scenario/scenario_detail.hpp"

namespace talus::io::detail {

void require_2d_flume(TomlReader& r, const DemContext& ctx) {
  if (ctx.dimension != 2) r.fail("flume", "the flume is a 2D scenario: set run.dimension = 2");
}

geometry::FlumeShape read_flume_shape(TomlReader& r) {
  geometry::FlumeShape f;
  f.beta = r.required_angle("beta");
  f.arc_radius = required_number_in(r, "arc_radius", positive());
  f.l_star = optional_number_in(r, "l_star", positive());
  f.barrier_length = optional_number_in(r, "barrier_length", positive());
  return f;
}

geometry::FlumeMeasures read_flume_measures(TomlReader& r) {
  geometry::FlumeMeasures m;
  m.front_quantile =
      number_in(r, "front_quantile", m.front_quantile, between(0.5, 1.0, true, false));
  m.profile_bin = number_in(r, "profile_bin", m.profile_bin, positive());
  m.tail_thickness = number_in(r, "tail_thickness", m.tail_thickness, non_negative());
  return m;
}

geometry::FlumeGeometry resolve_flume_shape(TomlReader& r, geometry::FlumeShape& f) {
  geometry::FlumeGeometry g;
  try {
    g = geometry::make_flume(f);
  } catch (const InputError& e) {
    r.fail("beta", e.what());
  }
  f.l_star = g.l_star;
  f.barrier_length = g.barrier_length;
  return g;
}

double degrees_for_file(double radians) { return std::round(rad2deg(radians) * 1e9) / 1e9; }

void write_flume_shape(nlohmann::ordered_json& t, const geometry::FlumeShape& f) {
  t["beta"] = degrees_for_file(f.beta);
  t["arc_radius"] = f.arc_radius;
  if (f.l_star) t["l_star"] = *f.l_star;
  if (f.barrier_length) t["barrier_length"] = *f.barrier_length;
}

void write_flume_measures(nlohmann::ordered_json& t, const geometry::FlumeMeasures& m) {
  t["front_quantile"] = m.front_quantile;
  t["profile_bin"] = m.profile_bin;
  t["tail_thickness"] = m.tail_thickness;
}

}  // namespace talus::io::detail
