#pragma once
// A wall: a set of primitives that moves as one rigid body and collects the
// force the particles exert on it.
//
// Motion (WallMotionParams), all exact functions of time so that a run
// resumed from a checkpoint puts the walls exactly where they were:
//   - translation with `velocity` while move_start <= t < move_stop,
//   - rotation with `angular_velocity` about `pivot` over the same interval
//     (the pivot travels with the wall),
//   - vibration A sin(2 pi f t + phase) along `direction`, at all times, so the
//     given geometry is the rest position and update(0) applies A sin(phase),
//   - removal: the wall is inactive from remove_at on,
//   - a servo (plane walls, motion.servo_*): the one motion that is state, not
//     a function of time: advance_servo() moves the wall along its normal from
//     the force of the last step until servo_stop, and displacement() adds the
//     distance travelled (servo_travel).
#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include "talus/geometry/flume_params.hpp"
#include "talus/geometry/primitive.hpp"
#include "talus/geometry/wall_params.hpp"

namespace talus::geometry {

struct Wall {
  std::string name;
  int material = 0;                  // index into the scenario's materials
  int dimension = 3;                 // 2 or 3
  std::vector<Primitive> reference;  // geometry as given, zero displacement
  std::vector<Primitive> current;    // geometry at the time of the last update()
  WallMotionParams motion;
  // Filled by the solver. Torque is about the current pivot, pivot_at(t)
  // (the origin unless a pivot is given); impulse is the time integral of force.
  Vec3 force = Vec3::Zero();
  Vec3 torque = Vec3::Zero();
  Vec3 impulse = Vec3::Zero();
  // Work the wall has done on what touches it (J): the time integral of
  // -(force . v(pivot) + torque . omega), the power its motion delivers; zero
  // for a wall that never moves. The energy check counts it as energy put in.
  double work = 0.0;
  // Component-wise extremes of `force` over the steps closed since the run
  // loop last reset them (after each series row): what a force sensor read
  // every step records. An interval's mean force (from `impulse`) smooths
  // away a grain's impact, which lasts a few dozen steps; its peak is the
  // number that changes with the contact stiffness (Kuen 2011 §7.1).
  Vec3 force_max = Vec3::Constant(-std::numeric_limits<double>::infinity());
  Vec3 force_min = Vec3::Constant(std::numeric_limits<double>::infinity());
  // Servo state: distance moved along servo_normal (the plane's normal, towards
  // the particles) and the speed of the current step.
  Vec3 servo_normal = Vec3::UnitZ();
  double servo_travel = 0.0, servo_speed = 0.0;
  // Translation under the velocities a caller has since replaced
  // (set_velocity): state like servo_travel, so the wall goes on from where
  // it stands.
  Vec3 shift = Vec3::Zero();

  // Takes `force` into the extremes (the solver, once per closed step).
  void note_force() {
    force_max = force_max.cwiseMax(force);
    force_min = force_min.cwiseMin(force);
  }
  // Adds a closed step's share of `work`, its forces taken at time t.
  void add_work(double t, double dt);
  void reset_force_extremes() {
    force_max.setConstant(-std::numeric_limits<double>::infinity());
    force_min.setConstant(std::numeric_limits<double>::infinity());
  }
  // Per component the extreme of larger magnitude, with its sign; `fallback`
  // when no step was closed since the last reset.
  Vec3 largest_force(const Vec3& fallback) const {
    if (!(force_max.x() >= force_min.x())) return fallback;
    Vec3 out;
    for (int c = 0; c < 3; ++c)
      out[c] = std::abs(force_max[c]) >= std::abs(force_min[c]) ? force_max[c] : force_min[c];
    return out;
  }

  // Recomputes `current` from `reference` and the motion at time t.
  void update(double t);
  // Velocity of the wall material at `point` (a point of the current geometry).
  Vec3 velocity_at(const Vec3& point, double t) const;
  // Its angular velocity at time t (zero outside [move_start, move_stop)):
  // velocity_at(x, t) = velocity_at(pivot_at(t), t) + this x (x - pivot_at(t)).
  Vec3 angular_velocity_at(double t) const;
  bool active(double t) const { return t < motion.remove_at; }
  // Displacement of the pivot: translation plus vibration.
  Vec3 displacement(double t) const;
  Vec3 pivot_at(double t) const { return motion.pivot + displacement(t); }
  // Signed rotation angle about angular_velocity's direction.
  double rotation_angle(double t) const;
  // False for a wall that never moves: update() is then a no-op.
  bool moves() const;
  bool has_servo() const { return motion.servo_pressure != 0.0; }
  // Between steps (the Python API): from time t on, translate at v with no
  // end; the translation so far moves into `shift`, so the wall does not jump.
  // Throws InputError for a wall with a rotation (its angle counts from
  // move_start, which this resets).
  void set_velocity(const Vec3& v, double t);
  // Between steps: hold the pressure p (Pa) on a plane wall from now on,
  // moving at up to `speed` (m/s), p measured over `area` (m^2); p = 0 turns
  // the servo off and the wall stays where it is. Throws InputError for a wall
  // that is not one plane or for p, speed, area not > 0.
  void set_servo(double pressure, double speed, double area);
  // Pressure the particles exert on the wall, -force . servo_normal / servo_area.
  double servo_pressure_now() const;
  // The servo's step from t to t + dt (call before update(t + dt)), from the
  // force of the step that ended at t; no-op without a servo or from servo_stop on.
  void advance_servo(double t, double dt);
  // Farthest distance of the given geometry from the pivot (at rest).
  double reach() const;
  // Largest speed any point of the wall reaches in the run: translation plus
  // rotation times reach() plus the vibration's 2 pi f A, or the servo's top speed.
  double top_speed() const;
  // Axis-aligned box around the current primitives.
  void bounds(Vec3& lo, Vec3& hi) const;
};

// Turns validated wall parameters into a wall at t = 0. Throws InputError,
// naming the wall, for degenerate geometry or a kind that does not exist in
// `dimension` (2D: Segment, Arc, Plane; 3D: Plane, Triangle, Mesh, Cylinder).
Wall make_wall(const WallParams& params, int material_index, int dimension);

}  // namespace talus::geometry
