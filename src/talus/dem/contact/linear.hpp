#pragma once
// Linear spring-dashpot of PFC (Kuen 2011 §2.3.4-2.3.5): normal spring k_n xi,
// incremental shear force capped by Coulomb, viscous damping set by the critical
// damping ratio beta so that the restitution does not depend on the stiffness:
// e = exp(-pi beta / sqrt(1 - beta^2)) when the dashpot may pull (the default).
#include <algorithm>
#include <array>
#include <cmath>
#include <string_view>

#include "talus/core/declared_keys.hpp"
#include "talus/dem/contact/kinematics.hpp"
#include "talus/dem/contact/pair_coefficients.hpp"

namespace talus::dem {

struct LinearSpringDashpot {
  static constexpr std::string_view name = "linear";
  // The keys of [[materials]] this law needs (PFC practice and Kuen's set:
  // k_s = k_n unless given).
  static constexpr std::array<DeclaredKey<MaterialParams>, 3> keys{
      required_key("normal_stiffness", &MaterialParams::normal_stiffness, positive()),
      DeclaredKey<MaterialParams>{"shear_stiffness", &MaterialParams::shear_stiffness, false, 0.0,
                                  non_negative(), KeyUnit::Plain, "normal_stiffness"},
      optional_key("damping_ratio", &MaterialParams::damping_ratio, 0.0,
                   between(0.0, 1.0, false, true))};
  static KeyProblem check(const MaterialParams&) { return {}; }
  struct Coeffs {
    double kn = 0, ks = 0, beta = 0, mu = 0;
    bool may_pull = true;
  };

  static Coeffs make(const ContactParams& cp, const MaterialParams& a, const MaterialParams& b,
                     const PairCoefficients& pc) {
    return {series(a.normal_stiffness, b.normal_stiffness),
            series(a.shear_stiffness, b.shear_stiffness),
            std::max(a.damping_ratio, b.damping_ratio), pc.friction, cp.dashpot_may_pull};
  }

  // The history holds the shear force itself (PFC's incremental form).
  template <int D>
  TALUS_HOT static void compute(const Coeffs& c, const ContactKinematics<D>& k,
                                ContactHistory<D>& h, double dt, ContactForce<D>& out) {
    const double cn = 2.0 * c.beta * std::sqrt(k.m_eff * c.kn);
    double fn = c.kn * k.overlap - cn * k.vn;
    if (!c.may_pull) fn = std::max(fn, 0.0);
    out.fn = fn;
    out.kn = c.kn;
    h.shear = rotate_into_plane<D>(h.shear, k.n);
    h.shear -= c.ks * dt * k.vt;
    const double cap = c.mu * std::abs(fn);
    const double s2 = h.shear.squaredNorm();
    if (s2 > cap * cap) {
      h.shear *= cap / std::sqrt(s2);  // sliding: the dashpot is inactive
      out.ft = h.shear;
    } else {
      out.ft = h.shear - 2.0 * c.beta * std::sqrt(k.m_eff * c.ks) * k.vt;
    }
  }

  // PFC's estimate: sqrt(m/k) for the lightest particle and stiffest contact.
  static double critical_time_step(const Coeffs& c, double m_min, double /*r_min*/,
                                   double /*v_ref*/) {
    const double k = std::max(c.kn, c.ks);
    return k > 0.0 ? std::sqrt(m_min / k) : 1e300;
  }
};

}  // namespace talus::dem
