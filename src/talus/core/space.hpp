#pragma once
// Dimension traits: one code path for 2D disks and 3D spheres.
// In 2D, rotations happen about z only, so angular quantities are scalars.
#include <Eigen/Core>
#include <Eigen/Geometry>
#include <cmath>

namespace talus {

using Vec3 = Eigen::Vector3d;

template <int D>
struct Space;

template <>
struct Space<2> {
  static constexpr int dim = 2;
  using Vec = Eigen::Vector2d;
  using Rot = double;  // angular velocity, torque, rotation about z

  static Rot cross(const Vec& a, const Vec& b) { return a.x() * b.y() - a.y() * b.x(); }
  static Vec cross(Rot w, const Vec& b) { return Vec(-w * b.y(), w * b.x()); }
  static Rot rot_zero() { return 0.0; }
  static double rot_norm(Rot w) { return std::abs(w); }
  static double rot_dot(Rot a, Rot b) { return a * b; }
  static Vec from3(const Vec3& v) { return Vec(v.x(), v.y()); }
  static Vec3 to3(const Vec& v) { return Vec3(v.x(), v.y(), 0.0); }
  static Vec3 rot_to3(Rot w) { return Vec3(0.0, 0.0, w); }
  static Rot rot_from3(const Vec3& w) { return w.z(); }
  // Disks of unit thickness (PFC2D convention): mass per metre of depth.
  static double volume(double r) { return M_PI * r * r; }
  static double inertia_factor() { return 0.5; }
};

template <>
struct Space<3> {
  static constexpr int dim = 3;
  using Vec = Eigen::Vector3d;
  using Rot = Eigen::Vector3d;

  static Vec cross(const Vec& a, const Vec& b) { return a.cross(b); }
  static Rot rot_zero() { return Rot::Zero(); }
  static double rot_norm(const Rot& w) { return w.norm(); }
  static double rot_dot(const Rot& a, const Rot& b) { return a.dot(b); }
  static Vec from3(const Vec3& v) { return v; }
  static Vec3 to3(const Vec& v) { return v; }
  static Vec3 rot_to3(const Rot& w) { return w; }
  static Rot rot_from3(const Vec3& w) { return w; }
  static double volume(double r) { return 4.0 / 3.0 * M_PI * r * r * r; }
  static double inertia_factor() { return 0.4; }
};

inline double deg2rad(double deg) { return deg * M_PI / 180.0; }
inline double rad2deg(double rad) { return rad * 180.0 / M_PI; }

}  // namespace talus
