// [dam_break]: the calibration test of the flume sand (spec: flume.md). It
// generates a floor, a back wall and a gate, and with [dam_break.release] the
// settled fill between them.
#include <fmt/format.h>

#include "talus/scenario/scenario_detail.hpp"

namespace talus::io::detail {

void read_dam_break(TomlReader& r, dem::DemScenario& s, const DemContext& ctx) {
  if (ctx.dimension != 2)
    r.fail("dam_break", "the dam break is a 2D scenario: set run.dimension = 2");
  dem::DamBreakParams d;
  d.width = required_number_in(r, "width", positive());
  d.height = required_number_in(r, "height", positive());
  d.floor_length = number_in(r, "floor_length", d.floor_length, positive());
  if (d.floor_length <= d.width) {
    r.fail("floor_length", fmt::format("the floor ({} m) must reach beyond the gate at {} m",
                                       d.floor_length, d.width));
  }
  d.wall_material = r.required_string("wall_material");
  check_material(r, "wall_material", d.wall_material, ctx);
  d.gate_open = number_in(r, "gate_open", d.gate_open, non_negative());
  d.segment_length = number_in(r, "segment_length", d.segment_length, positive());
  const auto segments = r.integer("segments", d.segments);
  r.expect(segments >= 1 && segments <= 100, "segments", "an integer from 1 to 100");
  d.segments = static_cast<int>(segments);
  d.profile_bin = number_in(r, "profile_bin", d.profile_bin, positive());
  d.toe_thickness = number_in(r, "toe_thickness", d.toe_thickness, non_negative());

  auto segment = [&](const char* name, Vec3 a, Vec3 b, double remove_at) {
    dem::WallParams w;
    w.name = name;
    w.kind = dem::WallKind::Segment;
    w.material = d.wall_material;
    w.a = a;
    w.b = b;
    w.motion.remove_at = remove_at;
    w.generated = true;
    s.walls.push_back(w);
  };
  segment("floor", Vec3(0, 0, 0), Vec3(d.floor_length, 0, 0), dem::kNever);
  segment("back", Vec3(0, 1.5 * d.height, 0), Vec3(0, 0, 0), dem::kNever);
  segment("gate", Vec3(d.width, 0, 0), Vec3(d.width, d.height, 0), d.gate_open);
  // The lid only holds the fill while it settles.
  segment("lid", Vec3(d.width, d.height, 0), Vec3(0, d.height, 0), d.gate_open);
  if (auto release = r.optional_table("release")) {
    const std::vector<Vec3> box = {Vec3(0, 0, 0), Vec3(d.width, 0, 0), Vec3(d.width, d.height, 0),
                                   Vec3(0, d.height, 0)};
    s.sources.push_back(read_release(*release, box, ctx));
  }
  r.finish();
  s.dam_break = d;
}

}  // namespace talus::io::detail
