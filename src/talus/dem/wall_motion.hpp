#pragma once
// How far the walls have moved since the last neighbour build: a list is
// rebuilt once this passes half the skin (the CPU stepper and the GPU backend).
#include <vector>

#include "talus/geometry/wall.hpp"

namespace talus::dem {

// Largest distance any point of a moving wall has travelled between the build
// (displacement and rotation angle of each wall then) and time t: translation
// and vibration exactly, rotation bounded by the angle times the farthest
// reach from the pivot.
double wall_motion_since(const std::vector<geometry::Wall>& walls, double t,
                         const std::vector<Vec3>& displacement_at_build,
                         const std::vector<double>& angle_at_build);

}  // namespace talus::dem
