#include "talus/analysis/flume_measure.hpp"

#include <algorithm>
#include <cmath>

namespace talus::analysis {

double bed_low_point(const geometry::FlumeGeometry& g) {
  // The arc turns from falling (chute) to rising (barrier) through the
  // horizontal, so its lowest point is straight below the centre.
  return g.arc_centre.y() - g.radius;
}

FrontSample measure_front(const geometry::FlumeGeometry& g, const Grains& grains, double quantile) {
  FrontSample out;
  if (grains.x.empty()) return out;
  std::vector<double> s(grains.x.size());
  const double chute_end = g.chute_end_s();
  for (std::size_t i = 0; i < s.size(); ++i) {
    s[i] = g.path_coordinate(grains.x[i]);
    if (s[i] < chute_end) ++out.on_chute;
  }
  // The k-th smallest, k = round(quantile * (n - 1)): quantile 1 is the farthest grain.
  const auto k =
      static_cast<std::size_t>(std::lround(quantile * static_cast<double>(s.size() - 1)));
  std::nth_element(s.begin(), s.begin() + static_cast<std::ptrdiff_t>(k), s.end());
  out.front_s = s[k];
  out.front = g.point_at(out.front_s);
  if (out.front_s > g.arc_end_s()) {
    out.runup_s = out.front_s - g.arc_end_s();
    out.runup_height = out.front.y() - bed_low_point(g);
  }
  return out;
}

std::vector<ProfileBin> deposit_profile(const geometry::FlumeGeometry& g, const Grains& grains,
                                        double bin) {
  const double s0 = g.chute_start_s(), s1 = g.path_end_s();
  const auto n = static_cast<std::size_t>(std::ceil((s1 - s0) / bin));
  std::vector<ProfileBin> profile(n);
  for (std::size_t k = 0; k < n; ++k) {
    profile[k].s_low = s0 + static_cast<double>(k) * bin;
    profile[k].s_high = std::min(s1, profile[k].s_low + bin);
  }
  for (std::size_t i = 0; i < grains.x.size(); ++i) {
    const double s = g.path_coordinate(grains.x[i]);
    const auto k = static_cast<std::size_t>(
        std::clamp(std::floor((s - s0) / bin), 0.0, static_cast<double>(n - 1)));
    const Vec2 n = bed_normal(g, s);
    const double top = (grains.x[i] - g.point_at(s)).dot(n) + grains.r[i];
    ProfileBin& b = profile[k];
    ++b.count;
    if (top > b.thickness) {
      b.thickness = top;
      // The top grain's own top, not bed + thickness * normal at the bin
      // centre: over the arc a deposit thicker than R would put that point
      // past the centre of curvature, where the normals cross.
      b.surface = grains.x[i] + grains.r[i] * n;
    }
  }
  for (ProfileBin& b : profile) {
    if (b.count == 0) b.surface = g.point_at(0.5 * (b.s_low + b.s_high));
  }
  return profile;
}

double deposit_tail(const std::vector<ProfileBin>& profile, double min_thickness) {
  if (profile.empty()) return 0.0;
  std::size_t thickest = 0;
  for (std::size_t k = 1; k < profile.size(); ++k) {
    if (profile[k].thickness > profile[thickest].thickness) thickest = k;
  }
  std::size_t start = thickest;
  while (start > 0 && profile[start - 1].thickness > min_thickness) --start;
  return profile[start].s_low;
}

}  // namespace talus::analysis
