#pragma once
// Wall primitives and their closest points: the inner loop of every
// particle-wall contact, so everything here is inline, branch on an enum and
// allocation free. All primitives are stored in 3D; 2D runs read x and y.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>

#include "talus/core/space.hpp"

namespace talus::geometry {

inline constexpr double kInf = std::numeric_limits<double>::infinity();

enum class PrimitiveKind : uint8_t { Segment, Arc, Plane, Triangle, Cylinder };

// One piece of a wall in world coordinates.
struct Primitive {
  PrimitiveKind kind = PrimitiveKind::Plane;
  // Segment: ends p0, p1. Triangle: vertices p0, p1, p2. Plane: point p0.
  // Arc: centre p0. Cylinder: point on the axis p0.
  Vec3 p0 = Vec3::Zero(), p1 = Vec3::Zero(), p2 = Vec3::Zero();
  // Plane, Triangle: unit normal. Cylinder: unit axis.
  Vec3 n = Vec3::UnitZ();
  double radius = 0;  // Arc, Cylinder
  // Arc: radians counter-clockwise from +x, angle_end > angle_start; a span of
  // 2 pi or more is a full circle.
  double angle_start = 0, angle_end = 0;
  // Cylinder: the surface covers axial coordinates [0, length] from p0; an
  // infinite length means unbounded in both directions.
  double length = kInf;
  // Cylinder: which side the particles are on. The cylinder is one-sided (see
  // closest_point); every other primitive is two-sided.
  bool inside = true;
};

template <int D>
struct Closest {
  typename Space<D>::Vec point;   // nearest point of the primitive
  typename Space<D>::Vec normal;  // unit, from point towards the particle side
  double distance;                // from the query point to `point`
};

// Builds a triangle with its unit normal (right-hand rule, p0 -> p1 -> p2);
// false when the vertices span no area relative to the edge lengths.
inline bool make_triangle(const Vec3& a, const Vec3& b, const Vec3& c, Primitive& p) {
  const Vec3 cross = (b - a).cross(c - a);
  const double size =
      std::max({(b - a).squaredNorm(), (c - a).squaredNorm(), (c - b).squaredNorm()});
  if (!(cross.norm() > 1e-12 * size)) return false;
  p.kind = PrimitiveKind::Triangle;
  p.p0 = a;
  p.p1 = b;
  p.p2 = c;
  p.n = cross.normalized();
  return true;
}

namespace detail {

// Any unit vector perpendicular to the unit vector a (for degenerate normals).
TALUS_HD inline Eigen::Vector2d perpendicular(const Eigen::Vector2d& a) { return {-a.y(), a.x()}; }
TALUS_HD inline Vec3 perpendicular(const Vec3& a) {
  const Vec3 other = std::abs(a.x()) < 0.9 ? Vec3::UnitX() : Vec3::UnitY();
  return a.cross(other).normalized();
}

// Fills out from a nearest point q; when x lies on the primitive the direction
// is undefined and fallback() (a unit vector) is used.
template <int D, class V, class Fallback>
TALUS_HD inline bool finish(const V& x, const V& q, Fallback fallback, double cutoff,
                            Closest<D>& out) {
  const V diff = x - q;
  const double d = diff.norm();
  if (d > cutoff) return false;
  out.point = q;
  out.normal = d > 0 ? V(diff / d) : V(fallback());
  out.distance = d;
  return true;
}

template <int D>
TALUS_HD inline bool closest_segment(const Primitive& p, const typename Space<D>::Vec& x,
                                     double cutoff, Closest<D>& out) {
  using V = typename Space<D>::Vec;
  const V a = Space<D>::from3(p.p0), b = Space<D>::from3(p.p1);
  const V ab = b - a;
  const double len2 = ab.squaredNorm();
  const double t = std::clamp((x - a).dot(ab) / len2, 0.0, 1.0);
  const V q = a + t * ab;
  return finish<D>(
      x, q, [&] { return perpendicular(V(ab / std::sqrt(len2))); }, cutoff, out);
}

// Ends outside the angular range map to the nearer end point: for a point at
// polar angle phi the distance to the circle point at theta grows with
// |theta - phi| (mod 2 pi), so the nearest arc point is an end point.
TALUS_HD inline bool closest_arc(const Primitive& p, const Eigen::Vector2d& x, double cutoff,
                                 Closest<2>& out) {
  using V = Eigen::Vector2d;
  const V c = Space<2>::from3(p.p0);
  const V rel = x - c;
  const double r = rel.norm();
  const double span = p.angle_end - p.angle_start;
  double phi =
      r > 0 ? std::atan2(rel.y(), rel.x()) : p.angle_start + 0.5 * std::min(span, 2 * M_PI);
  // Shift phi into [angle_start, angle_start + 2 pi).
  phi = p.angle_start + std::fmod(std::fmod(phi - p.angle_start, 2 * M_PI) + 2 * M_PI, 2 * M_PI);
  if (phi - p.angle_start >= 2 * M_PI) phi -= 2 * M_PI;  // fmod rounding at the seam
  if (phi <= p.angle_end) {
    const V radial(std::cos(phi), std::sin(phi));
    const double d = std::abs(r - p.radius);
    if (d > cutoff) return false;
    out.point = c + p.radius * radial;
    out.normal = r >= p.radius ? radial : V(-radial);
    out.distance = d;
    return true;
  }
  const V e0 = c + p.radius * V(std::cos(p.angle_start), std::sin(p.angle_start));
  const V e1 = c + p.radius * V(std::cos(p.angle_end), std::sin(p.angle_end));
  const bool first = (x - e0).squaredNorm() <= (x - e1).squaredNorm();
  const V q = first ? e0 : e1;
  return finish<2>(
      x, q, [&] { return V((q - c) / p.radius); }, cutoff, out);
}

template <int D>
TALUS_HD inline bool closest_plane(const Primitive& p, const typename Space<D>::Vec& x,
                                   double cutoff, Closest<D>& out) {
  using V = typename Space<D>::Vec;
  const V n = Space<D>::from3(p.n);
  const double s = (x - Space<D>::from3(p.p0)).dot(n);
  const double d = std::abs(s);
  if (d > cutoff) return false;
  out.point = x - s * n;
  out.normal = s >= 0 ? n : V(-n);
  out.distance = d;
  return true;
}

// Ericson, Real-Time Collision Detection (2005) 5.1.5: Voronoi regions of the
// vertices, then the edges, else the face.
TALUS_HD inline bool closest_triangle(const Primitive& p, const Vec3& x, double cutoff,
                                      Closest<3>& out) {
  const Vec3 &a = p.p0, &b = p.p1, &c = p.p2;
  const double s = (x - a).dot(p.n);
  if (std::abs(s) > cutoff) return false;  // the plane is never farther than the triangle
  const Vec3 side = s >= 0 ? p.n : Vec3(-p.n);
  auto fallback = [&] { return side; };
  const Vec3 ab = b - a, ac = c - a, ap = x - a;
  const double d1 = ab.dot(ap), d2 = ac.dot(ap);
  if (d1 <= 0 && d2 <= 0) return finish<3>(x, a, fallback, cutoff, out);
  const Vec3 bp = x - b;
  const double d3 = ab.dot(bp), d4 = ac.dot(bp);
  if (d3 >= 0 && d4 <= d3) return finish<3>(x, b, fallback, cutoff, out);
  const double vc = d1 * d4 - d3 * d2;
  if (vc <= 0 && d1 >= 0 && d3 <= 0)
    return finish<3>(x, Vec3(a + d1 / (d1 - d3) * ab), fallback, cutoff, out);
  const Vec3 cp = x - c;
  const double d5 = ab.dot(cp), d6 = ac.dot(cp);
  if (d6 >= 0 && d5 <= d6) return finish<3>(x, c, fallback, cutoff, out);
  const double vb = d5 * d2 - d1 * d6;
  if (vb <= 0 && d2 >= 0 && d6 <= 0)
    return finish<3>(x, Vec3(a + d2 / (d2 - d6) * ac), fallback, cutoff, out);
  const double va = d3 * d6 - d5 * d4;
  if (va <= 0 && d4 - d3 >= 0 && d5 - d6 >= 0) {
    const double w = (d4 - d3) / ((d4 - d3) + (d5 - d6));
    return finish<3>(x, Vec3(b + w * (c - b)), fallback, cutoff, out);
  }
  // Face region: exact plane projection, no division by a small distance.
  out.point = x - s * p.n;
  out.normal = side;
  out.distance = std::abs(s);
  return true;
}

// One-sided: `distance` is signed, positive on the particle side (inside or
// outside per p.inside) and negative once a centre has crossed the surface;
// `normal` always points into the particle side. A centre more than cutoff
// beyond the surface has passed through and is not in contact. Past the ends
// of a finite cylinder the nearest point is on the rim circle (open ends).
TALUS_HD inline bool closest_cylinder(const Primitive& p, const Vec3& x, double cutoff,
                                      Closest<3>& out) {
  const Vec3 rel = x - p.p0;
  const double axial = rel.dot(p.n);
  const Vec3 radial_vec = rel - axial * p.n;
  const double r = radial_vec.norm();
  const Vec3 radial = r > 0 ? Vec3(radial_vec / r) : detail::perpendicular(p.n);
  const double clamped = std::isinf(p.length) ? axial : std::clamp(axial, 0.0, p.length);
  const Vec3 q = p.p0 + clamped * p.n + p.radius * radial;
  const Vec3 into_side = p.inside ? Vec3(-radial) : radial;
  if (clamped != axial)
    return finish<3>(
        x, q, [&] { return into_side; }, cutoff, out);
  const double d = p.inside ? p.radius - r : r - p.radius;
  if (d > cutoff || d < -cutoff) return false;
  out.point = q;
  out.normal = into_side;
  out.distance = d;
  return true;
}

}  // namespace detail

// Nearest point of the primitive to x; false when it is farther than cutoff
// (out is then unspecified). 2D: Segment, Arc, Plane (the line through p0 with
// normal n). 3D: Plane, Triangle, Cylinder, Segment. Other combinations: false.
template <int D>
TALUS_HD inline bool closest_point(const Primitive& p, const typename Space<D>::Vec& x,
                                   double cutoff, Closest<D>& out) {
  switch (p.kind) {
    case PrimitiveKind::Segment:
      return detail::closest_segment<D>(p, x, cutoff, out);
    case PrimitiveKind::Plane:
      return detail::closest_plane<D>(p, x, cutoff, out);
    case PrimitiveKind::Arc:
      if constexpr (D == 2) return detail::closest_arc(p, x, cutoff, out);
      return false;
    case PrimitiveKind::Triangle:
      if constexpr (D == 3) return detail::closest_triangle(p, x, cutoff, out);
      return false;
    case PrimitiveKind::Cylinder:
      if constexpr (D == 3) return detail::closest_cylinder(p, x, cutoff, out);
      return false;
  }
  return false;
}

// Axis-aligned bounding box; +-inf along the directions a primitive is unbounded.
inline void bounds(const Primitive& p, Vec3& lo, Vec3& hi) {
  switch (p.kind) {
    case PrimitiveKind::Segment:
      lo = p.p0.cwiseMin(p.p1);
      hi = p.p0.cwiseMax(p.p1);
      return;
    case PrimitiveKind::Triangle:
      lo = p.p0.cwiseMin(p.p1).cwiseMin(p.p2);
      hi = p.p0.cwiseMax(p.p1).cwiseMax(p.p2);
      return;
    case PrimitiveKind::Arc: {
      auto at = [&](double a) { return Vec3(p.p0 + p.radius * Vec3(std::cos(a), std::sin(a), 0)); };
      lo = at(p.angle_start).cwiseMin(at(p.angle_end));
      hi = at(p.angle_start).cwiseMax(at(p.angle_end));
      // Add the axis extremes (multiples of pi/2) that the arc passes.
      for (double k = std::ceil(p.angle_start / M_PI_2); k * M_PI_2 < p.angle_end; ++k) {
        lo = lo.cwiseMin(at(k * M_PI_2));
        hi = hi.cwiseMax(at(k * M_PI_2));
        if (k * M_PI_2 > p.angle_start + 2 * M_PI) break;
      }
      return;
    }
    case PrimitiveKind::Plane:
      // Bounded only along an axis the plane is perpendicular to.
      for (int i = 0; i < 3; ++i) {
        const bool perpendicular = std::abs(p.n[i]) == p.n.norm();
        lo[i] = perpendicular ? p.p0[i] : -kInf;
        hi[i] = perpendicular ? p.p0[i] : kInf;
      }
      return;
    case PrimitiveKind::Cylinder:
      // A circle of radius R with unit axis n reaches R sqrt(1 - n_i^2) along axis i.
      for (int i = 0; i < 3; ++i) {
        const double reach = p.radius * std::sqrt(std::max(0.0, 1 - p.n[i] * p.n[i]));
        if (std::isinf(p.length)) {
          const bool along = p.n[i] != 0;
          lo[i] = along ? -kInf : p.p0[i] - reach;
          hi[i] = along ? kInf : p.p0[i] + reach;
        } else {
          const double end = p.p0[i] + p.length * p.n[i];
          lo[i] = std::min(p.p0[i], end) - reach;
          hi[i] = std::max(p.p0[i], end) + reach;
        }
      }
      return;
  }
}

}  // namespace talus::geometry
