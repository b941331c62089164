// [hollow_sphere]: the object and the outer membrane of the hollow sphere
// (Götz 2024 §4.3, spec/membranes-and-jamming.md), checked against the
// membranes and particles already read; and its table for the resolved scenario.
#include <fmt/format.h>

#include <algorithm>

#include "talus/scenario/scenario_detail.hpp"

namespace talus::io::detail {
namespace {

const dem::MembraneSpec& named_membrane(TomlReader& r, const dem::DemScenario& s, const char* key,
                                        const std::string& name) {
  auto m = std::find_if(s.membranes.begin(), s.membranes.end(),
                        [&](const dem::MembraneSpec& x) { return x.name == name; });
  if (m == s.membranes.end()) r.fail(key, fmt::format("no membrane named '{}'", name));
  if (m->mesh != dem::MembraneMeshKind::GeodesicSphere)
    r.fail(key, fmt::format("membrane '{}' must be a \"geodesic_sphere\"", name));
  return *m;
}

}  // namespace

void read_hollow_sphere(TomlReader& r, dem::DemScenario& s) {
  dem::HollowSphereParams h;
  h.object = r.required_string("object");
  h.shell = r.required_string("shell");
  const auto& obj = named_membrane(r, s, "object", h.object);
  const auto& shell = named_membrane(r, s, "shell", h.shell);
  if (h.object == h.shell) r.fail("shell", "the object and the shell must be different membranes");
  // The measurement reads the load on the rigid core under the membrane.
  if (!(obj.core_radius > 0) || obj.fixed != dem::MembraneFixed::None)
    r.fail("object", fmt::format("membrane '{}' must wrap the object: core_radius > 0 and "
                                 "fixed = \"none\"",
                                 h.object));
  if (shell.fixed != dem::MembraneFixed::None || !(shell.pressure < 0))
    r.fail("shell", fmt::format("membrane '{}' must be free (fixed = \"none\") with a vacuum "
                                "pressure < 0",
                                h.shell));
  if ((shell.origin - obj.origin).norm() > 1e-12 * shell.radius || !(shell.radius > obj.radius) ||
      !(shell.core_radius == 0))
    r.fail("shell", fmt::format("membrane '{}' must be centred on the object, larger than it and "
                                "without a core",
                                h.shell));
  // One vacuum: it pushes the object's membrane out and the shell's in alike.
  if (obj.pressure != -shell.pressure || obj.pressure_ramp_start != shell.pressure_ramp_start ||
      obj.pressure_ramp_end != shell.pressure_ramp_end)
    r.fail("object", fmt::format("membrane '{}' needs pressure = {} (minus the shell's) and the "
                                 "shell's pressure_ramp: the same vacuum acts on both",
                                 h.object, -shell.pressure));
  if (r.has("poisson_ratio")) {
    h.poisson_ratio = required_number_in(r, "poisson_ratio", between(0.0, 0.5, false, true));
  } else {
    if (s.sources.empty())
      r.fail("poisson_ratio", "missing (and no [[particles]] to take it from)");
    auto mat = std::find_if(s.materials.begin(), s.materials.end(),
                            [&](const auto& m) { return m.name == s.sources.front().material; });
    if (mat == s.materials.end())
      r.fail("poisson_ratio", "missing (the first [[particles]] source names no material)");
    h.poisson_ratio = mat->poisson_ratio;
  }
  r.finish();
  s.hollow_sphere = h;
}

nlohmann::ordered_json hollow_sphere_table(const dem::HollowSphereParams& h) {
  return {{"object", h.object}, {"shell", h.shell}, {"poisson_ratio", h.poisson_ratio}};
}

}  // namespace talus::io::detail
