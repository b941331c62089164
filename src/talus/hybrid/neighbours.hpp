#pragma once
// Neighbour search for the kernel sums: particles binned into square cells
// of the kernel's support (2 l) by a counting sort, so that every neighbour
// of a particle lies in its own cell or one of the eight around it. Rebuilt
// each step (cheap: two passes over the particles).
#include <cstddef>
#include <vector>

namespace talus::hybrid {

class NeighbourGrid {
 public:
  // Bins the points (x[k], y[k]). The cells cover the points' bounding box.
  void build(const std::vector<double>& x, const std::vector<double>& y, double cell);

  // Calls f(j) for every point j in the 3 x 3 cells around (px, py),
  // including a point at (px, py) itself; the caller tests the distance.
  template <class F>
  void for_near(double px, double py, F&& f) const {
    const long ci = cell_of(px, x0_, nx_), cj = cell_of(py, y0_, ny_);
    for (long j = std::max(0L, cj - 1); j <= std::min(ny_ - 1, cj + 1); ++j)
      for (long i = std::max(0L, ci - 1); i <= std::min(nx_ - 1, ci + 1); ++i) {
        const std::size_t c = static_cast<std::size_t>(j * nx_ + i);
        for (std::size_t k = start_[c]; k < start_[c + 1]; ++k) f(order_[k]);
      }
  }

 private:
  long cell_of(double p, double p0, long n) const {
    const long c = static_cast<long>((p - p0) * inv_);
    return c < 0 ? 0 : (c >= n ? n - 1 : c);
  }
  double x0_ = 0.0, y0_ = 0.0, inv_ = 1.0;
  long nx_ = 1, ny_ = 1;
  std::vector<std::size_t> start_;  // per cell, into order_ (one past the end last)
  std::vector<int> order_;          // point indices sorted by cell
};

}  // namespace talus::hybrid
