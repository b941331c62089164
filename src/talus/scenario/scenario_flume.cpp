// [flume]: the Mancarella & Hungr flume from the barrier angle and arc radius
// (spec: flume.md). It generates the walls and, with [flume.release], the fill
// behind the gate, so a flume scenario never types wall coordinates.
#include <fmt/format.h>

#include "talus/geometry/flume.hpp"
#include "talus/scenario/scenario_detail.hpp"

namespace talus::io::detail {
namespace {

const EnumNames<int> kGateModes = {{"remove", 0}, {"lift", 1}};

// Kuen's calibrated fill (flume.md): radius uniform 1-2 mm, 3 % shrink, and a
// 2D porosity that gives about his 9099 disks in the release triangle.
constexpr double kReleaseRadiusMin = 1e-3, kReleaseRadiusMax = 2e-3;
constexpr double kReleasePorosity = 0.1662, kReleaseShrink = 0.03;

}  // namespace

dem::ParticleSourceParams read_release(TomlReader& r, const std::vector<Vec3>& polygon,
                                       const DemContext& ctx) {
  dem::ParticleSourceParams s;
  s.kind = dem::SourceKind::RandomFill;
  s.generated = true;
  s.material = r.required_string("material");
  check_material(r, "material", s.material, ctx);
  s.polygon = polygon;
  set_polygon_bounds(s);
  s.radius_min = number_in(r, "radius_min", kReleaseRadiusMin, positive());
  s.radius_max = number_in(r, "radius_max", kReleaseRadiusMax, positive());
  if (s.radius_min > s.radius_max) {
    r.fail("radius_min", fmt::format("radius_min = {} is larger than radius_max = {}", s.radius_min,
                                     s.radius_max));
  }
  s.porosity = number_in(r, "porosity", kReleasePorosity, between(0.0, 1.0, true, true));
  s.count = read_count(r);
  s.shrink = number_in(r, "shrink", kReleaseShrink, between(0.0, 1.0, false, true));
  if (r.has("settle")) {
    s.settle = read_settle(r);
  } else {
    s.settle.enabled = true;
    s.settle.ke_ratio = 1e-4;
    s.settle.max_time = 1.0;
  }
  r.finish();
  return s;
}

void read_flume(TomlReader& r, dem::DemScenario& s, const DemContext& ctx) {
  dem::FlumeParams f;
  require_2d_flume(r, ctx);
  f.shape = read_flume_shape(r);
  f.wall_material = r.required_string("wall_material");
  check_material(r, "wall_material", f.wall_material, ctx);
  f.lift_gate = r.enumeration("gate", kGateModes, 0) == 1;
  f.gate_speed = number_in(r, "gate_speed", f.gate_speed, positive());
  f.gate_open = number_in(r, "gate_open", f.gate_open, non_negative());
  const auto layers = r.integer("layers", f.layers);
  r.expect(layers >= 1 && layers <= 100, "layers", "an integer from 1 to 100");
  f.layers = static_cast<int>(layers);
  f.measures = read_flume_measures(r);
  const geometry::FlumeGeometry g = resolve_flume_shape(r, f.shape);

  auto walls = g.walls(f.wall_material);
  // The lid only holds the fill in place while it settles.
  walls.lid.motion.remove_at = f.gate_open;
  if (f.lift_gate) {
    const double height = (g.gate_top - g.gate_bottom).norm();
    walls.gate.motion.velocity = Vec3(0.0, f.gate_speed, 0.0);
    walls.gate.motion.move_start = f.gate_open;
    // Once its foot has passed the lid level the gate touches nothing.
    walls.gate.motion.remove_at = f.gate_open + height / f.gate_speed;
  } else {
    walls.gate.motion.remove_at = f.gate_open;
  }
  for (dem::WallParams* w : {&walls.chute, &walls.arc, &walls.barrier, &walls.gate, &walls.lid}) {
    w->generated = true;
    s.walls.push_back(*w);
  }
  if (auto release = r.optional_table("release")) {
    std::vector<Vec3> polygon;
    for (const auto& p : g.release) polygon.push_back(Space<2>::to3(p));
    s.sources.push_back(read_release(*release, polygon, ctx));
  }
  r.finish();
  s.flume = f;
}

}  // namespace talus::io::detail
