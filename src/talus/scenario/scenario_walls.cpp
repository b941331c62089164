// [[walls]]: geometry per wall type, and the optional prescribed motion.
#include <fmt/format.h>

#include <cmath>

#include "talus/scenario/scenario_detail.hpp"

namespace talus::io::detail {
namespace {

using dem::WallKind;

// The keys each wall type reads, to say which type a stray key belongs to.
const std::vector<std::string_view> kGeometryKeys = {
    "a",        "b",    "center", "radius", "angle_start", "angle_end", "point", "normal",
    "vertices", "file", "scale",  "offset", "axis",        "inside",    "length"};

dem::WallMotionParams read_motion(TomlReader& r, const DemContext& ctx) {
  dem::WallMotionParams m;
  m.velocity = point_or(r, "velocity", ctx, Vec3::Zero());
  m.move_start = number_in(r, "start", 0.0, non_negative());
  m.move_stop = number_in(r, "stop", dem::kNever, non_negative());
  if (m.move_stop <= m.move_start) {
    r.expect(false, "stop", fmt::format("a time after start = {} s", m.move_start));
  }
  m.angular_velocity = spin_or_zero(r, "angular_velocity", ctx);
  m.pivot = point_or(r, "pivot", ctx, Vec3::Zero());
  m.amplitude = number_in(r, "amplitude", 0.0, non_negative());
  m.frequency = number_in(r, "frequency", 0.0, non_negative());
  if (m.amplitude > 0.0 && m.frequency <= 0.0) {
    r.fail("frequency", "missing: a vibration amplitude needs a positive frequency (Hz)");
  }
  m.phase = r.angle("phase", 0.0);
  m.direction = unit_vector_or(r, "direction", ctx, up(ctx));
  m.remove_at = number_in(r, "remove_at", dem::kNever, non_negative());
  if (auto servo = r.optional_table("servo")) {
    // Stress control (the triaxial plates): pressure target, the area it acts
    // on, the largest speed, and when it hands over to the prescribed motion.
    m.servo_pressure = required_number_in(*servo, "pressure", positive());
    m.servo_area = required_number_in(*servo, "area", positive());
    m.servo_speed = required_number_in(*servo, "speed", positive());
    m.servo_stop = required_number_in(*servo, "stop", positive());
    servo->finish();
    if (m.move_start < m.servo_stop && (!m.velocity.isZero(0.0) || !m.angular_velocity.isZero(0.0)))
      r.expect(false, "start",
               fmt::format("a time at or after servo.stop = {} s (the prescribed velocity takes "
                           "over from the servo)",
                           m.servo_stop));
  }
  r.finish();
  return m;
}

void read_geometry(TomlReader& r, dem::WallParams& w, const DemContext& ctx) {
  switch (w.kind) {
    case WallKind::Segment:
      w.a = required_point(r, "a", ctx);
      w.b = required_point(r, "b", ctx);
      if (w.a == w.b) r.expect(false, "b", "an end point different from a");
      break;
    case WallKind::Arc:
      w.center = required_point(r, "center", ctx);
      w.radius = required_number_in(r, "radius", positive());
      w.angle_start = r.required_angle("angle_start");
      w.angle_end = r.required_angle("angle_end");
      // Counter-clockwise from start to end; a full circle at most.
      if (!(w.angle_end > w.angle_start) || w.angle_end - w.angle_start > 2.0 * M_PI + 1e-12) {
        r.expect(false, "angle_end",
                 fmt::format("an angle in ({}, {}] degrees (counter-clockwise from angle_start)",
                             r.text("angle_start"), rad2deg(w.angle_start) + 360.0));
      }
      break;
    case WallKind::Plane:
      w.point = required_point(r, "point", ctx);
      if (!r.has("normal")) r.missing("normal", "missing (expected [nx, ny, nz])");
      w.normal = unit_vector_or(r, "normal", ctx, Vec3::UnitZ());
      break;
    case WallKind::Triangle: {
      if (!r.has("vertices"))
        r.missing("vertices", "missing (expected [[x, y, z], [x, y, z], [x, y, z]])");
      w.vertices = r.vec3_list("vertices");
      r.expect(w.vertices.size() == 3, "vertices",
               "three points [[x, y, z], [x, y, z], [x, y, z]]");
      const Vec3 n = (w.vertices[1] - w.vertices[0]).cross(w.vertices[2] - w.vertices[0]);
      r.expect(n.norm() > 0.0, "vertices", "three points that are not on one line");
      break;
    }
    case WallKind::Mesh:
      w.file = required_file(r, "file", ctx);
      w.scale = number_in(r, "scale", 1.0, positive());
      w.offset = point_or(r, "offset", ctx, Vec3::Zero());
      break;
    case WallKind::Cylinder:
      w.point = point_or(r, "point", ctx, Vec3::Zero());
      w.axis = unit_vector_or(r, "axis", ctx, Vec3::UnitZ());
      w.radius = required_number_in(r, "radius", positive());
      w.inside = r.boolean("inside", true);
      w.length = number_in(r, "length", dem::kNever, positive());
      break;
  }
}

}  // namespace

dem::WallParams read_wall(TomlReader& r, std::size_t index, const DemContext& ctx) {
  dem::WallParams w;
  w.name = r.string("name", fmt::format("wall{}", index));
  r.expect(!w.name.empty(), "name", "a non-empty name");
  w.kind = r.required_enum("type", kWallKinds);
  const bool planar = w.kind == WallKind::Segment || w.kind == WallKind::Arc;
  if (planar != (ctx.dimension == 2)) {
    r.fail("type", fmt::format("\"{}\" walls need run.dimension = {} (this run has {}); {}",
                               name_of(kWallKinds, w.kind), planar ? 2 : 3, ctx.dimension,
                               ctx.dimension == 2 ? "2D runs use \"segment\" and \"arc\""
                                                  : "3D runs use \"plane\", \"triangle\", "
                                                    "\"mesh\" and \"cylinder\""));
  }
  w.material = r.required_string("material");
  check_material(r, "material", w.material, ctx);
  read_geometry(r, w, ctx);
  r.reject(kGeometryKeys,
           fmt::format("not used by walls of type \"{}\"", name_of(kWallKinds, w.kind)));
  if (auto motion = r.optional_table("motion")) {
    w.motion = read_motion(*motion, ctx);
    if (w.motion.servo_pressure > 0 && w.kind != WallKind::Plane)
      motion->fail("servo", "a servo needs a wall of type \"plane\" (it moves along the normal)");
  } else
    w.motion.direction = up(ctx);
  r.finish();
  return w;
}

}  // namespace talus::io::detail
