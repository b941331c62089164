#include "talus/geometry/flume.hpp"

#include <fmt/format.h>

#include <array>
#include <cmath>

#include "talus/core/error.hpp"
#include "talus/geometry/primitive.hpp"

namespace talus::geometry {

namespace {

// Kuen (2011) Table 2 as corrected in flume.md: L* as printed; the barrier
// length is the distance from the corner to the printed W3 end point along the
// barrier line (the end points lie on that line to 0.04 mm).
struct TableRow {
  double beta_deg, radius, l_star, barrier_length;
};
constexpr std::array<TableRow, 8> kTable2 = {{
    {7, 0.10, 1.6875, 0.78221},
    {13, 0.10, 1.7018, 0.72926},
    {22, 0.10, 1.7075, 0.85375},
    {33, 0.02, 1.7194, 1.11744},
    {33, 0.10, 1.7163, 1.11831},
    {33, 0.26, 1.7179, 1.11785},
    {61, 0.02, 1.7569, 0.99904},
    {61, 0.10, 1.7570, 0.75554},
}};

const TableRow* table_row(double beta_deg, double radius) {
  for (const TableRow& row : kTable2) {
    if (std::abs(row.beta_deg - beta_deg) < 1e-9 && std::abs(row.radius - radius) < 1e-12)
      return &row;
  }
  return nullptr;
}

// Piecewise linear in beta over the R = 0.10 rows, constant beyond the ends.
template <class Field>
double interpolate(double beta_deg, Field field) {
  std::array<const TableRow*, 5> rows{};
  std::size_t n = 0;
  for (const TableRow& row : kTable2) {
    if (row.radius == 0.10) rows[n++] = &row;
  }
  if (beta_deg <= rows[0]->beta_deg) return field(*rows[0]);
  for (std::size_t i = 1; i < n; ++i) {
    if (beta_deg <= rows[i]->beta_deg) {
      const double w =
          (beta_deg - rows[i - 1]->beta_deg) / (rows[i]->beta_deg - rows[i - 1]->beta_deg);
      return (1 - w) * field(*rows[i - 1]) + w * field(*rows[i]);
    }
  }
  return field(*rows[n - 1]);
}

Vec2 direction(double angle) { return {std::cos(angle), std::sin(angle)}; }
// Functions, not namespace-scope constants: a FlumeGeometry built during
// another file's static initialisation must not see them still zero.
constexpr double kChute = kFlumeChuteAngleDeg * M_PI / 180.0;
Vec2 chute_dir() { return direction(-kChute); }
double gate_s() { return kFlumeGateX / std::cos(kChute); }  // chute top to gate foot

Primitive segment(const Vec2& a, const Vec2& b) {
  Primitive p;
  p.kind = PrimitiveKind::Segment;
  p.p0 = Space<2>::to3(a);
  p.p1 = Space<2>::to3(b);
  return p;
}

}  // namespace

double flume_l_star(double beta_deg, double arc_radius) {
  if (const TableRow* row = table_row(beta_deg, arc_radius)) return row->l_star;
  return interpolate(beta_deg, [](const TableRow& r) { return r.l_star; });
}

double flume_barrier_length(double beta_deg, double arc_radius) {
  if (const TableRow* row = table_row(beta_deg, arc_radius)) return row->barrier_length;
  return interpolate(beta_deg, [](const TableRow& r) { return r.barrier_length; });
}

FlumeGeometry make_flume(const FlumeShape& shape) {
  // Kuen's table and the messages are in degrees; the geometry keeps shape.beta.
  const double beta_deg = rad2deg(shape.beta);
  const double arc_radius = shape.arc_radius;
  if (!(beta_deg > 0 && beta_deg < 90))
    throw InputError(fmt::format("flume.beta = {} deg: must be between 0 and 90", beta_deg));
  if (!(arc_radius > 0))
    throw InputError(fmt::format("flume.arc_radius = {} m: must be positive", arc_radius));
  FlumeGeometry f;
  f.beta = shape.beta;
  f.radius = arc_radius;
  f.l_star = shape.l_star.value_or(flume_l_star(beta_deg, arc_radius));
  f.barrier_length = shape.barrier_length.value_or(flume_barrier_length(beta_deg, arc_radius));
  // Tangent length: from the corner to where the arc meets each straight line.
  const double tangent = arc_radius * std::tan((kChute + f.beta) / 2);
  if (!(f.l_star - tangent > gate_s()))
    throw InputError(fmt::format(
        "flume.l_star = {} m with flume.arc_radius = {} m: the arc would start above the gate "
        "(chute must be longer than {:.4f} m)",
        f.l_star, arc_radius, gate_s() + tangent));
  if (!(f.barrier_length > tangent))
    throw InputError(
        fmt::format("flume.barrier_length = {} m: shorter than the arc's tangent length {:.4f} m",
                    f.barrier_length, tangent));

  const Vec2 barrier_dir = direction(f.beta);
  f.chute_start = Vec2(0, kFlumeChuteTopY);
  f.corner = f.chute_start + f.l_star * chute_dir();
  f.chute_end = f.corner - tangent * chute_dir();
  f.arc_centre = f.chute_end + arc_radius * Vec2(std::sin(kChute), std::cos(kChute));
  f.arc_angle_start = deg2rad(270.0) - kChute;
  f.arc_angle_end = deg2rad(270.0) + f.beta;
  f.barrier_start = f.corner + tangent * barrier_dir;
  f.barrier_end = f.corner + f.barrier_length * barrier_dir;
  f.gate_bottom = f.chute_start + gate_s() * chute_dir();
  f.gate_top = Vec2(kFlumeGateX, kFlumeChuteTopY);
  f.lid_end = f.chute_start;
  f.release[0] = f.chute_start;
  f.release[1] = f.gate_bottom;
  f.release[2] = f.gate_top;
  return f;
}

double FlumeGeometry::release_area() const {
  const Vec2 a = release[1] - release[0], b = release[2] - release[0];
  return 0.5 * std::abs(a.x() * b.y() - a.y() * b.x());
}

double FlumeGeometry::chute_start_s() const { return -gate_s(); }
double FlumeGeometry::chute_end_s() const { return (chute_end - chute_start).norm() - gate_s(); }
double FlumeGeometry::arc_end_s() const {
  return chute_end_s() + radius * (arc_angle_end - arc_angle_start);
}
double FlumeGeometry::path_end_s() const {
  return arc_end_s() + (barrier_end - barrier_start).norm();
}

Vec2 FlumeGeometry::point_at(double s) const {
  if (s <= chute_end_s()) return gate_bottom + s * chute_dir();
  if (s >= arc_end_s()) return barrier_start + (s - arc_end_s()) * direction(beta);
  return arc_centre + radius * direction(arc_angle_start + (s - chute_end_s()) / radius);
}

Vec2 FlumeGeometry::tangent_at(double s) const {
  if (s <= chute_end_s()) return chute_dir();
  if (s >= arc_end_s()) return direction(beta);
  // Counter-clockwise along the arc: the radial direction turned by +90 deg.
  const Vec2 radial = direction(arc_angle_start + (s - chute_end_s()) / radius);
  return {-radial.y(), radial.x()};
}

double FlumeGeometry::path_coordinate(const Vec2& x) const {
  Primitive arc;
  arc.kind = PrimitiveKind::Arc;
  arc.p0 = Space<2>::to3(arc_centre);
  arc.radius = radius;
  arc.angle_start = arc_angle_start;
  arc.angle_end = arc_angle_end;
  const Closest<2> none{Vec2::Zero(), Vec2::Zero(), kInf};
  Closest<2> chute_hit = none, arc_hit = none, barrier_hit = none;
  closest_point<2>(segment(chute_start, chute_end), x, kInf, chute_hit);
  closest_point<2>(arc, x, kInf, arc_hit);
  closest_point<2>(segment(barrier_start, barrier_end), x, kInf, barrier_hit);
  if (chute_hit.distance <= arc_hit.distance && chute_hit.distance <= barrier_hit.distance)
    return (chute_hit.point - chute_start).dot(chute_dir()) - gate_s();
  if (barrier_hit.distance < arc_hit.distance)
    return arc_end_s() + (barrier_hit.point - barrier_start).norm();
  const Vec2 rel = arc_hit.point - arc_centre;
  double angle = std::atan2(rel.y(), rel.x());
  while (angle < arc_angle_start - 1e-12) angle += 2 * M_PI;
  return chute_end_s() +
         radius * std::min(angle - arc_angle_start, arc_angle_end - arc_angle_start);
}

FlumeWalls FlumeGeometry::walls(const std::string& material) const {
  auto segment_wall = [&](const char* name, const Vec2& a, const Vec2& b) {
    WallParams w;
    w.name = name;
    w.kind = WallKind::Segment;
    w.material = material;
    w.a = Space<2>::to3(a);
    w.b = Space<2>::to3(b);
    return w;
  };
  FlumeWalls walls;
  walls.chute = segment_wall("chute", chute_start, chute_end);
  walls.arc.name = "arc";
  walls.arc.kind = WallKind::Arc;
  walls.arc.material = material;
  walls.arc.center = Space<2>::to3(arc_centre);
  walls.arc.radius = radius;
  walls.arc.angle_start = arc_angle_start;
  walls.arc.angle_end = arc_angle_end;
  walls.barrier = segment_wall("barrier", barrier_start, barrier_end);
  walls.gate = segment_wall("gate", gate_bottom, gate_top);
  walls.lid = segment_wall("lid", gate_top, lid_end);
  return walls;
}

}  // namespace talus::geometry
