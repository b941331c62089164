#pragma once
// The Mancarella & Hungr (2010) flume as modelled by Kuen (2011), built from
// the barrier angle beta and the arc radius R (spec: flume.md "Geometry").
// x horizontal downstream, y up, metres.
//
//   W1 chute    from (0, 1.115) down at 29 deg, length L* - R tan((29 + beta)/2)
//   W2 arc      radius R tangent to chute and barrier, 241 to 270 + beta deg
//   W3 barrier  rising at beta from the arc to barrier_length beyond the corner
//   W4 gate     x = 0.5276 from the chute up to y = 1.115
//   W5 lid      y = 1.115 from the gate back to x = 0
// L* (the chute length from its top to the corner, where the chute and barrier
// lines meet) and the barrier length are data of each test, not a rule: no
// fixed pivot, end height or total length reproduces Kuen's Table 2 (checked
// to 5 mm). Only the 33 deg rows share a barrier length (1.118 m beyond the
// corner, to 1 mm, for R = 0.02, 0.10 and 0.26). So:
//   - (beta, R) of a row of Table 2: that row's L* and barrier length;
//   - any other (beta, R): both interpolated linearly in beta between the
//     R = 0.10 rows (7, 13, 22, 33, 61 deg), the end rows outside that range;
//   - either can be given explicitly instead.
#include <optional>
#include <string>

#include "talus/core/space.hpp"
#include "talus/geometry/flume_params.hpp"
#include "talus/geometry/wall_params.hpp"

namespace talus::geometry {

using Vec2 = Eigen::Vector2d;

struct FlumeWalls {
  WallParams chute, arc, barrier, gate, lid;  // named W1..W5
};

struct FlumeGeometry {
  double beta = 0;             // barrier inclination, rad
  double radius = 0;           // arc radius, m
  double l_star = 0;           // chute top to corner, m
  double barrier_length = 0;   // corner to barrier end, along the barrier line, m
  Vec2 corner = Vec2::Zero();  // where the chute and barrier lines meet
  Vec2 chute_start = Vec2::Zero(), chute_end = Vec2::Zero();
  Vec2 arc_centre = Vec2::Zero();
  double arc_angle_start = 0, arc_angle_end = 0;  // rad, counter-clockwise from +x
  Vec2 barrier_start = Vec2::Zero(), barrier_end = Vec2::Zero();
  Vec2 gate_bottom = Vec2::Zero(),
       gate_top = Vec2::Zero();  // gate_bottom lies exactly on the chute
  Vec2 lid_end = Vec2::Zero();   // the lid runs from gate_top to lid_end
  // The release triangle between chute, gate and lid (counter-clockwise).
  Vec2 release[3] = {Vec2::Zero(), Vec2::Zero(), Vec2::Zero()};

  double release_area() const;

  // Path coordinate s: arc length along chute, arc and barrier, zero at the
  // gate foot, negative upstream of it. The pieces end at these values of s:
  double chute_start_s() const;  // negative
  double chute_end_s() const;
  double arc_end_s() const;
  double path_end_s() const;  // top of the barrier
  // Point on the path at s; beyond either end it continues along the straight
  // chute or barrier line.
  Vec2 point_at(double s) const;
  // Unit tangent in the direction of increasing s.
  Vec2 tangent_at(double s) const;
  // s of the path point nearest to x (clamped to the finite path).
  double path_coordinate(const Vec2& x) const;

  // Wall parameters of W1..W5 (2D, no motion: a scenario adds the gate lift).
  FlumeWalls walls(const std::string& material) const;
};

inline constexpr double kFlumeChuteAngleDeg = 29.0;
inline constexpr double kFlumeChuteTopY = 1.1150;  // chute starts at (0, 1.115)
inline constexpr double kFlumeGateX = 0.5276;

// L* and barrier length of Kuen's Table 2 for (beta, R), or the interpolation
// described above when (beta, R) is not a row.
double flume_l_star(double beta_deg, double arc_radius);
double flume_barrier_length(double beta_deg, double arc_radius);

// Throws InputError (keys flume.beta, flume.arc_radius, flume.l_star,
// flume.barrier_length) when the pieces do not fit: beta outside (0, 90) deg,
// R <= 0, an arc that reaches past the gate or the barrier end.
FlumeGeometry make_flume(const FlumeShape& shape);

// Inner unit normal of the bed at path coordinate s (into the flow).
inline Vec2 bed_normal(const FlumeGeometry& g, double s) {
  const Vec2 t = g.tangent_at(s);
  return {-t.y(), t.x()};
}

}  // namespace talus::geometry
