#pragma once
// Velocity smoothing of the DAN boundary blocks (Mancarella & Hungr 2010;
// Kuen 2011 §2.2.6, eqs. 2.40-2.41), made to conserve momentum exactly.
//
// DAN's formula v_i' = (w_l v_{i-1} + v_i + w_r v_{i+1}) / (w_l + 1 + w_r) with
// w = dx_avg c_s / (x_k - x_i) is read as an exchange across each link
// (i, i+1): momentum J = m_link w_link / D_link (v_{i+1} - v_i) goes from the
// faster block to the slower, with m_link = min(m_i, m_{i+1}) and D_link the
// larger of the two blocks' denominators 1 + w_l + w_r. For equal masses and
// equal denominators this is DAN's formula; in general each block's new
// velocity stays a convex combination of its and its neighbours' old ones (no
// new extremes), and the momentum sum is unchanged up to round-off because
// every J leaves one block and enters the other.
#include <vector>

namespace talus::runout {

struct SmoothingParams {
  bool enabled = true;
  double c_end = 0.004;   // links touching the front or tail block
  double c_inner = 0.02;  // all other links
  // DAN applies the formula once per step, so its strength depends on the
  // step. Here the weights are scaled by dt / reference_time_step, which makes
  // the smoothing a rate and lets results converge as dt is refined.
  double reference_time_step = 1e-3;  // s
};

// x: horizontal coordinate of each boundary block (increasing), mass: its mass
// (> 0), v: its velocity, smoothed in place. dt: the time step. Uses scratch
// as working space (resized as needed).
void smooth_velocities(const SmoothingParams& p, const std::vector<double>& x,
                       const std::vector<double>& mass, double dt, std::vector<double>& v,
                       std::vector<double>& scratch);

}  // namespace talus::runout
