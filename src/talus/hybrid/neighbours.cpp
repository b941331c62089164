#include "talus/hybrid/neighbours.hpp"

#include <algorithm>
#include <cmath>

#include "talus/core/error.hpp"

namespace talus::hybrid {

void NeighbourGrid::build(const std::vector<double>& x, const std::vector<double>& y, double cell) {
  const std::size_t n = x.size();
  inv_ = 1.0 / cell;
  if (n == 0) {
    nx_ = ny_ = 1;
    start_.assign(2, 0);
    order_.clear();
    return;
  }
  const auto [xmin, xmax] = std::minmax_element(x.begin(), x.end());
  const auto [ymin, ymax] = std::minmax_element(y.begin(), y.end());
  if (!std::isfinite(*xmin) || !std::isfinite(*xmax) || !std::isfinite(*ymin) ||
      !std::isfinite(*ymax))
    throw RunError("hybrid: a particle position is not finite");
  x0_ = *xmin;
  y0_ = *ymin;
  nx_ = static_cast<long>((*xmax - x0_) * inv_) + 1;
  ny_ = static_cast<long>((*ymax - y0_) * inv_) + 1;
  const std::size_t cells = static_cast<std::size_t>(nx_ * ny_);
  start_.assign(cells + 1, 0);
  std::vector<std::size_t> cell_of_point(n);
  for (std::size_t k = 0; k < n; ++k) {
    const std::size_t c =
        static_cast<std::size_t>(cell_of(y[k], y0_, ny_) * nx_ + cell_of(x[k], x0_, nx_));
    cell_of_point[k] = c;
    ++start_[c + 1];
  }
  for (std::size_t c = 0; c < cells; ++c) start_[c + 1] += start_[c];
  order_.resize(n);
  std::vector<std::size_t> next(start_.begin(), start_.end() - 1);
  for (std::size_t k = 0; k < n; ++k) order_[next[cell_of_point[k]]++] = static_cast<int>(k);
}

}  // namespace talus::hybrid
