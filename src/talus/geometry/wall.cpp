#include "talus/geometry/wall.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "talus/core/error.hpp"
#include "talus/geometry/stl.hpp"

namespace talus::geometry {

namespace {

// Time spent moving by t: translation and rotation run on [move_start, move_stop).
double moving_time(const WallMotionParams& m, double t) {
  return std::clamp(t - m.move_start, 0.0, std::max(0.0, m.move_stop - m.move_start));
}

bool moving_at(const WallMotionParams& m, double t) { return t >= m.move_start && t < m.move_stop; }

}  // namespace

Vec3 Wall::displacement(double t) const {
  Vec3 d = shift + motion.velocity * moving_time(motion, t) + servo_travel * servo_normal;
  if (motion.amplitude != 0) {
    d += motion.amplitude * std::sin(2 * M_PI * motion.frequency * t + motion.phase) *
         motion.direction.normalized();
  }
  return d;
}

double Wall::rotation_angle(double t) const {
  return motion.angular_velocity.norm() * moving_time(motion, t);
}

bool Wall::moves() const {
  const bool translates = motion.velocity != Vec3::Zero() && motion.move_stop > motion.move_start;
  const bool rotates =
      motion.angular_velocity != Vec3::Zero() && motion.move_stop > motion.move_start;
  // A wall a servo or a replaced velocity has moved stays moved.
  const bool moved = servo_travel != 0.0 || shift != Vec3::Zero();
  return translates || rotates || motion.amplitude != 0 || has_servo() || moved;
}

void Wall::set_velocity(const Vec3& v, double t) {
  if (motion.angular_velocity != Vec3::Zero())
    throw InputError(fmt::format(
        "wall '{}' rotates: its translation cannot be changed during the run (the rotation "
        "angle counts from the motion's start)",
        name));
  if (!v.allFinite()) throw InputError(fmt::format("wall '{}': velocity must be finite", name));
  // displacement(t) is the same number before and after: shift takes the
  // translation so far, and the new one has run for no time yet.
  shift += motion.velocity * moving_time(motion, t);
  motion.velocity = v;
  motion.move_start = t;
  motion.move_stop = kNever;
}

void Wall::set_servo(double pressure, double speed, double area) {
  if (pressure == 0.0) {
    motion.servo_pressure = 0.0;
    servo_speed = 0.0;
    return;
  }
  if (reference.size() != 1 || reference[0].kind != PrimitiveKind::Plane)
    throw InputError(
        fmt::format("wall '{}': a servo needs a plane wall (it moves along the normal)", name));
  if (!(pressure > 0) || !(speed > 0) || !(area > 0) || !std::isfinite(pressure) ||
      !std::isfinite(speed) || !std::isfinite(area))
    throw InputError(fmt::format(
        "wall '{}': a servo needs a finite pressure, speed and area > 0 (got {}, {}, {})", name,
        pressure, speed, area));
  servo_normal = reference[0].n;
  motion.servo_pressure = pressure;
  motion.servo_speed = speed;
  motion.servo_area = area;
  motion.servo_stop = kNever;
}

double Wall::servo_pressure_now() const {
  return motion.servo_area > 0 ? -force.dot(servo_normal) / motion.servo_area : 0.0;
}

void Wall::advance_servo(double t, double dt) {
  if (!has_servo() || t >= motion.servo_stop) {
    servo_speed = 0.0;
    return;
  }
  // Proportional control saturating at servo_speed: the wall approaches at
  // full speed while nothing pushes back and settles where p = p*.
  const double error = (motion.servo_pressure - servo_pressure_now()) / motion.servo_pressure;
  servo_speed = motion.servo_speed * std::clamp(error, -1.0, 1.0);
  servo_travel += servo_speed * dt;
}

void Wall::update(double t) {
  if (!moves()) {
    current = reference;
    return;
  }
  const Vec3 pivot = motion.pivot;
  const Vec3 shift = displacement(t);
  const double omega = motion.angular_velocity.norm();
  const Eigen::Matrix3d rot =
      omega > 0 ? Eigen::AngleAxisd(rotation_angle(t), motion.angular_velocity / omega).matrix()
                : Eigen::Matrix3d::Identity();
  // Arcs live in the xy plane, where rotations are about z (make_wall checks).
  const double arc_turn = motion.angular_velocity.z() * moving_time(motion, t);
  auto place = [&](const Vec3& x) -> Vec3 { return pivot + shift + rot * (x - pivot); };
  current.resize(reference.size());
  for (std::size_t i = 0; i < reference.size(); ++i) {
    const Primitive& ref = reference[i];
    Primitive& cur = current[i];
    cur = ref;
    cur.p0 = place(ref.p0);
    cur.p1 = place(ref.p1);
    cur.p2 = place(ref.p2);
    cur.n = rot * ref.n;
    if (ref.kind == PrimitiveKind::Arc) {
      cur.angle_start = ref.angle_start + arc_turn;
      cur.angle_end = ref.angle_end + arc_turn;
    }
  }
}

Vec3 Wall::velocity_at(const Vec3& point, double t) const {
  Vec3 v = Vec3::Zero();
  if (moving_at(motion, t)) {
    v += motion.velocity + motion.angular_velocity.cross(point - pivot_at(t));
  }
  v += servo_speed * servo_normal;
  if (motion.amplitude != 0) {
    const double w = 2 * M_PI * motion.frequency;
    v += motion.amplitude * w * std::cos(w * t + motion.phase) * motion.direction.normalized();
  }
  return v;
}

void Wall::add_work(double t, double dt) {
  if (!moves()) return;
  // The particles feel -force, applied where each touches the wall, moving
  // with velocity_at(pivot) + omega x (point - pivot): summed over the
  // contacts this is -(force . v(pivot) + torque . omega), torque being about the pivot.
  work -= (force.dot(velocity_at(pivot_at(t), t)) + torque.dot(angular_velocity_at(t))) * dt;
}

double Wall::reach() const {
  double r = 0.0;
  for (const auto& prim : reference)
    for (const Vec3& q : {prim.p0, prim.p1, prim.p2})
      r = std::max(r, (q - motion.pivot).norm() + prim.radius);
  return r;
}

double Wall::top_speed() const {
  if (!moves()) return 0.0;
  double v = 0.0;
  if (motion.move_stop > motion.move_start)
    v += motion.velocity.norm() + motion.angular_velocity.norm() * reach();
  v += 2 * M_PI * std::abs(motion.frequency * motion.amplitude);
  if (has_servo()) v += std::abs(motion.servo_speed);
  return v;
}

Vec3 Wall::angular_velocity_at(double t) const {
  return moving_at(motion, t) ? motion.angular_velocity : Vec3::Zero();
}

void Wall::bounds(Vec3& lo, Vec3& hi) const {
  lo = Vec3::Constant(kInf);
  hi = Vec3::Constant(-kInf);
  for (const Primitive& p : current) {
    Vec3 plo, phi;
    geometry::bounds(p, plo, phi);
    lo = lo.cwiseMin(plo);
    hi = hi.cwiseMax(phi);
  }
}

namespace {

[[noreturn]] void fail(const WallParams& w, const std::string& what) {
  throw InputError(fmt::format("wall '{}': {}", w.name, what));
}

// Relative tolerance for degenerate geometry, in units of the coordinates' size.
constexpr double kDegenerate = 1e-12;

Vec3 unit(const WallParams& w, const Vec3& v, const char* key) {
  const double len = v.norm();
  if (!(len > 0) || !std::isfinite(len)) fail(w, fmt::format("{} must be a non-zero vector", key));
  return v / len;
}

Primitive segment(const WallParams& w) {
  const double scale = std::max({1.0, w.a.norm(), w.b.norm()});
  if ((w.b - w.a).norm() <= kDegenerate * scale) fail(w, "segment end points a and b coincide");
  Primitive p;
  p.kind = PrimitiveKind::Segment;
  p.p0 = w.a;
  p.p1 = w.b;
  return p;
}

Primitive arc(const WallParams& w) {
  if (!(w.radius > 0)) fail(w, "radius must be positive");
  if (!(w.angle_end > w.angle_start) || !std::isfinite(w.angle_end - w.angle_start))
    fail(w, "angle_end must be greater than angle_start");
  Primitive p;
  p.kind = PrimitiveKind::Arc;
  p.p0 = w.center;
  p.radius = w.radius;
  p.angle_start = w.angle_start;
  p.angle_end = w.angle_end;
  return p;
}

Primitive plane(const WallParams& w, int dimension) {
  Primitive p;
  p.kind = PrimitiveKind::Plane;
  p.p0 = w.point;
  if (dimension == 2) {
    if (std::hypot(w.normal.x(), w.normal.y()) <= kDegenerate * w.normal.norm())
      fail(w, "normal must have an x or y component in 2D");
    p.n = unit(w, Vec3(w.normal.x(), w.normal.y(), 0), "normal");
  } else {
    p.n = unit(w, w.normal, "normal");
  }
  return p;
}

Primitive cylinder(const WallParams& w) {
  if (!(w.radius > 0)) fail(w, "radius must be positive");
  if (!(w.length > 0)) fail(w, "length must be positive");
  Primitive p;
  p.kind = PrimitiveKind::Cylinder;
  p.p0 = w.point;
  p.n = unit(w, w.axis, "axis");
  p.radius = w.radius;
  p.length = w.length;
  p.inside = w.inside;
  return p;
}

void check_motion(const WallParams& w, int dimension) {
  const WallMotionParams& m = w.motion;
  if (m.move_stop < m.move_start) fail(w, "move_stop must not be before move_start");
  if (m.amplitude != 0) {
    unit(w, m.direction, "direction");
    if (m.frequency < 0) fail(w, "frequency must not be negative");
  }
  if (dimension == 2) {
    if (m.angular_velocity.x() != 0 || m.angular_velocity.y() != 0)
      fail(w, "in 2D, angular_velocity must be about z");
    if (m.amplitude != 0 && m.direction.head<2>().isZero())
      fail(w, "in 2D, the vibration direction must have an x or y component");
  }
}

const char* kind_name(WallKind kind) {
  switch (kind) {
    case WallKind::Segment:
      return "segment";
    case WallKind::Arc:
      return "arc";
    case WallKind::Plane:
      return "plane";
    case WallKind::Triangle:
      return "triangle";
    case WallKind::Mesh:
      return "mesh";
    case WallKind::Cylinder:
      return "cylinder";
  }
  return "?";
}

}  // namespace

Wall make_wall(const WallParams& params, int material_index, int dimension) {
  WallParams w = params;
  if (dimension == 2) w.a.z() = w.b.z() = w.center.z() = w.point.z() = 0;  // 2D walls lie in z = 0
  if (dimension != 2 && dimension != 3)
    fail(w, fmt::format("dimension {} is not 2 or 3", dimension));
  const bool kind_2d = w.kind == WallKind::Segment || w.kind == WallKind::Arc;
  const bool kind_3d = w.kind != WallKind::Plane && !kind_2d;
  if ((dimension == 2 && kind_3d) || (dimension == 3 && kind_2d))
    fail(w, fmt::format("kind '{}' is not available in {}D", kind_name(w.kind), dimension));
  check_motion(w, dimension);

  Wall wall;
  wall.name = w.name;
  wall.material = material_index;
  wall.dimension = dimension;
  wall.motion = w.motion;
  switch (w.kind) {
    case WallKind::Segment:
      wall.reference.push_back(segment(w));
      break;
    case WallKind::Arc:
      wall.reference.push_back(arc(w));
      break;
    case WallKind::Plane:
      wall.reference.push_back(plane(w, dimension));
      break;
    case WallKind::Triangle: {
      Primitive p;
      if (w.vertices.size() != 3)
        fail(w, fmt::format("a triangle needs 3 vertices, got {}", w.vertices.size()));
      if (!make_triangle(w.vertices[0], w.vertices[1], w.vertices[2], p))
        fail(w, "degenerate triangle (vertices on one line)");
      wall.reference.push_back(p);
      break;
    }
    case WallKind::Mesh: {
      if (!(w.scale > 0) || !std::isfinite(w.scale)) fail(w, "scale must be positive");
      wall.reference = read_stl(w.file, w.scale, w.offset);
      if (wall.reference.empty()) fail(w, fmt::format("mesh file '{}' has no triangles", w.file));
      break;
    }
    case WallKind::Cylinder:
      wall.reference.push_back(cylinder(w));
      break;
  }
  if (w.motion.servo_pressure != 0) {
    if (w.kind != WallKind::Plane)
      fail(w, "a servo needs a plane wall (it moves along the normal)");
    if (!(w.motion.servo_area > 0) || !(w.motion.servo_speed > 0))
      fail(w, "a servo needs a positive area and speed");
    wall.servo_normal = wall.reference[0].n;
  }
  wall.current = wall.reference;
  wall.update(0.0);
  return wall;
}

}  // namespace talus::geometry
