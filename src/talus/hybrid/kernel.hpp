#pragma once
// The smoothing kernel of the hybrid particle method: Monaghan's (2000) 2D
// cubic spline (van den Bout et al. 2021 eq. 74, spec mpm.md), with q = r / l
// for smoothing length l and support 2 l:
//   W = 10 / (7 pi l^2) (1 - 1.5 q^2 + 0.75 q^3)   for 0 <= q < 1,
//       10 / (28 pi l^2) (2 - q)^3                  for 1 <= q < 2, 0 beyond;
// it integrates to 1 over the plane. The gradient (eq. 77) is
// grad_i W_ij = (x_i - x_j) / r dW/dr.
#include <cmath>
#include <numbers>

namespace talus::hybrid {

class CubicSplineKernel {
 public:
  explicit CubicSplineKernel(double smoothing_length)
      : l_(smoothing_length), norm_(10.0 / (7.0 * std::numbers::pi * l_ * l_)) {}

  double smoothing_length() const { return l_; }
  double support() const { return 2.0 * l_; }

  double value(double r) const {
    const double q = r / l_;
    if (q < 1.0) return norm_ * (1.0 - 1.5 * q * q + 0.75 * q * q * q);
    if (q < 2.0) {
      const double t = 2.0 - q;
      return 0.25 * norm_ * t * t * t;
    }
    return 0.0;
  }
  // dW/dr divided by r (finite at r = 0, where the gradient vanishes): the
  // gradient is then (x_i - x_j) times this, without a division by r.
  double derivative_over_r(double r) const {
    const double q = r / l_;
    if (q < 1.0) return norm_ / (l_ * l_) * (-3.0 + 2.25 * q);
    if (q < 2.0) {
      const double t = 2.0 - q;
      return -0.75 * norm_ * t * t / (l_ * r);
    }
    return 0.0;
  }

 private:
  double l_, norm_;
};

}  // namespace talus::hybrid
