#pragma once
// The slope limiter of the grid solvers' MUSCL reconstruction.
#include <algorithm>
#include <cmath>

namespace talus::runout {

// Van Leer's monotonised-central slope from the differences to the left and
// right neighbour: the central difference, capped at twice either one-sided
// difference, zero at an extremum. Face values stay between the neighbours'
// values (so depths are never negative). Where the profile curves it is
// steeper than minmod's (the smaller one-sided difference), up to twice: the
// thin tip of a flow front, h ~ distance^2, curves, and minmod's flatter
// slopes held the front back (docs/validation/runout.md, "The front at three
// resolutions").
inline double limited_slope(double left, double right) {
  const double cap = 2.0 * std::min(std::abs(left), std::abs(right));
  const double magnitude = std::min(0.5 * std::abs(left + right), cap);
  return left * right > 0.0 ? std::copysign(magnitude, left) : 0.0;  // branch-free
}

}  // namespace talus::runout
