#include "talus/runout/path.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "talus/core/error.hpp"

namespace talus::runout {

RunoutPath::RunoutPath(double s_begin, double spacing, std::vector<Vec2> points,
                       std::vector<double> angle, std::vector<double> width)
    : s0_(s_begin),
      ds_(spacing),
      points_(std::move(points)),
      angle_(std::move(angle)),
      width_(std::move(width)) {
  const std::size_t n = points_.size();
  if (n < 3 || angle_.size() != n || width_.size() != n || !(ds_ > 0))
    throw InputError("runout path: at least three samples with a positive spacing are needed");
  curvature_.assign(n, 0.0);
  for (std::size_t k = 1; k + 1 < n; ++k)
    curvature_[k] = (angle_[k + 1] - angle_[k - 1]) / (2 * ds_);
  curvature_[0] = (angle_[1] - angle_[0]) / ds_;
  curvature_[n - 1] = (angle_[n - 1] - angle_[n - 2]) / ds_;
}

RunoutPath::Lookup RunoutPath::locate(double s) const {
  const double u = (s - s0_) / ds_;
  const std::size_t last = points_.size() - 1;
  if (u <= 0) return {0, 0.0, u * ds_};
  if (u >= static_cast<double>(last)) return {last - 1, 1.0, (u - static_cast<double>(last)) * ds_};
  const auto k = std::min(static_cast<std::size_t>(u), last - 1);
  return {k, u - static_cast<double>(k), 0.0};
}

Vec2 RunoutPath::point(double s) const {
  const Lookup l = locate(s);
  const Vec2 p = (1 - l.w) * points_[l.k] + l.w * points_[l.k + 1];
  if (l.beyond == 0.0) return p;
  const double a = l.beyond < 0 ? angle_.front() : angle_.back();
  return p + l.beyond * Vec2(std::cos(a), std::sin(a));
}

double RunoutPath::angle(double s) const {
  const Lookup l = locate(s);
  return (1 - l.w) * angle_[l.k] + l.w * angle_[l.k + 1];
}

double RunoutPath::curvature(double s) const {
  const Lookup l = locate(s);
  if (l.beyond != 0.0) return 0.0;
  return (1 - l.w) * curvature_[l.k] + l.w * curvature_[l.k + 1];
}

double RunoutPath::width(double s) const {
  const Lookup l = locate(s);
  return (1 - l.w) * width_[l.k] + l.w * width_[l.k + 1];
}

double RunoutPath::s_at_x(double x) const {
  if (x <= points_.front().x()) {
    const double c = std::cos(angle_.front());
    return s0_ + (c > 0 ? (x - points_.front().x()) / c : 0.0);
  }
  if (x >= points_.back().x()) {
    const double c = std::cos(angle_.back());
    return s_end() + (c > 0 ? (x - points_.back().x()) / c : 0.0);
  }
  const auto it = std::upper_bound(points_.begin(), points_.end(), x,
                                   [](double v, const Vec2& p) { return v < p.x(); });
  const auto k = static_cast<std::size_t>(it - points_.begin()) - 1;
  const double dx = points_[k + 1].x() - points_[k].x();
  const double w = dx > 0 ? (x - points_[k].x()) / dx : 0.0;
  return s0_ + (static_cast<double>(k) + w) * ds_;
}

RunoutPath path_from_flume(const geometry::FlumeGeometry& flume, double width, double spacing) {
  const double s0 = flume.chute_start_s(), s1 = flume.path_end_s();
  const auto n = static_cast<std::size_t>(std::ceil((s1 - s0) / spacing));
  const double ds = (s1 - s0) / static_cast<double>(n);
  std::vector<Vec2> points(n + 1);
  std::vector<double> angle(n + 1), widths(n + 1, width);
  for (std::size_t k = 0; k <= n; ++k) {
    const double s = s0 + static_cast<double>(k) * ds;
    points[k] = flume.point_at(s);
    const Vec2 t = flume.tangent_at(s);
    angle[k] = std::atan2(t.y(), t.x());
  }
  return RunoutPath(s0, ds, std::move(points), std::move(angle), std::move(widths));
}

RunoutPath path_from_profile(const std::vector<Vec2>& points, const std::vector<double>& widths,
                             double smoothing_length, double spacing) {
  if (points.size() < 2) throw InputError("profile: at least two points are needed");
  if (widths.size() != points.size()) throw InputError("profile: one width per point is needed");
  std::vector<double> cumulative(points.size(), 0.0);
  for (std::size_t i = 1; i < points.size(); ++i) {
    if (!(points[i].x() > points[i - 1].x()))
      throw InputError(
          fmt::format("profile: point {} has x = {} not greater than the point "
                      "before it (x must increase along the path)",
                      i, points[i].x()));
    cumulative[i] = cumulative[i - 1] + (points[i] - points[i - 1]).norm();
  }
  for (std::size_t i = 0; i < widths.size(); ++i)
    if (!(widths[i] > 0))
      throw InputError(fmt::format("profile: point {} has width {}; expected > 0", i, widths[i]));
  const double length = cumulative.back();
  const auto n = std::max<std::size_t>(2, static_cast<std::size_t>(std::ceil(length / spacing)));
  const double ds = length / static_cast<double>(n);
  std::vector<double> raw(n + 1), width(n + 1);
  std::size_t seg = 0;
  for (std::size_t k = 0; k <= n; ++k) {
    const double s = static_cast<double>(k) * ds;
    while (seg + 2 < points.size() && s > cumulative[seg + 1]) ++seg;
    const Vec2 d = points[seg + 1] - points[seg];
    raw[k] = std::atan2(d.y(), d.x());
    const double w =
        std::clamp((s - cumulative[seg]) / (cumulative[seg + 1] - cumulative[seg]), 0.0, 1.0);
    width[k] = (1 - w) * widths[seg] + w * widths[seg + 1];
  }
  // Moving average of the angle over the window, shrunk at the ends so that
  // the end tangents stay those of the first and last segments.
  const auto half = static_cast<std::size_t>(std::round(0.5 * smoothing_length / ds));
  std::vector<double> angle(n + 1);
  for (std::size_t k = 0; k <= n; ++k) {
    const std::size_t h = std::min({half, k, n - k});
    double sum = 0;
    for (std::size_t j = k - h; j <= k + h; ++j) sum += raw[j];
    angle[k] = sum / static_cast<double>(2 * h + 1);
  }
  std::vector<Vec2> curve(n + 1);
  curve[0] = points.front();
  for (std::size_t k = 1; k <= n; ++k) {
    const double a = 0.5 * (angle[k] + angle[k - 1]);
    curve[k] = curve[k - 1] + ds * Vec2(std::cos(a), std::sin(a));
  }
  return RunoutPath(0.0, ds, std::move(curve), std::move(angle), std::move(width));
}

}  // namespace talus::runout
