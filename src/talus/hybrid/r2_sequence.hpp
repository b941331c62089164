#pragma once
// Particle placement within a cell by the R2 low-discrepancy sequence
// (Roberts 2020; van den Bout et al. 2021 eq. 88, spec mpm.md): the n-th point
// is (n a) mod 1 with a = (1/c_p, 1/c_p^2) and c_p the plastic number, the
// real root of x^3 = x + 1. Any number of points fills the unit square
// evenly, so a cell's count can follow its flow depth.
#include <cmath>
#include <utility>

namespace talus::hybrid {

inline constexpr double kPlasticNumber = 1.32471795724474602596;

// The n-th point (n >= 1) in the unit square, offset by 1/2 as Roberts
// recommends so that the first point is not on an edge.
inline std::pair<double, double> r2_point(long n) {
  constexpr double a1 = 1.0 / kPlasticNumber;
  constexpr double a2 = 1.0 / (kPlasticNumber * kPlasticNumber);
  const double x = 0.5 + a1 * static_cast<double>(n);
  const double y = 0.5 + a2 * static_cast<double>(n);
  return {x - std::floor(x), y - std::floor(y)};
}

}  // namespace talus::hybrid
