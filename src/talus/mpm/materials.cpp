#include "talus/mpm/materials.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace talus::mpm {

namespace {

struct Increment {
  Mat3 strain, spin;
};
Increment increment(const Mat3& l, double dt) { return {sym(l) * dt, skew(l) * dt}; }

Mat3 elastic_trial(const MaterialState& s, const Increment& inc, const ElasticConstants& k) {
  const Mat3 rotated = rotate_stress(s.stress, inc.spin);
  return rotated + 2.0 * k.shear * deviator(inc.strain) +
         k.bulk * inc.strain.trace() * Mat3::Identity();
}

double equivalent_plastic_strain(const Mat3& plastic) {
  const Mat3 e = deviator(plastic);
  return std::sqrt(2.0 / 3.0 * (e.array() * e.array()).sum());
}

}  // namespace

void LinearElastic::update(MaterialState& s, const Mat3& l, double dt, double) const {
  s.stress = elastic_trial(s, increment(l, dt), k);
}
double LinearElastic::wave_speed() const { return std::sqrt(k.p_modulus() / density); }

void NeoHookean::update(MaterialState& s, const Mat3& l, double dt, double) const {
  // Cayley (midpoint) update of F: exactly orthogonal for a pure spin, so a
  // rigid rotation leaves J and the invariants of the stress unchanged.
  const Mat3 i = Mat3::Identity();
  s.deformation = (i - 0.5 * dt * l).inverse() * (i + 0.5 * dt * l) * s.deformation;
  const double j = s.deformation.determinant();
  const double mu = k.shear, lambda = k.bulk - 2.0 / 3.0 * k.shear;
  const Mat3 b = s.deformation * s.deformation.transpose();
  s.stress = mu / j * (b - Mat3::Identity()) + lambda * std::log(j) / j * Mat3::Identity();
}
double NeoHookean::wave_speed() const { return std::sqrt(k.p_modulus() / density); }

double DruckerPrager::alpha(double phi) {
  const double t = std::tan(phi);
  return t / std::sqrt(9.0 + 12.0 * t * t);
}
double DruckerPrager::kc(double phi, double cohesion) {
  const double t = std::tan(phi);
  return 3.0 * cohesion / std::sqrt(9.0 + 12.0 * t * t);
}
double DruckerPrager::yield(const Mat3& stress, double cohesion) const {
  return std::sqrt(j2(stress)) + alpha(phi) * stress.trace() - kc(phi, cohesion);
}

Mat3 DruckerPrager::update_returning(MaterialState& s, const Mat3& l, double dt,
                                     double dv_over_v0) const {
  const Increment inc = increment(l, dt);
  const Mat3 trial = elastic_trial(s, inc, k);
  const Mat3 id = Mat3::Identity();
  const double a = alpha(phi), sin_psi = std::sin(psi);
  double p = trial.trace() / 3.0;
  Mat3 dev = deviator(trial);
  const double f_trial = std::sqrt(j2(trial)) + 3.0 * a * p - kc(phi, s.cohesion);
  const double apex = a > 0.0 ? kc(phi, s.cohesion) / (3.0 * a) : tension_cutoff;
  s.yielding = f_trial > 0.0 || p > std::min(apex, tension_cutoff);
  if (!s.yielding) {
    s.stress = trial;
    return Mat3::Zero();
  }
  // Bonds break while the point yields, so the return uses the reduced c.
  lose_cohesion(s, c0, critical_volume_strain, dv_over_v0);
  const double kc_now = kc(phi, s.cohesion);
  const double p_cut = std::min(a > 0.0 ? kc_now / (3.0 * a) : tension_cutoff, tension_cutoff);
  Mat3 plastic = Mat3::Zero();
  // Tension cut-off (Bui et al. 2008, "tension cracking"): the mean stress
  // beyond the cut-off is removed as plastic volumetric strain.
  if (p > p_cut) {
    plastic += (p - p_cut) / (3.0 * k.bulk) * id;
    p = p_cut;
  }
  const double sqrt_j2 = std::sqrt(0.5 * (dev.array() * dev.array()).sum());
  const double f = sqrt_j2 + 3.0 * a * p - kc_now;
  if (f > 0.0) {
    // Along the return sqrt(J2) falls by G dl and I1 by 27 K sin(psi) dl, so
    // the consistency condition is linear in dl: the discrete form of Bui's
    // lambda-dot (same denominator 27 alpha K sin(psi) + G).
    const double dl = f / (k.shear + 27.0 * a * k.bulk * sin_psi);
    if (sqrt_j2 - k.shear * dl > 0.0) {
      plastic += dl * (dev / (2.0 * sqrt_j2) + 3.0 * sin_psi * id);
      dev *= 1.0 - k.shear * dl / sqrt_j2;
      p -= 9.0 * k.bulk * sin_psi * dl;
    } else {
      // Past the apex: the deviator is gone; the mean stress stays on or below it.
      plastic += dev / (2.0 * k.shear);
      dev.setZero();
      if (a > 0.0) p = std::min(p, kc_now / (3.0 * a));
    }
  }
  s.stress = dev + p * id;
  s.plastic_strain += equivalent_plastic_strain(plastic);
  return plastic;
}
double DruckerPrager::wave_speed() const { return std::sqrt(k.p_modulus() / density); }

void NewtonianFluid::update(MaterialState& s, const Mat3& l, double dt, double) const {
  const Mat3 d = sym(l);
  const double mean = s.stress.trace() / 3.0 + bulk * d.trace() * dt;
  s.stress = mean * Mat3::Identity() + 2.0 * viscosity * deviator(d);
}
double NewtonianFluid::wave_speed() const { return std::sqrt(bulk / density); }

double critical_volume_strain(const MaterialParams& p, double cell_size) {
  // The bonds are gone at a volume strain 2 eps_c; in a band of width h that
  // is an opening of 2 eps_c h.
  return p.critical_opening > 0.0 ? p.critical_opening / (2.0 * cell_size)
                                  : p.critical_volume_strain;
}

LinearElastic LinearElastic::make(const MaterialParams& p) {
  return {ElasticConstants::from(p.youngs_modulus, p.poisson_ratio), p.density};
}
NeoHookean NeoHookean::make(const MaterialParams& p) {
  return {ElasticConstants::from(p.youngs_modulus, p.poisson_ratio), p.density};
}
DruckerPrager DruckerPrager::make(const MaterialParams& p) {
  const auto k = ElasticConstants::from(p.youngs_modulus, p.poisson_ratio);
  const double phi = p.friction_angle, psi = p.dilatancy_angle;
  return {k, p.density, phi, psi, p.cohesion, p.tension_cutoff, p.critical_volume_strain};
}
MohrCoulomb MohrCoulomb::make(const MaterialParams& p) {
  const auto k = ElasticConstants::from(p.youngs_modulus, p.poisson_ratio);
  const double phi = p.friction_angle, psi = p.dilatancy_angle;
  return {k, p.density, phi, psi, p.cohesion, p.critical_volume_strain};
}
NewtonianFluid NewtonianFluid::make(const MaterialParams& p) {
  return {p.bulk_modulus, p.viscosity, p.density};
}

KeyProblem check_frictional(const MaterialParams& p) {
  if (p.dilatancy_angle > p.friction_angle)
    return {"dilatancy_angle", "expected an angle in [0, friction_angle] degrees"};
  // 0 means "none" for either key, so a --set can switch one form off.
  if (p.critical_opening > 0.0 && p.critical_volume_strain > 0.0)
    return {"critical_opening",
            "either critical_volume_strain or critical_opening (the crack-band form), not both"};
  if (p.nonlocal_length > 0.0 && !(p.critical_volume_strain > 0.0))
    return {"nonlocal_length",
            "a critical_volume_strain > 0 beside it (the averaged dilation drives that loss; "
            "critical_opening is the other, crack-band, regularisation)"};
  return {};
}
KeyProblem DruckerPrager::check(const MaterialParams& p) {
  if (auto problem = check_frictional(p)) return problem;
  if (p.friction_angle == 0.0 && p.cohesion == 0.0)
    return {"cohesion", "a Drucker-Prager material needs friction_angle > 0 or cohesion > 0"};
  return {};
}

Material make_material(const MaterialParams& p) {
  const std::size_t law = MaterialLaws::index_of(p.model);
  if (law == MaterialLaws::size) throw std::invalid_argument("unknown material model " + p.model);
  return MaterialLaws::visit(law, [&]<class Law>() { return Material(Law::make(p)); });
}

double wave_speed(const Material& m) {
  return std::visit([](const auto& model) { return model.wave_speed(); }, m);
}
double density(const Material& m) {
  return std::visit([](const auto& model) { return model.density; }, m);
}
double initial_cohesion(const MaterialParams& p) {
  const std::size_t law = MaterialLaws::index_of(p.model);
  if (law == MaterialLaws::size) return 0.0;
  const bool has_cohesion = MaterialLaws::visit(law, []<class Law>() {
    for (const auto& key : Law::keys)
      if (key.field == &MaterialParams::cohesion) return true;
    return false;
  });
  return has_cohesion ? p.cohesion : 0.0;
}

}  // namespace talus::mpm
