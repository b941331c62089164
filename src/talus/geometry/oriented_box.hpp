#pragma once
// Boxes turned in space, and whether two of them overlap (separating axis
// theorem). Used to refuse a scenario whose material starts inside a rigid
// body: the first contact step would then push it out at whatever speed the
// overlap asks for (a clay block that started 1.3 cm inside its obstacle was
// crushed before it moved; docs/validation.md "Clay block").
#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <limits>

#include "talus/core/space.hpp"

namespace talus::geometry {

struct OrientedBox {
  Vec3 centre = Vec3::Zero();
  Eigen::Matrix3d axes = Eigen::Matrix3d::Identity();  // columns: the box's unit axes
  Vec3 half = Vec3::Zero();                            // half extents along them

  // The box [min, max] turned by `rotation` about `pivot`.
  static OrientedBox turned(const Vec3& min, const Vec3& max, const Eigen::Matrix3d& rotation,
                            const Vec3& pivot) {
    OrientedBox b;
    b.centre = pivot + rotation * (0.5 * (min + max) - pivot);
    b.axes = rotation;
    b.half = 0.5 * (max - min);
    return b;
  }
};

// How deep the two boxes overlap: the smallest overlap of their projections
// over the 15 candidate separating axes (3 + 3 face normals, 9 edge-edge
// cross products); 0 or negative means they are apart or only touch.
inline double overlap_depth(const OrientedBox& a, const OrientedBox& b) {
  double depth = std::numeric_limits<double>::infinity();
  const Vec3 d = b.centre - a.centre;
  auto radius = [](const OrientedBox& box, const Vec3& axis) {
    double r = 0.0;
    for (int i = 0; i < 3; ++i) r += box.half[i] * std::abs(box.axes.col(i).dot(axis));
    return r;
  };
  auto test = [&](Vec3 axis) {
    const double n = axis.norm();
    if (n < 1e-9) return;  // parallel edges: covered by the face normals
    axis /= n;
    depth = std::min(depth, radius(a, axis) + radius(b, axis) - std::abs(d.dot(axis)));
  };
  for (int i = 0; i < 3; ++i) {
    test(a.axes.col(i));
    test(b.axes.col(i));
  }
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) test(a.axes.col(i).cross(b.axes.col(j)));
  return depth;
}

}  // namespace talus::geometry
