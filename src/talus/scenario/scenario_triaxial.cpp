// [triaxial]: which plates and membrane make up the triaxial test (Götz 2024
// §3.3.1, spec/membranes-and-jamming.md), checked against the walls and
// membranes already read; and its table for the resolved scenario.
#include <fmt/format.h>

#include <algorithm>

#include "talus/scenario/scenario_detail.hpp"

namespace talus::io::detail {

void read_triaxial(TomlReader& r, dem::DemScenario& s) {
  dem::TriaxialParams t;
  t.bottom_plate = r.required_string("bottom_plate");
  t.top_plate = r.required_string("top_plate");
  t.membrane = r.required_string("membrane");
  for (const char* key : {"bottom_plate", "top_plate"}) {
    const std::string& name = std::string_view(key) == "top_plate" ? t.top_plate : t.bottom_plate;
    auto w = std::find_if(s.walls.begin(), s.walls.end(),
                          [&](const dem::WallParams& x) { return x.name == name; });
    if (w == s.walls.end()) r.fail(key, fmt::format("no wall named '{}'", name));
    if (w->kind != dem::WallKind::Plane || !(w->motion.servo_pressure > 0))
      r.fail(key, fmt::format("wall '{}' must be a \"plane\" with a [walls.motion.servo] (the "
                              "stress-controlled phase that finds h0)",
                              name));
  }
  if (t.top_plate == t.bottom_plate) r.fail("top_plate", "the two plates must be different walls");
  auto m = std::find_if(s.membranes.begin(), s.membranes.end(),
                        [&](const dem::MembraneSpec& x) { return x.name == t.membrane; });
  if (m == s.membranes.end()) r.fail("membrane", fmt::format("no membrane named '{}'", t.membrane));
  if (m->mesh != dem::MembraneMeshKind::Cylinder || m->caps || !(m->pressure < 0))
    r.fail("membrane",
           fmt::format("membrane '{}' must be an open cylinder (caps = false) with a confining "
                       "pressure < 0",
                       t.membrane));
  r.finish();
  s.triaxial = t;
}

nlohmann::ordered_json triaxial_table(const dem::TriaxialParams& t) {
  return {{"bottom_plate", t.bottom_plate}, {"top_plate", t.top_plate}, {"membrane", t.membrane}};
}

}  // namespace talus::io::detail
