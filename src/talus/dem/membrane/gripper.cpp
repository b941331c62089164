#include "talus/dem/membrane/gripper.hpp"

#include <fmt/format.h>

#include <algorithm>

#include "talus/core/error.hpp"
#include "talus/dem/membrane/from_spec.hpp"

namespace talus::dem::membrane {

void apply_gripper(const GripperParams& g, const DemScenario& sc, DemSystem<3>& s) {
  auto [spec, body] = named_membrane(sc.membranes, s.membranes, g.membrane, "[gripper]");
  const int material = s.material_index(g.object_material);
  if (material < 0)
    throw InputError(fmt::format("[gripper]: no material named '{}'", g.object_material));

  // Filling: the free particles wait on the larger sphere, pinned (the source
  // holds them there "to fit more grains in"); the rim stays where it is.
  MembraneBody& mb = body;
  auto& m = mb.body;
  mb.held.assign(m.x.size(), 0);
  for (std::size_t i = 0; i < m.x.size(); ++i) {
    if (m.fixed[i]) continue;
    m.x[i] = spec.origin + g.hold_stretch * (m.x[i] - spec.origin);
    mb.held[i] = 1;
    m.fixed[i] = 1;
  }
  mb.release_time = g.release;
  mb.rest_cut = g.pretension;
  mb.release_rest = m.rest.length;

  // The vacuum: a pressure pushing the membrane inwards, in steps.
  mb.pressure = -g.vacuum;
  mb.ramp_start = g.vacuum_start;
  mb.ramp_end = g.vacuum_end;
  mb.pressure_steps = g.vacuum_steps;
  mb.step_rise = 0.5;
  m.params.pressure = pressure_at(mb, 0.0);

  DrivenSphere o;
  o.name = "object";
  o.radius = g.object_radius;
  o.material = material;
  o.origin = g.object_center;
  o.legs = {{g.push_start, g.push_end, Vec3(0, 0, g.push_speed)},
            {g.pull_start, kNever, Vec3(0, 0, -g.pull_speed)}};
  o.active_from = g.push_start;
  o.x = position_at(o, 0.0);
  o.memory.resize(s.membranes.size());
  s.objects.push_back(std::move(o));
}

}  // namespace talus::dem::membrane
