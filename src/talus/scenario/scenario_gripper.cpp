// [gripper]: the granular gripper's protocol (Götz 2024 §4.2,
// spec/membranes-and-jamming.md; dem::GripperParams), checked against the
// membranes, materials and output already read, with its phase times
// derived; and its table for the resolved scenario (the given keys only).
#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "talus/scenario/scenario_detail.hpp"

namespace talus::io::detail {
namespace {

const dem::MembraneSpec& gripper_membrane(TomlReader& r, const dem::DemScenario& s,
                                          const std::string& name) {
  auto m = std::find_if(s.membranes.begin(), s.membranes.end(),
                        [&](const dem::MembraneSpec& x) { return x.name == name; });
  if (m == s.membranes.end()) r.fail("membrane", fmt::format("no membrane named '{}'", name));
  // The protocol holds the free particles and keeps the rim: a hemisphere
  // pinned at its rim, with no vacuum of its own (the protocol sets it).
  if (m->mesh != dem::MembraneMeshKind::GeodesicHemisphere ||
      m->fixed != dem::MembraneFixed::Edge || m->pressure != 0.0)
    r.fail("membrane", fmt::format("membrane '{}' must be a \"geodesic_hemisphere\" with fixed = "
                                   "\"edge\" and no pressure (the vacuum is [gripper] 'vacuum')",
                                   name));
  return *m;
}

}  // namespace

void read_gripper(TomlReader& r, dem::DemScenario& s, const DemContext& ctx) {
  dem::GripperParams g;
  g.membrane = r.required_string("membrane");
  const auto& mem = gripper_membrane(r, s, g.membrane);
  g.object_material = r.required_string("object_material");
  check_material(r, "object_material", g.object_material, ctx);
  g.hold_stretch = number_in(r, "hold_stretch", 1.25, between(1.0, 2.0, false, false));
  g.release = required_number_in(r, "release", non_negative());
  g.pretension = number_in(r, "pretension", 0.125, between(0.0, 0.5, false, true));
  g.object_radius = required_number_in(r, "object_radius", positive());
  r.expect(g.object_radius < mem.radius, "object_radius",
           fmt::format("a radius below the membrane's ({} m)", mem.radius));
  g.object_center = required_point(r, "object_center", ctx);
  // The object starts on the membrane's axis below its lowest rest point; it
  // touches nothing before push_start, so the held membrane may reach lower.
  const Vec3 c = mem.origin;
  const double lowest = c.z() - mem.radius;
  r.expect(
      g.object_center.z() + g.object_radius < lowest &&
          std::hypot(g.object_center.x() - c.x(), g.object_center.y() - c.y()) < 1e-9 * mem.radius,
      "object_center",
      fmt::format("a point on the membrane's axis (x = {}, y = {}) with the object's top "
                  "below the membrane's lowest rest point (z < {} m)",
                  c.x(), c.y(), lowest - g.object_radius));
  g.push_start = required_number_in(r, "push_start", non_negative());
  r.expect(g.push_start >= g.release, "push_start",
           fmt::format("a time no earlier than 'release' ({} s)", g.release));
  g.push_speed = required_number_in(r, "push_speed", positive());
  g.depth = required_number_in(r, "depth", positive());
  // depth: of the object's top above the hemisphere's lowest rest point.
  const double top_end = c.z() - mem.radius + g.depth;
  r.expect(top_end > g.object_center.z() + g.object_radius && top_end < c.z(), "depth",
           fmt::format("a depth that ends the push above the object's start and below the "
                       "membrane's rim (0 < depth < {} m)",
                       mem.radius));
  g.push_end = g.push_start + (top_end - g.object_center.z() - g.object_radius) / g.push_speed;
  g.relax = required_number_in(r, "relax", non_negative());
  g.vacuum = required_number_in(r, "vacuum", positive());
  const auto steps = r.integer("vacuum_steps", 1);
  r.expect(steps >= 1 && steps <= 100, "vacuum_steps", "an integer in [1, 100]");
  g.vacuum_steps = static_cast<int>(steps);
  g.vacuum_step_time = required_number_in(r, "vacuum_step_time", positive());
  g.hold = required_number_in(r, "hold", non_negative());
  g.pull_speed = required_number_in(r, "pull_speed", positive());
  g.vacuum_start = g.push_end + g.relax;
  g.vacuum_end = g.vacuum_start + g.vacuum_steps * g.vacuum_step_time;
  g.pull_start = g.vacuum_end + g.hold;
  if (!(g.pull_start < s.run.duration))
    r.fail("pull_speed",
           fmt::format("no time left to pull: the pull starts at {:.4g} s (push ends at {:.4g} "
                       "s, vacuum from {:.4g} to {:.4g} s) but run.duration is {} s",
                       g.pull_start, g.push_end, g.vacuum_start, g.vacuum_end, s.run.duration));
  if (s.output.checkpoint_interval > 0)
    r.fail("membrane",
           "checkpoints of [gripper] runs are not supported (the object's friction springs are "
           "not stored): leave output.checkpoint_interval out");
  r.finish();
  s.gripper = g;
}

nlohmann::ordered_json gripper_table(const dem::GripperParams& g) {
  const Vec3& o = g.object_center;
  return {{"membrane", g.membrane},
          {"object_material", g.object_material},
          {"hold_stretch", g.hold_stretch},
          {"release", g.release},
          {"pretension", g.pretension},
          {"object_radius", g.object_radius},
          {"object_center", {o.x(), o.y(), o.z()}},
          {"push_start", g.push_start},
          {"push_speed", g.push_speed},
          {"depth", g.depth},
          {"relax", g.relax},
          {"vacuum", g.vacuum},
          {"vacuum_steps", g.vacuum_steps},
          {"vacuum_step_time", g.vacuum_step_time},
          {"hold", g.hold},
          {"pull_speed", g.pull_speed}};
}

}  // namespace talus::io::detail
