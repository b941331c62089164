#include "talus/runout/smoothing.hpp"

#include <algorithm>

namespace talus::runout {

void smooth_velocities(const SmoothingParams& p, const std::vector<double>& x,
                       const std::vector<double>& mass, double dt, std::vector<double>& v,
                       std::vector<double>& scratch) {
  const std::size_t n = v.size();
  if (!p.enabled || n < 2) return;
  const double dx_avg = (x.back() - x.front()) / static_cast<double>(n - 1);
  const double rate = dt / p.reference_time_step;
  // Link weights w (one per link), then each block's denominator.
  std::vector<double>& w = scratch;
  w.assign(2 * n, 0.0);
  const double min_gap = 1e-9 * std::max(dx_avg, 1e-12);
  for (std::size_t i = 0; i + 1 < n; ++i) {
    const bool end = i == 0 || i + 2 == n;
    const double c = end ? p.c_end : p.c_inner;
    w[i] = rate * dx_avg * c / std::max(x[i + 1] - x[i], min_gap);
  }
  double* denom = w.data() + n;
  for (std::size_t i = 0; i < n; ++i)
    denom[i] = 1.0 + (i > 0 ? w[i - 1] : 0.0) + (i + 1 < n ? w[i] : 0.0);
  // Jacobi update from the old velocities: the exchange J of link i is
  // computed before either of its blocks changes.
  double carry = 0.0;  // J of the previous link, already computed from old v
  double v_prev_old = v[0];
  for (std::size_t i = 0; i + 1 < n; ++i) {
    const double m_link = std::min(mass[i], mass[i + 1]);
    const double J = m_link * w[i] / std::max(denom[i], denom[i + 1]) * (v[i + 1] - v_prev_old);
    v_prev_old = v[i + 1];
    v[i] += (J - carry) / mass[i];
    carry = J;
  }
  v[n - 1] -= carry / mass[n - 1];
}

}  // namespace talus::runout
