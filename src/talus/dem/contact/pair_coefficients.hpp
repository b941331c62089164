#pragma once
// Coefficients of a pair of materials: the mixing rule of the scenario, unless
// the pair is given explicitly. Walls have materials too, so the same rules
// apply to particle-wall contacts (PFC used the larger friction: rule "max").
#include <string>
#include <vector>

#include "talus/dem/params.hpp"

namespace talus::dem {

struct PairCoefficients {
  double friction = 0.0;
  double rolling_friction = 0.0;
  double restitution = 1.0;
};

double combine(PairRule rule, double a, double b);

PairCoefficients pair_coefficients(const ContactParams& contact, const MaterialParams& a,
                                   const MaterialParams& b);

// Series springs: k = (1/k1 + 1/k2)^-1 (PFC linear contacts). A zero stiffness
// means a rigid body (a wall without its own stiffness).
double series(double k1, double k2);

// E* = 1/((1-nu1^2)/E1 + (1-nu2^2)/E2), G* = 1/(2(2-nu1)(1+nu1)/E1 + ...). A zero
// modulus means rigid.
double effective_youngs(const MaterialParams& a, const MaterialParams& b);
double effective_shear(const MaterialParams& a, const MaterialParams& b);

}  // namespace talus::dem
