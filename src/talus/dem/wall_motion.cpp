#include "talus/dem/wall_motion.hpp"

#include <algorithm>
#include <cmath>

namespace talus::dem {

double wall_motion_since(const std::vector<geometry::Wall>& walls, double t,
                         const std::vector<Vec3>& displacement_at_build,
                         const std::vector<double>& angle_at_build) {
  double moved = 0.0;
  for (std::size_t k = 0; k < walls.size(); ++k) {
    const auto& w = walls[k];
    if (!w.moves()) continue;
    double d = (w.displacement(t) - displacement_at_build[k]).norm();
    if (w.motion.angular_velocity.squaredNorm() > 0.0)
      d += std::abs(w.rotation_angle(t) - angle_at_build[k]) * w.reach();
    moved = std::max(moved, d);
  }
  return moved;
}

}  // namespace talus::dem
