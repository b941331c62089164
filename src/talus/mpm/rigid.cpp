#include "talus/mpm/rigid.hpp"

#include <Eigen/Geometry>
#include <algorithm>

namespace talus::mpm {

namespace {

// Rotation by the angular velocity w over time tau, as a D x D matrix.
template <int D>
Eigen::Matrix<double, D, D> rotation(const Vec3& w, double tau) {
  if constexpr (D == 2) {
    return Eigen::Rotation2Dd(w.z() * tau).toRotationMatrix();
  } else {
    const double rate = w.norm();
    if (rate == 0.0) return Eigen::Matrix3d::Identity();
    return Eigen::AngleAxisd(rate * tau, w / rate).toRotationMatrix();
  }
}

}  // namespace

template <int D>
double RigidBody<D>::active_time(double t0, double t1) const {
  return std::max(0.0, std::min(t1, motion.stop) - std::max(t0, motion.start));
}

template <int D>
typename RigidBody<D>::Vec RigidBody<D>::velocity_at(const Vec& y, double t, double dt) const {
  const double tau = active_time(t, t + dt);
  if (tau <= 0.0) return Vec::Zero();
  // Mean velocity over the step: the displacement of the exact motion / dt.
  const Vec r = y - hinge;
  const Vec moved = rotation<D>(motion.angular_velocity, tau) * r - r;
  return (moved + tau * Space<D>::from3(motion.velocity)) / dt;
}

template <int D>
void RigidBody<D>::advance(double t, double dt) {
  const double tau = active_time(t, t + dt);
  if (tau <= 0.0) return;
  const auto q = rotation<D>(motion.angular_velocity, tau);
  const Vec shift = tau * Space<D>::from3(motion.velocity);
  for (auto& y : x) y = hinge + q * (y - hinge) + shift;
  for (auto& n : normal) n = q * n;
  hinge += shift;
  angle += D == 2 ? motion.angular_velocity.z() * tau : motion.angular_velocity.norm() * tau;
}

template <int D>
double RigidBody<D>::max_speed(double t) const {
  if (t < motion.start || t >= motion.stop) return 0.0;
  const double w = D == 2 ? std::abs(motion.angular_velocity.z()) : motion.angular_velocity.norm();
  double r = 0.0;
  for (const auto& y : x) r = std::max(r, (y - hinge).norm());
  return Space<D>::from3(motion.velocity).norm() + w * r;
}

template <int D>
void RigidNodes<D>::reset(std::int64_t nodes) {
  if (static_cast<std::int64_t>(weight.size()) != nodes) {
    weight.assign(nodes, 0.0);
    momentum.assign(nodes, Vec::Zero());
    normal.assign(nodes, Vec::Zero());
    touched.clear();
    return;
  }
  for (auto a : touched) {
    weight[a] = 0.0;
    momentum[a].setZero();
    normal[a].setZero();
  }
  touched.clear();
}

template struct RigidBody<2>;
template struct RigidBody<3>;
template struct RigidNodes<2>;
template struct RigidNodes<3>;

}  // namespace talus::mpm
