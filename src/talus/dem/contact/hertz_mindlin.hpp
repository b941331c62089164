#pragma once
// Hertz normal force with restitution-based damping and a Mindlin tangential
// spring with history and Coulomb cap, exactly as LIGGGHTS
// `pair_style gran model hertz tangential history` (the peer benchmark's
// reference definition, ../shared/peers/README.md §1).
#include <algorithm>
#include <array>
#include <cmath>
#include <string_view>

#include "talus/core/declared_keys.hpp"
#include "talus/dem/contact/kinematics.hpp"
#include "talus/dem/contact/pair_coefficients.hpp"

namespace talus::dem {

// Effective constants shared by the Hertz-type laws.
struct HertzConstants {
  double e_star = 0, g_star = 0, mu = 0;
};

// Hertz contact: maximum overlap of an impact at relative normal speed v.
inline double hertz_max_overlap(double e_star, double r_eff, double m_eff, double v) {
  return std::pow(15.0 * m_eff * v * v / (16.0 * e_star * std::sqrt(r_eff)), 0.4);
}

// Analogue of PFC's sqrt(m/k) with the tangent Hertz stiffness 2 E* sqrt(R d)
// at the largest overlap expected for impacts at v_ref.
inline double hertz_critical_time_step(double e_star, double r_eff, double m_eff, double v_ref) {
  const double d = hertz_max_overlap(e_star, r_eff, m_eff, v_ref);
  const double k = 2.0 * e_star * std::sqrt(r_eff * d);
  return std::sqrt(m_eff / k);
}

// The keys of [[materials]] both Hertz laws need.
inline constexpr std::array<DeclaredKey<MaterialParams>, 2> kHertzKeys{
    required_key("youngs_modulus", &MaterialParams::youngs_modulus, positive()),
    optional_key("poisson_ratio", &MaterialParams::poisson_ratio, 0.3,
                 between(-1.0, 0.5, true, true))};

struct HertzMindlin {
  static constexpr std::string_view name = "hertz_mindlin";
  static constexpr auto keys = join(
      kHertzKeys, std::array<DeclaredKey<MaterialParams>, 1>{required_key(
                      "restitution", &MaterialParams::restitution, between(0, 1, true, false))});
  static KeyProblem check(const MaterialParams&) { return {}; }
  struct Coeffs {
    HertzConstants h;
    double beta = 0;  // ln e / sqrt(ln^2 e + pi^2), negative
    // Precomputed so a contact needs one square root for both dampers:
    // gamma_n = damp_n sqrt(m* sqrt(R* d)), gamma_t = gamma_n sqrt(S_t / S_n).
    double damp_n = 0, tangential_ratio = 0;
  };

  static Coeffs make(const ContactParams&, const MaterialParams& a, const MaterialParams& b,
                     const PairCoefficients& pc) {
    const double ln_e = std::log(pc.restitution);
    Coeffs c;
    c.h = {effective_youngs(a, b), effective_shear(a, b), pc.friction};
    c.beta = ln_e / std::sqrt(ln_e * ln_e + M_PI * M_PI);
    constexpr double two_sqrt_5_6 = 1.8257418583505538;  // 2 sqrt(5/6)
    c.damp_n = -two_sqrt_5_6 * c.beta * std::sqrt(2.0 * c.h.e_star);
    c.tangential_ratio = std::sqrt(8.0 * c.h.g_star / (2.0 * c.h.e_star));
    return c;
  }

  // The history holds the shear displacement xi.
  template <int D>
  TALUS_HOT static void compute(const Coeffs& c, const ContactKinematics<D>& k,
                                ContactHistory<D>& h, double dt, ContactForce<D>& out) {
    const double sqrt_rd = std::sqrt(k.r_eff * k.overlap);
    const double sn = 2.0 * c.h.e_star * sqrt_rd;
    const double st = 8.0 * c.h.g_star * sqrt_rd;
    const double kn = (4.0 / 3.0) * c.h.e_star * sqrt_rd;
    const double gn = c.damp_n * std::sqrt(k.m_eff * sqrt_rd);
    const double gt = gn * c.tangential_ratio;
    const double fn = kn * k.overlap - gn * k.vn;  // may turn slightly negative (as LIGGGHTS)
    out.fn = fn;
    out.kn = sn;
    h.shear += k.vt * dt;
    h.shear -= h.shear.dot(k.n) * k.n;
    const double cap = c.h.mu * std::abs(fn);
    const double spring2 = st * st * h.shear.squaredNorm();
    if (spring2 > cap * cap) {
      h.shear *= cap / std::sqrt(spring2);
      out.ft = -st * h.shear;  // sliding: no tangential damping
    } else {
      out.ft = -st * h.shear - gt * k.vt;
    }
  }

  static double critical_time_step(const Coeffs& c, double m_eff, double r_eff, double v_ref) {
    return hertz_critical_time_step(c.h.e_star, r_eff, m_eff, v_ref);
  }
};

// Viscoelastic Hertz (Brilliantov et al. 1996), Götz 2024 §2, with the sign of
// the damping term corrected (spec/dem.md): it opposes approach and the force is
// never attractive. Written with E* so that two equal spheres give the source's
// prefactor 2E sqrt(R)/(3(1-nu^2)) = (4/3) E* sqrt(R); k_t = (32/3) G* sqrt(R xi)
// likewise equals the source's 8E/(3(1+nu)(2-nu)) sqrt(R xi) for equal spheres.
struct ViscoelasticHertz {
  static constexpr std::string_view name = "viscoelastic_hertz";
  static constexpr auto keys =
      join(kHertzKeys, std::array<DeclaredKey<MaterialParams>, 1>{optional_key(
                           "dissipation", &MaterialParams::dissipation, 0.0, non_negative())});
  static KeyProblem check(const MaterialParams&) { return {}; }
  struct Coeffs {
    HertzConstants h;
    double dissipation = 0;  // A [s]
    double gamma_t = 0;      // tangential damping factor
  };

  static Coeffs make(const ContactParams& cp, const MaterialParams& a, const MaterialParams& b,
                     const PairCoefficients& pc) {
    return {{effective_youngs(a, b), effective_shear(a, b), pc.friction},
            std::max(a.dissipation, b.dissipation),
            cp.tangential_damping};
  }

  // The history holds the tangential spring xi_t.
  template <int D>
  TALUS_HOT static void compute(const Coeffs& c, const ContactKinematics<D>& k,
                                ContactHistory<D>& h, double dt, ContactForce<D>& out) {
    const double sqrt_d = std::sqrt(k.overlap);
    const double rho = (4.0 / 3.0) * c.h.e_star * std::sqrt(k.r_eff);
    const double overlap_rate = -k.vn;
    const double fn =
        std::max(0.0, rho * (k.overlap * sqrt_d + 1.5 * c.dissipation * sqrt_d * overlap_rate));
    out.fn = fn;
    out.kn = 1.5 * rho * sqrt_d;
    const double kt = (32.0 / 3.0) * c.h.g_star * std::sqrt(k.r_eff * k.overlap);
    h.shear = rotate_into_plane<D>(h.shear, k.n);
    h.shear += k.vt * dt;
    const double damp = c.gamma_t * std::sqrt(k.m_eff * kt);
    typename Space<D>::Vec ft = -(2.0 / 3.0) * kt * h.shear - damp * k.vt;
    const double cap = c.h.mu * fn;
    const double f2 = ft.squaredNorm();
    if (f2 > cap * cap) {
      ft *= cap / std::sqrt(f2);
      // Shorten the spring so that it alone would give the capped force.
      h.shear = -(ft + damp * k.vt) / ((2.0 / 3.0) * kt);
    }
    out.ft = ft;
  }

  static double critical_time_step(const Coeffs& c, double m_eff, double r_eff, double v_ref) {
    return hertz_critical_time_step(c.h.e_star, r_eff, m_eff, v_ref);
  }
};

}  // namespace talus::dem
