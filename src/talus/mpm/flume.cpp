#include "talus/mpm/flume.hpp"

#include <algorithm>
#include <cmath>

namespace talus::mpm {

RigidBody<2> path_wall(const std::function<Vec2(double)>& point,
                       const std::function<Vec2(double)>& normal, double s0, double s1,
                       double spacing, int layers, double mu) {
  RigidBody<2> body;
  const auto columns = std::max(1, static_cast<int>(std::ceil((s1 - s0) / spacing - 1e-9)));
  const double ds = (s1 - s0) / columns;
  for (int c = 0; c < columns; ++c) {
    const double s = s0 + (c + 0.5) * ds;
    const Vec2 x = point(s), n = normal(s);
    // Curvature of the bed at s (positive when it turns towards n, as on the
    // flume's arc): rows below a concave bed are longer than the bed itself.
    const double h = 0.5 * ds;
    const double kappa = (normal(s + h) - normal(s - h)).norm() / (2.0 * h) *
                         ((point(s + h) + point(s - h) - 2.0 * x).dot(n) >= 0.0 ? 1.0 : -1.0);
    for (int k = 0; k < layers; ++k) {
      const double depth = (k + 0.5) * spacing;
      body.x.push_back(x - depth * n);
      body.weight.push_back(ds * spacing * std::max(0.0, 1.0 + depth * kappa));
      body.normal.push_back(n);
    }
  }
  body.contact = RigidContact::Friction;
  body.friction = mu;
  return body;
}

RigidBody<2> flume_bed(const geometry::FlumeGeometry& g, double spacing, int layers, double mu) {
  return path_wall([&g](double s) { return g.point_at(s); },
                   [&g](double s) { return geometry::bed_normal(g, s); }, g.chute_start_s(),
                   g.path_end_s(), spacing, layers, mu);
}

std::vector<Vec2> fill_triangle(const Vec2& a, const Vec2& b, const Vec2& c, double dx,
                                const Vec2& o) {
  const auto cross = [](const Vec2& u, const Vec2& v) { return u.x() * v.y() - u.y() * v.x(); };
  const double orientation = cross(b - a, c - a) >= 0.0 ? 1.0 : -1.0;
  const Vec2 lo = a.cwiseMin(b).cwiseMin(c), hi = a.cwiseMax(b).cwiseMax(c);
  const auto i0 = static_cast<long>(std::floor((lo.x() - o.x()) / dx));
  const auto i1 = static_cast<long>(std::ceil((hi.x() - o.x()) / dx));
  const auto j0 = static_cast<long>(std::floor((lo.y() - o.y()) / dx));
  const auto j1 = static_cast<long>(std::ceil((hi.y() - o.y()) / dx));
  std::vector<Vec2> points;
  for (long j = j0; j <= j1; ++j)
    for (long i = i0; i <= i1; ++i) {
      const Vec2 p = o + dx * Vec2(i + 0.5, j + 0.5);
      if (orientation * cross(b - a, p - a) >= 0.0 && orientation * cross(c - b, p - b) >= 0.0 &&
          orientation * cross(a - c, p - c) >= 0.0)
        points.push_back(p);
    }
  return points;
}

}  // namespace talus::mpm
