#pragma once
// Kuen's rolling resistance (Kuen 2011 §2.3.5.4 and eq. 2.75), reproduced
// faithfully, time-step dependence included (spec/dem.md):
//  - at walls (Preh & Poisel 2007): every step |omega| drops by
//    g c_rr / (r (r_rr - 2/5 r)) dt with r_rr = r - u_rr, c_rr = sqrt(2 r u_rr - u_rr^2),
//    never changing sign. The derivation uses sphere inertia (2/5) and the
//    weight m g instead of the contact normal force, also for disks.
//  - between particles: omega <- mu_Br omega every step for a particle with at
//    least one particle contact. That is a rotational damping whose rate,
//    -ln(mu_Br) / dt, grows as the step shrinks: with half the step Model 3's
//    grains roll half as fast under the same torque, and the flume's results
//    move (docs/validation.md, "Time step"). Given a reference step t_ref
//    (`kuen_reference_step`), the factor per step is mu_Br^(dt / t_ref): the
//    same decay per unit time as mu_Br at t_ref, whatever the step.
#include <cmath>

#include "talus/dem/params.hpp"
#include "talus/dem/particles.hpp"

namespace talus::dem {

// Angular deceleration of Kuen's wall model [rad/s^2] for radius r.
inline double kuen_wall_deceleration(double g, double r, double u_rr) {
  const double r_rr = r - u_rr;
  const double c_rr = std::sqrt(2.0 * r * u_rr - u_rr * u_rr);
  return g * c_rr / (r * (r_rr - 0.4 * r));
}

// Kuen's rules for one step of length dt: the particle factor is computed once
// per step, not once per grain (it may need a pow).
class KuenStep {
 public:
  KuenStep(double g, double u_rr, double dt, double mu) : g_(g), u_rr_(u_rr), dt_(dt), mu_(mu) {}

  // Particle i at the end of a step, after its second half kick.
  template <int D>
  TALUS_HOT void apply(Particles<D>& p, std::size_t i) const {
    if (p.wall_contacts[i] > 0) {
      const double dw = kuen_wall_deceleration(g_, p.r[i], u_rr_) * dt_;
      const double w = Space<D>::rot_norm(p.w[i]);
      p.w[i] = w > dw ? (p.w[i] * ((w - dw) / w)) : Space<D>::rot_zero();
    }
    if (p.contacts[i] > 0) p.w[i] = p.w[i] * mu_;
  }

 private:
  double g_, u_rr_, dt_, mu_;
};

class KuenRolling {
 public:
  KuenRolling() = default;
  KuenRolling(const ContactParams& c, double g)
      : enabled_(c.rolling == RollingModel::Kuen),
        g_(g),
        u_rr_(c.kuen_wall_depth),
        mu_br_(c.kuen_particle_factor),
        reference_step_(c.kuen_reference_step) {}

  bool enabled() const { return enabled_; }

  // The rules for a step of length dt; the factor on omega at a particle
  // contact is mu_Br, or mu_Br^(dt / t_ref) given a reference step.
  KuenStep at(double dt) const {
    const double mu = reference_step_ > 0.0 ? std::pow(mu_br_, dt / reference_step_) : mu_br_;
    return KuenStep(g_, u_rr_, dt, mu);
  }

 private:
  bool enabled_ = false;
  double g_ = 9.81, u_rr_ = 0.0, mu_br_ = 1.0, reference_step_ = 0.0;
};

}  // namespace talus::dem
