// The [flume] keys that the DEM flume (scenario_flume.cpp) and the MPM flume
// (scenario_mpm.cpp) share: the path and the analysis. One reading, so the
// two accept the same values and fail with the same messages.
#include "talus/core/error.hpp"
#include "talus/geometry/flume.hpp"
#include "talus/scenario/scenario_detail.hpp"
#include "talus/mpm/scenario.hpp"

namespace talus::io::detail {

template <class Flume>
void read_flume_path(TomlReader& r, Flume& f, const DemContext& ctx) {
  if (ctx.dimension != 2) r.fail("flume", "the flume is a 2D scenario: set run.dimension = 2");
  f.beta = r.required_angle("beta");
  f.arc_radius = required_number_in(r, "arc_radius", positive());
  f.l_star = optional_number_in(r, "l_star", positive());
  f.barrier_length = optional_number_in(r, "barrier_length", positive());
}

template <class Flume>
void read_flume_analysis(TomlReader& r, Flume& f) {
  f.front_quantile =
      number_in(r, "front_quantile", f.front_quantile, between(0.5, 1.0, true, false));
  f.profile_bin = number_in(r, "profile_bin", f.profile_bin, positive());
  f.tail_thickness = number_in(r, "tail_thickness", f.tail_thickness, non_negative());
}

template <class Flume>
geometry::FlumeGeometry resolve_flume_path(TomlReader& r, Flume& f) {
  geometry::FlumeGeometry g;
  try {
    g = geometry::make_flume(rad2deg(f.beta), f.arc_radius, f.l_star, f.barrier_length);
  } catch (const InputError& e) {
    r.fail("beta", e.what());
  }
  f.l_star = g.l_star;
  f.barrier_length = g.barrier_length;
  return g;
}

template void read_flume_path(TomlReader&, dem::FlumeParams&, const DemContext&);
template void read_flume_path(TomlReader&, mpm::MpmFlumeParams&, const DemContext&);
template void read_flume_analysis(TomlReader&, dem::FlumeParams&);
template void read_flume_analysis(TomlReader&, mpm::MpmFlumeParams&);
template geometry::FlumeGeometry resolve_flume_path(TomlReader&, dem::FlumeParams&);
template geometry::FlumeGeometry resolve_flume_path(TomlReader&, mpm::MpmFlumeParams&);

}  // namespace talus::io::detail
