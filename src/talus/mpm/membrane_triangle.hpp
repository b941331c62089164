#pragma once
// One tension-only membrane triangle of the coupled FE membrane in 3D (mpm.md
// "Membranes in MPM": a mesh of 3-node triangles whose nodes move like
// material points, T = J max(eps, 0), J = E t). A constant-strain triangle in
// its own plane:
//  - strain: the principal stretches l1 >= l2 of F = Ds Dm^-1 (Ds the current
//    edges, Dm the rest edges in the rest plane), engineering strains
//    e_i = l_i - 1, so that a uniaxial stretch gives T = J eps exactly as a
//    cable does (Green strain would give J (l^2 - 1) / 2);
//  - stress: linear plane stress with J and Poisson's ratio nu, relaxed by
//    tension field theory (the mixed criterion of Roddeman et al. 1987 /
//    Kang & Im 1997): taut when both principal tensions are >= 0; wrinkled
//    when the smaller would be negative but e1 > 0 (the wrinkles relieve the
//    compression: n1 = J e1, n2 = 0); slack when e1 <= 0 (nothing). With
//    nu = 0 this is simply "negative principal tensions are zero".
//    The relaxed energy w(e1, e2) is continuous with its first derivatives,
//    and the forces are its exact gradient: they conserve energy, momentum
//    and angular momentum, and rotate with the element.
// Tensions are per unit rest width (N/m), like the cables' T.
#include <array>

#include "talus/core/space.hpp"

namespace talus::mpm {

// The rest shape: the inverse of the rest edge matrix Dm (the edges x2 - x1,
// x3 - x1 in an orthonormal frame of the rest plane) and the rest area.
struct TriangleRest {
  Eigen::Matrix2d inverse = Eigen::Matrix2d::Identity();
  double area = 0.0;
};

// The rest shape of the triangle a, b, c scaled by `scale` (1 + slack: its
// edges are that much longer at rest than drawn). Throws InputError for a
// degenerate triangle.
TriangleRest triangle_rest(const Vec3& a, const Vec3& b, const Vec3& c, double scale = 1.0);

struct TriangleTension {
  double e1 = 0.0, e2 = 0.0;      // principal engineering strains, e1 >= e2
  double n1 = 0.0, n2 = 0.0;      // principal tensions after relaxation, N/m
  Vec3 direction = Vec3::Zero();  // current unit direction of n1 (zero if slack)
};

// Principal strains and tensions of the triangle with nodes x.
TriangleTension triangle_tension(const std::array<Vec3, 3>& x, const TriangleRest& rest,
                                 double stiffness, double poisson);

// Its elastic energy, rest area times the relaxed w(e1, e2) (for checks).
double triangle_energy(const std::array<Vec3, 3>& x, const TriangleRest& rest, double stiffness,
                       double poisson);

// The forces of the triangle on its nodes, -dW/dx (they sum to zero); returns
// its tensions.
TriangleTension triangle_forces(const std::array<Vec3, 3>& x, const TriangleRest& rest,
                                double stiffness, double poisson, std::array<Vec3, 3>& f);

}  // namespace talus::mpm
