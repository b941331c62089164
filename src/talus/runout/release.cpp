#include "talus/runout/release.hpp"

#include <algorithm>
#include <cmath>

#include "talus/core/error.hpp"

namespace talus::runout {
namespace {

// Sutherland-Hodgman against one half-plane sign * (x - x_cut) >= 0.
std::vector<Vec2> clip(const std::vector<Vec2>& poly, double x_cut, double sign) {
  std::vector<Vec2> out;
  const std::size_t n = poly.size();
  for (std::size_t i = 0; i < n; ++i) {
    const Vec2& a = poly[i];
    const Vec2& b = poly[(i + 1) % n];
    const double da = sign * (a.x() - x_cut), db = sign * (b.x() - x_cut);
    if (da >= 0) out.push_back(a);
    if ((da >= 0) != (db >= 0)) out.push_back(a + (b - a) * (da / (da - db)));
  }
  return out;
}

double area(const std::vector<Vec2>& poly) {
  double a = 0.0;
  for (std::size_t i = 0; i < poly.size(); ++i) {
    const Vec2& p = poly[i];
    const Vec2& q = poly[(i + 1) % poly.size()];
    a += p.x() * q.y() - q.x() * p.y();
  }
  return 0.5 * std::abs(a);
}

}  // namespace

double polygon_area_between(const std::vector<Vec2>& polygon, double x0, double x1) {
  return area(clip(clip(polygon, x0, 1.0), x1, -1.0));
}

DanBlocks blocks_from_polygon(const RunoutPath& path, const std::vector<Vec2>& polygon,
                              std::size_t n) {
  if (n < 2) throw InputError("release: at least 2 boundary blocks are needed");
  if (polygon.size() < 3 || area(polygon) <= 0)
    throw InputError("release: the polygon needs three or more vertices enclosing an area");
  double x_min = polygon[0].x(), x_max = polygon[0].x();
  for (const Vec2& p : polygon) x_min = std::min(x_min, p.x()), x_max = std::max(x_max, p.x());
  const double s0 = path.s_at_x(x_min), s1 = path.s_at_x(x_max);
  DanBlocks b;
  b.s.resize(n);
  for (std::size_t i = 0; i < n; ++i)
    b.s[i] = s0 + (s1 - s0) * static_cast<double>(i) / static_cast<double>(n - 1);
  b.v.assign(n, 0.0);
  b.volume.resize(n - 1);
  for (std::size_t j = 0; j + 1 < n; ++j) {
    const double xa = j == 0 ? x_min : path.point(b.s[j]).x();
    const double xb = j + 2 == n ? x_max : path.point(b.s[j + 1]).x();
    const double width = 0.5 * (path.width(b.s[j]) + path.width(b.s[j + 1]));
    b.volume[j] = width * polygon_area_between(polygon, xa, xb);
  }
  return b;
}

DanBlocks blocks_from_depth(const RunoutPath& path, double s_tail, double s_front, std::size_t n,
                            const std::function<double(double)>& depth,
                            const std::function<double(double)>& velocity) {
  if (n < 2) throw InputError("release: at least 2 boundary blocks are needed");
  if (!(s_front > s_tail)) throw InputError("release: the front must lie downstream of the tail");
  DanBlocks b;
  b.s.resize(n);
  b.v.assign(n, 0.0);
  for (std::size_t i = 0; i < n; ++i) {
    b.s[i] = s_tail + (s_front - s_tail) * static_cast<double>(i) / static_cast<double>(n - 1);
    if (velocity) b.v[i] = velocity(b.s[i]);
  }
  b.volume.resize(n - 1);
  constexpr int kSub = 8;
  for (std::size_t j = 0; j + 1 < n; ++j) {
    const double a = b.s[j], step = (b.s[j + 1] - a) / kSub;
    double sum = 0.0;
    for (int q = 0; q <= kSub; ++q) {
      const double s = a + q * step;
      const double weight = (q == 0 || q == kSub) ? 1.0 : (q % 2 ? 4.0 : 2.0);
      sum += weight * depth(s) * path.width(s);
    }
    b.volume[j] = sum * step / 3.0;
  }
  return b;
}

}  // namespace talus::runout
