#pragma once
// The walls of a run as its caller sees them between steps (the Python API):
// what each one feels and how it moves, and its motion changed from the
// current time on. Methods with walls (DEM) implement it; the run loop never
// calls it.
#include <cstddef>
#include <string>
#include <vector>

#include "talus/core/space.hpp"

namespace talus::run {

struct WallReading {
  std::string name;
  Vec3 force = Vec3::Zero();         // N (N/m in 2D), what the particles exert on it
  Vec3 torque = Vec3::Zero();        // about its pivot
  Vec3 displacement = Vec3::Zero();  // m, of its pivot since t = 0
  Vec3 velocity = Vec3::Zero();      // m/s, of its pivot now (translation, servo, vibration)
  double pressure = 0.0;             // Pa, normal force over the servo area (0 without one)
  double servo_pressure = 0.0;       // Pa, the servo's target (0: no servo)
  double servo_speed = 0.0;          // m/s, the servo's largest speed
  double servo_area = 0.0;           // m^2 (m in 2D)
};

class WallControl {
 public:
  virtual ~WallControl() = default;
  virtual std::vector<WallReading> walls() const = 0;
  // From now on the wall translates at v (m/s). InputError where that cannot
  // be: an unknown wall, a rotating wall, a speed the time step cannot follow.
  virtual void set_velocity(std::size_t wall, const Vec3& v) = 0;
  // From now on a servo holds the pressure on a plane wall (0: servo off).
  virtual void set_servo(std::size_t wall, double pressure, double speed, double area) = 0;
};

}  // namespace talus::run
