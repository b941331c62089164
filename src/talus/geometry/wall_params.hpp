#pragma once
// What a scenario says about a wall: its shape, material name and prescribed
// motion. Plain data, SI units, angles in radians; geometry/wall.hpp builds
// the wall from it.
#include <limits>
#include <string>
#include <vector>

#include "talus/core/space.hpp"

namespace talus::geometry {

inline constexpr double kNever = std::numeric_limits<double>::infinity();

enum class WallKind { Segment, Arc, Plane, Triangle, Mesh, Cylinder };

struct WallMotionParams {
  Vec3 velocity = Vec3::Zero();          // translation, m/s
  double move_start = 0.0;               // s
  double move_stop = kNever;             // s
  Vec3 angular_velocity = Vec3::Zero();  // rad/s about pivot
  Vec3 pivot = Vec3::Zero();
  double amplitude = 0.0;  // m, vibration x(t) = A sin(2 pi f t + phase) along direction
  double frequency = 0.0;  // Hz
  double phase = 0.0;      // rad
  Vec3 direction = Vec3::UnitZ();
  double remove_at = kNever;  // s
  // Stress control of a plane wall (the triaxial test's plates, Götz 2024
  // §3.3.1): while t < servo_stop the wall moves along its normal n (towards
  // the particles) at v = servo_speed * clamp((p* - p) / p*, -1, 1), where
  // p = -F.n / servo_area is the pressure the particles exert on it and p* =
  // servo_pressure; afterwards it stays where the servo left it (plus any
  // prescribed motion). servo_pressure = 0: no servo.
  double servo_pressure = 0.0;  // Pa
  double servo_area = 0.0;      // m^2
  double servo_speed = 0.0;     // m/s, the largest servo speed
  double servo_stop = 0.0;      // s
};

struct WallParams {
  std::string name;
  WallKind kind = WallKind::Plane;
  std::string material;
  // Segment: a, b. Arc: center, radius, angle_start, angle_end (radians, counter-clockwise).
  // Plane: point, normal. Triangle: vertices[0..2]. Mesh: file (STL), scale, offset.
  // Cylinder: point (on axis), axis, radius, inside, length (kNever = infinite).
  Vec3 a = Vec3::Zero(), b = Vec3::Zero(), center = Vec3::Zero(), point = Vec3::Zero();
  Vec3 normal = Vec3::UnitZ(), axis = Vec3::UnitZ(), offset = Vec3::Zero();
  std::vector<Vec3> vertices;
  double radius = 0.0, angle_start = 0.0, angle_end = 0.0, scale = 1.0, length = kNever;
  bool inside = true;
  std::string file;
  WallMotionParams motion;
  bool generated = false;  // by [flume] or [dam_break], which the resolved scenario writes instead
};

}  // namespace talus::geometry
