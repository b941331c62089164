// DemSimulation's walls as its caller drives them between steps (the Python
// API): readings, and translations and servos set from the current time on.
#include <fmt/core.h>

#include <algorithm>

#include "talus/core/error.hpp"
#include "talus/run/methods/dem.hpp"

namespace talus::run {

template <int D>
std::vector<WallReading> DemSimulation<D>::walls() const {
  const auto& s = run_.system;
  std::vector<WallReading> out;
  for (const auto& w : s.walls) {
    WallReading r;
    r.name = w.name;
    r.force = w.force;
    r.torque = w.torque;
    r.displacement = w.displacement(s.time);
    r.velocity = w.velocity_at(w.pivot_at(s.time), s.time);
    r.pressure = w.servo_pressure_now();
    r.servo_pressure = w.motion.servo_pressure;
    r.servo_speed = w.motion.servo_speed;
    r.servo_area = w.motion.servo_area;
    out.push_back(r);
  }
  return out;
}

template <int D>
geometry::Wall& DemSimulation<D>::wall_to_change(std::size_t wall) {
  auto& s = run_.system;
  if (wall >= s.walls.size())
    throw InputError(fmt::format("wall {}: the run has {} walls", wall, s.walls.size()));
  // The GPU backend copies the walls' motion to the device when it starts.
  if (!device_.empty())
    throw InputError(fmt::format("wall '{}': walls are driven during a run on the CPU backend only",
                                 s.walls[wall].name));
  return s.walls[wall];
}

template <int D>
void DemSimulation<D>::check_wall_speed(const geometry::Wall& wall, double speed) const {
  const auto& s = run_.system;
  const auto& r = s.particles.r;
  const double r_min = r.empty() ? 0.0 : *std::min_element(r.begin(), r.end());
  // The time step was chosen for impacts up to reference_speed (Hertz), and a
  // wall must not press a grain deeper than the smallest radius in one
  // critical step: the builder's two rules for the walls of the scenario.
  if (speed > s.reference_speed)
    throw InputError(fmt::format(
        "wall '{}': {:.4g} m/s is faster than the impact speed the time step was chosen for "
        "({:.4g} m/s); give the wall that speed in the scenario so the step accounts for it",
        wall.name, speed, s.reference_speed));
  if (r_min > 0.0 && speed * s.critical_time_step > r_min)
    throw InputError(fmt::format(
        "wall '{}': at {:.4g} m/s a particle it strikes would be pressed about {:.3g} m into it, "
        "more than the smallest radius ({:.3g} m); slow it below {:.3g} m/s",
        wall.name, speed, speed * s.critical_time_step, r_min, r_min / s.critical_time_step));
}

template <int D>
void DemSimulation<D>::set_velocity(std::size_t wall, const Vec3& v) {
  auto& w = wall_to_change(wall);
  if (D == 2 && v.z() != 0.0)
    throw InputError(
        fmt::format("wall '{}': a 2D wall moves in the xy plane (v_z = {})", w.name, v.z()));
  check_wall_speed(w, v.norm());
  w.set_velocity(v, run_.system.time);
}

template <int D>
void DemSimulation<D>::set_servo(std::size_t wall, double pressure, double speed, double area) {
  auto& w = wall_to_change(wall);
  if (pressure != 0.0) check_wall_speed(w, speed);
  w.set_servo(pressure, speed, area);
}

template std::vector<WallReading> DemSimulation<2>::walls() const;
template std::vector<WallReading> DemSimulation<3>::walls() const;
template void DemSimulation<2>::set_velocity(std::size_t, const Vec3&);
template void DemSimulation<3>::set_velocity(std::size_t, const Vec3&);
template void DemSimulation<2>::set_servo(std::size_t, double, double, double);
template void DemSimulation<3>::set_servo(std::size_t, double, double, double);

}  // namespace talus::run
