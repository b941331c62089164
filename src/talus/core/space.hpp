#pragma once
// Dimension traits: one code path for 2D disks and 3D spheres.
// In 2D, rotations happen about z only, so angular quantities are scalars.
#include <Eigen/Core>
#include <Eigen/Geometry>
#include <cmath>
#include <type_traits>

// Hot per-contact functions are forced inline: the stepper instantiates many
// contact models in one translation unit, where GCC's inliner gives up early.
// Compiled by nvcc (the GPU backend, dem/gpu/) they are device functions too,
// so the GPU runs the very contact laws the CPU runs.
// TALUS_HD marks other code the GPU shares (wall primitives' closest points).
#ifdef __CUDACC__
#define TALUS_HOT __host__ __device__ inline __attribute__((always_inline))
#define TALUS_HD __host__ __device__
#else
#define TALUS_HOT inline __attribute__((always_inline))
#define TALUS_HD
#endif

namespace talus {

using Vec3 = Eigen::Vector3d;

// Zero for small fixed vectors and scalars, written out so that it inlines
// (Eigen's setZero goes through an out-of-line std::fill_n here).
template <class T>
TALUS_HOT T zero_of() {
  if constexpr (std::is_arithmetic_v<T>) {
    return T(0);
  } else {
    T v;
    for (int d = 0; d < T::RowsAtCompileTime; ++d) v[d] = 0.0;
    return v;
  }
}

template <int D>
struct Space;

template <>
struct Space<2> {
  static constexpr int dim = 2;
  using Vec = Eigen::Vector2d;
  using Rot = double;  // angular velocity, torque, rotation about z

  TALUS_HOT static Rot cross(const Vec& a, const Vec& b) { return a.x() * b.y() - a.y() * b.x(); }
  TALUS_HOT static Vec cross(Rot w, const Vec& b) { return Vec(-w * b.y(), w * b.x()); }
  TALUS_HOT static Rot rot_zero() { return 0.0; }
  TALUS_HOT static double rot_norm(Rot w) { return std::abs(w); }
  TALUS_HOT static double rot_dot(Rot a, Rot b) { return a * b; }
  TALUS_HOT static Vec from3(const Vec3& v) { return Vec(v.x(), v.y()); }
  TALUS_HOT static Vec3 to3(const Vec& v) { return Vec3(v.x(), v.y(), 0.0); }
  TALUS_HOT static Vec3 rot_to3(Rot w) { return Vec3(0.0, 0.0, w); }
  TALUS_HOT static Rot rot_from3(const Vec3& w) { return w.z(); }
  // Disks of unit thickness (PFC2D convention): mass per metre of depth.
  TALUS_HOT static double volume(double r) { return M_PI * r * r; }
  TALUS_HOT static double inertia_factor() { return 0.5; }
};

template <>
struct Space<3> {
  static constexpr int dim = 3;
  using Vec = Eigen::Vector3d;
  using Rot = Eigen::Vector3d;

  TALUS_HOT static Vec cross(const Vec& a, const Vec& b) { return a.cross(b); }
  TALUS_HOT static Rot rot_zero() { return zero_of<Rot>(); }
  TALUS_HOT static double rot_norm(const Rot& w) { return w.norm(); }
  TALUS_HOT static double rot_dot(const Rot& a, const Rot& b) { return a.dot(b); }
  TALUS_HOT static Vec from3(const Vec3& v) { return v; }
  TALUS_HOT static Vec3 to3(const Vec& v) { return v; }
  TALUS_HOT static Vec3 rot_to3(const Rot& w) { return w; }
  TALUS_HOT static Rot rot_from3(const Vec3& w) { return w; }
  TALUS_HOT static double volume(double r) { return 4.0 / 3.0 * M_PI * r * r * r; }
  TALUS_HOT static double inertia_factor() { return 0.4; }
};

inline double deg2rad(double deg) { return deg * M_PI / 180.0; }
inline double rad2deg(double rad) { return rad * 180.0 / M_PI; }

}  // namespace talus
