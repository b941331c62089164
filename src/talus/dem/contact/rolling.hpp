#pragma once
// Rolling resistance acting per contact. Kuen's model is not here: it changes
// the angular velocity of particles, not contact torques (see dem/kuen_rolling.hpp).
#include <cmath>
#include <vector>

#include "talus/dem/contact/kinematics.hpp"
#include "talus/dem/contact/pair_coefficients.hpp"

namespace talus::dem {

struct NoRolling {
  static constexpr const char* name = "none";
  static constexpr bool needs_inertia = false;
  static constexpr bool has_torque = false;  // never writes the rolling history
  struct Coeffs {};
  static Coeffs make(const ContactParams&, const PairCoefficients&) { return {}; }
  template <int D>
  TALUS_HOT static void compute(const Coeffs&, const ContactKinematics<D>&, ContactHistory<D>&,
                                double, ContactForce<D>&) {}
};

// EPSD / type C (Ai, Chen, Rotter & Ooi 2011): an elastic spring on the relative
// rotation, k_r = 2.25 mu_r^2 R^2 k_n, capped at M_m = mu_r R F_n (rate
// independent), with a viscous damper 2 eta_r sqrt(I_r k_r) while not at the cap.
struct EpsdRolling {
  static constexpr const char* name = "epsd";
  static constexpr bool needs_inertia = true;
  static constexpr bool has_torque = true;
  struct Coeffs {
    double mu_r = 0, stiffness_factor = 2.25, eta = 0.3;
  };
  static Coeffs make(const ContactParams& cp, const PairCoefficients& pc) {
    return {pc.rolling_friction, cp.epsd_stiffness_factor, cp.epsd_damping_ratio};
  }

  template <int D>
  TALUS_HOT static void compute(const Coeffs& c, const ContactKinematics<D>& k,
                                ContactHistory<D>& h, double dt, ContactForce<D>& out) {
    if (c.mu_r <= 0.0) return;
    using Rot = typename Space<D>::Rot;
    Rot w = k.w_rel;
    if constexpr (D == 3) {
      // Twisting about the normal is not rolling.
      w -= w.dot(k.n) * k.n;
      h.roll -= h.roll.dot(k.n) * k.n;
    }
    const double kr = c.stiffness_factor * c.mu_r * c.mu_r * k.r_eff * k.r_eff * out.kn;
    h.roll -= kr * dt * w;
    const double cap = c.mu_r * k.r_eff * std::abs(out.fn);
    const double m = Space<D>::rot_norm(h.roll);
    if (m > cap) {
      h.roll = h.roll * (cap / m);
      out.roll_torque = h.roll;
    } else {
      out.roll_torque = h.roll - 2.0 * c.eta * std::sqrt(k.inertia_eff * kr) * w;
    }
  }
};

// A contact model is a force law plus a rolling part, composed at compile time
// so the hot loop has no virtual call.
template <class Law, class Rolling>
struct ComposedContact {
  static constexpr bool needs_inertia = Rolling::needs_inertia;
  static constexpr bool has_rolling = Rolling::has_torque;
  struct Coeffs {
    typename Law::Coeffs law;
    typename Rolling::Coeffs roll;
  };
  static Coeffs make(const ContactParams& cp, const MaterialParams& a, const MaterialParams& b) {
    const PairCoefficients pc = pair_coefficients(cp, a, b);
    return {Law::make(cp, a, b, pc), Rolling::make(cp, pc)};
  }
  template <int D>
  TALUS_HOT static void compute(const Coeffs& c, const ContactKinematics<D>& k,
                                ContactHistory<D>& h, double dt, ContactForce<D>& out) {
    Law::compute(c.law, k, h, dt, out);
    Rolling::compute(c.roll, k, h, dt, out);
  }
  static double critical_time_step(const Coeffs& c, double m_eff, double r_eff, double v_ref) {
    return Law::critical_time_step(c.law, m_eff, r_eff, v_ref);
  }
};

// A model's coefficients for every pair of materials, row-major by the
// first material's index (the steppers' lookup table).
template <class Model>
std::vector<typename Model::Coeffs> coefficient_table(
    const ContactParams& cp, const std::vector<MaterialParams>& materials) {
  const std::size_t m = materials.size();
  std::vector<typename Model::Coeffs> table(m * m);
  for (std::size_t a = 0; a < m; ++a)
    for (std::size_t b = 0; b < m; ++b)
      table[a * m + b] = Model::make(cp, materials[a], materials[b]);
  return table;
}

}  // namespace talus::dem
