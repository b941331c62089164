#pragma once
// The Mancarella & Hungr flume (geometry/flume.hpp) for the MPM (2D): the bed
// (chute, arc, barrier) as a rigid body of boundary particles in a band below
// the bed line, with Bardenhagen friction contact at the basal friction angle,
// and the release triangle behind the gate filled with material points. The
// gate is gone at t = 0 (Kuen's variant I) and the lid carries no load, so
// neither is modelled. Why boundary particles rather than a friction
// condition on a polyline: the rigid-body contact (rigid.hpp) is the one the
// tilting-plate check already verifies, its nodal normals are the bed normals
// the particles carry (exact on the arc too), and a moving bed would cost
// nothing more (docs/design.md "MPM flume walls").
#include <functional>
#include <vector>

#include "talus/geometry/flume.hpp"
#include "talus/mpm/rigid.hpp"

namespace talus::mpm {

using Vec2 = Eigen::Vector2d;

// A wall along a path x(s), s in [s0, s1], whose material side is the left of
// the direction of increasing s (the side its unit normal n(s) points to):
// boundary particles on a lattice of spacing `spacing` along s and `layers`
// rows below the bed at depths (k + 1/2) spacing, weight spacing^2 times the
// local stretch of the row on a curve (1 - depth * curvature), each with the
// bed normal n(s) of its column. Friction contact with Coulomb coefficient mu.
RigidBody<2> path_wall(const std::function<Vec2(double)>& point,
                       const std::function<Vec2(double)>& normal, double s0, double s1,
                       double spacing, int layers, double mu);

// The bed of the flume (chute start to barrier end) as path_wall.
RigidBody<2> flume_bed(const geometry::FlumeGeometry& g, double spacing, int layers, double mu);

// Centres of the lattice cells of spacing dx (origin at `lattice_origin`)
// that lie inside the triangle a, b, c (either orientation).
std::vector<Vec2> fill_triangle(const Vec2& a, const Vec2& b, const Vec2& c, double dx,
                                const Vec2& lattice_origin);

}  // namespace talus::mpm
