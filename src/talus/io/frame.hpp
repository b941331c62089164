#pragma once
// Plain snapshots handed to the writers. The io layer knows no physics: a
// solver fills these from its own state and the writers only serialise them.
#include <array>
#include <cstdint>
#include <map>
#include <string>
#include <vector>

#include "talus/core/space.hpp"

namespace talus::io {

// One snapshot of particles; 2D runs have z = 0 (and angular velocity along z).
// Every per-particle array has the same length as `position`.
struct ParticleFrame {
  std::vector<Vec3> position, velocity, angular_velocity;
  std::vector<double> radius;
  std::vector<int64_t> id;
  std::vector<int> material, contacts;
  std::map<std::string, std::vector<double>> extra_scalars;  // optional fields, e.g. "layer"
};

// Wall geometry as lines (2D) and triangles (3D), indices into `points`.
struct WallFrame {
  std::vector<Vec3> points;
  std::vector<std::array<int, 2>> lines;
  std::vector<std::array<int, 3>> triangles;
  std::vector<int> line_wall, triangle_wall;  // wall index of each cell
};

// A deforming triangle surface (a DEM membrane): per-point vectors (e.g.
// velocity) and per-triangle scalars (e.g. tension), each as long as its points
// or triangles.
struct MeshFrame {
  std::vector<Vec3> points;
  std::vector<std::array<int, 3>> triangles;
  std::map<std::string, std::vector<Vec3>> point_vectors;
  std::map<std::string, std::vector<double>> point_scalars;
  std::map<std::string, std::vector<double>> cell_scalars;
};

}  // namespace talus::io
