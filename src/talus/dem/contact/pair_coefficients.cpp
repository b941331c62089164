#include "talus/dem/contact/pair_coefficients.hpp"

#include <algorithm>

namespace talus::dem {

double combine(PairRule rule, double a, double b) {
  switch (rule) {
    case PairRule::Max:
      return std::max(a, b);
    case PairRule::Min:
      return std::min(a, b);
    case PairRule::Harmonic:
      return (a + b) > 0.0 ? 2.0 * a * b / (a + b) : 0.0;
    case PairRule::Mean:
      return 0.5 * (a + b);
  }
  return a;
}

PairCoefficients pair_coefficients(const ContactParams& contact, const MaterialParams& a,
                                   const MaterialParams& b) {
  PairCoefficients c;
  c.friction = combine(contact.friction_rule, a.friction, b.friction);
  c.rolling_friction = combine(contact.friction_rule, a.rolling_friction, b.rolling_friction);
  c.restitution = combine(PairRule::Min, a.restitution, b.restitution);
  for (const auto& p : contact.pairs) {
    const bool match = (p.material_a == a.name && p.material_b == b.name) ||
                       (p.material_a == b.name && p.material_b == a.name);
    if (!match) continue;
    if (p.friction) c.friction = *p.friction;
    if (p.rolling_friction) c.rolling_friction = *p.rolling_friction;
    if (p.restitution) c.restitution = *p.restitution;
  }
  return c;
}

double series(double k1, double k2) {
  if (k1 <= 0.0) return k2;
  if (k2 <= 0.0) return k1;
  return 1.0 / (1.0 / k1 + 1.0 / k2);
}

namespace {
double compliance_n(const MaterialParams& m) {
  return m.youngs_modulus > 0.0 ? (1.0 - m.poisson_ratio * m.poisson_ratio) / m.youngs_modulus
                                : 0.0;
}
double compliance_t(const MaterialParams& m) {
  return m.youngs_modulus > 0.0
             ? 2.0 * (2.0 - m.poisson_ratio) * (1.0 + m.poisson_ratio) / m.youngs_modulus
             : 0.0;
}
}  // namespace

double effective_youngs(const MaterialParams& a, const MaterialParams& b) {
  return 1.0 / (compliance_n(a) + compliance_n(b));
}

double effective_shear(const MaterialParams& a, const MaterialParams& b) {
  return 1.0 / (compliance_t(a) + compliance_t(b));
}

}  // namespace talus::dem
