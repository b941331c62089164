#include "talus/runout/dan.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "talus/core/error.hpp"

namespace talus::runout {

DanModel::DanModel(RunoutPath path, DanParams params, DanBlocks blocks)
    : path_(std::move(path)), p_(params), b_(std::move(blocks)) {
  const std::size_t n = b_.s.size();
  if (n < 2) throw InputError("DAN: at least 2 boundary blocks are needed");
  if (b_.v.empty()) b_.v.assign(n, 0.0);
  if (b_.v.size() != n || b_.volume.size() != n - 1)
    throw InputError("DAN: n positions, n velocities and n - 1 volumes are needed");
  if (b_.k.empty()) b_.k.assign(n - 1, initial_earth_pressure(p_.pressure));
  if (b_.k.size() != n - 1) throw InputError("DAN: one earth-pressure coefficient per mass block");
  for (std::size_t j = 0; j + 1 < n; ++j) {
    if (!(b_.s[j + 1] > b_.s[j]))
      throw InputError(
          fmt::format("DAN: boundary block {} is not downstream of block {}", j + 1, j));
    if (!(b_.volume[j] > 0))
      throw InputError(
          fmt::format("DAN: mass block {} has volume {}; expected > 0", j, b_.volume[j]));
  }
  mass_.assign(n, 0.0);
  for (std::size_t j = 0; j + 1 < n; ++j) {
    mass_[j] += 0.5 * p_.density * b_.volume[j];
    mass_[j + 1] += 0.5 * p_.density * b_.volume[j];
  }
  h_.resize(n - 1);
  H_.resize(n);
  energy_min_ = total_energy();
  kinetic_peak_ = kinetic_energy();
  depth_energy_start_ = depth_energy();
}

void DanModel::restore(DanBlocks blocks, EnergyWatch watch) {
  const std::size_t n = size();
  if (blocks.s.size() != n || blocks.v.size() != n || blocks.k.size() != n - 1 ||
      blocks.volume != b_.volume)
    throw InputError("DAN: the checkpoint's blocks are not this scenario's");
  b_ = std::move(blocks);
  energy_min_ = watch.lowest;
  kinetic_peak_ = watch.kinetic_peak;
  depth_energy_start_ = watch.depth_start;
}

double DanModel::width_between(std::size_t j) const {
  return 0.5 * (path_.width(b_.s[j]) + path_.width(b_.s[j + 1]));
}

double DanModel::block_depth(std::size_t j) const {
  return b_.volume[j] / ((b_.s[j + 1] - b_.s[j]) * width_between(j));
}

double DanModel::boundary_depth(std::size_t i) const {
  const std::size_t n = size();
  if (i == 0) return 0.5 * block_depth(0);
  if (i + 1 == n) return 0.5 * block_depth(n - 2);
  return 0.5 * (block_depth(i - 1) + block_depth(i));
}

// k dH/ds at boundary block i (Kuen eq. 2.35 with the "+" typo corrected): the
// mean of the one-sided slopes to the neighbouring blocks' mid-points, each
// with that block's k. The end blocks have one side only.
double DanModel::pressure_gradient(std::size_t i, const std::vector<double>& h,
                                   const std::vector<double>& H) const {
  const std::size_t n = size();
  const auto& s = b_.s;
  double sum = 0.0;
  int sides = 0;
  if (i + 1 < n) {
    const double mid = 0.5 * (s[i] + s[i + 1]);
    sum += b_.k[i] * (h[i] - H[i]) / (mid - s[i]);
    ++sides;
  }
  if (i > 0) {
    const double mid = 0.5 * (s[i - 1] + s[i]);
    sum += b_.k[i - 1] * (H[i] - h[i - 1]) / (s[i] - mid);
    ++sides;
  }
  return sum / sides;
}

// (1 / (rho g cos psi H)) dp/ds at boundary block i in the conservative form:
// the pressure resultants P_j = k_j rho g cos h_j^2 / 2 of the blocks on either
// side (none beyond the ends) over the node's volume per width
// (h_{j-1} L_{j-1} + h_j L_j) / 2. For uniform k this is k dh/ds.
double DanModel::pressure_divergence(std::size_t i, const std::vector<double>& h) const {
  const std::size_t n = size();
  const auto& s = b_.s;
  double behind = 0.0, ahead = 0.0, volume = 0.0;
  if (i > 0) {
    behind = b_.k[i - 1] * h[i - 1] * h[i - 1];
    volume += h[i - 1] * (s[i] - s[i - 1]);
  }
  if (i + 1 < n) {
    ahead = b_.k[i] * h[i] * h[i];
    volume += h[i] * (s[i + 1] - s[i]);
  }
  return (ahead - behind) / volume;
}

void DanModel::step(double dt) {
  const std::size_t n = size();
  const double g = p_.gravity;
  for (std::size_t j = 0; j + 1 < n; ++j) h_[j] = block_depth(j);
  H_[0] = 0.5 * h_[0];
  H_[n - 1] = 0.5 * h_[n - 2];
  for (std::size_t i = 1; i + 1 < n; ++i) H_[i] = 0.5 * (h_[i - 1] + h_[i]);

  v_new_.resize(n);
  x_.resize(n);
  for (std::size_t i = 0; i < n; ++i) {
    const double s = b_.s[i], v = b_.v[i];
    const double theta = path_.angle(s);
    const double cos_psi = std::cos(theta);
    // Downslope gravity minus the pressure gradient, per unit mass.
    const double pressure = p_.pressure_form == PressureForm::Gradient
                                ? pressure_gradient(i, h_, H_)
                                : pressure_divergence(i, h_);
    const double drive = -g * std::sin(theta) - g * cos_psi * pressure;
    // Basal normal stress with the centripetal acceleration of the curved
    // path; a block flying off a convex crest carries no friction.
    const double kappa = p_.centripetal ? path_.curvature(s) : 0.0;
    const double sigma_n = std::max(0.0, p_.density * H_[i] * (g * cos_psi + v * v * kappa));
    const double resist =
        basal_shear(p_.rheology, sigma_n, std::abs(v), p_.density, g) / (p_.density * H_[i]);
    const double trial = v + dt * drive;
    // Friction stops a block but never pushes it backwards.
    v_new_[i] = std::abs(trial) <= dt * resist ? 0.0 : trial - std::copysign(dt * resist, trial);
    x_[i] = path_.point(s).x();
  }
  smooth_velocities(p_.smoothing, x_, mass_, dt, v_new_, scratch_);

  s_old_ = b_.s;
  for (std::size_t i = 0; i < n; ++i) {
    b_.s[i] += dt * v_new_[i];  // symplectic Euler: see dan.hpp
    if (!std::isfinite(b_.s[i]) || !std::isfinite(v_new_[i]))
      throw RunError(fmt::format("DAN: block {} has a non-finite position or velocity at t = {} s",
                                 i, b_.time));
  }
  for (std::size_t j = 0; j + 1 < n; ++j) {
    const double length = b_.s[j + 1] - b_.s[j], old = s_old_[j + 1] - s_old_[j];
    if (!(length > 0))
      throw RunError(
          fmt::format("DAN: boundary blocks {} and {} crossed at t = {} s; reduce the time step", j,
                      j + 1, b_.time));
    const double dh_dx = (H_[j + 1] - H_[j]) / old;
    b_.k[j] = update_earth_pressure(p_.pressure, b_.k[j], (length - old) / old, dh_dx);
  }
  b_.v.swap(v_new_);
  b_.time += dt;
  check_energy();
}

void DanModel::check_energy() {
  if (!(p_.energy_growth_tolerance > 0)) return;
  const double e = total_energy();
  kinetic_peak_ = std::max(kinetic_peak_, kinetic_energy());
  energy_min_ = std::min(energy_min_, e);
  const double scale = std::max(depth_energy_start_, kinetic_peak_);
  // The round-off of the sum (heights measured from an arbitrary datum) is no
  // growth.
  if (e - energy_min_ > p_.energy_growth_tolerance * scale + 1e-12 * std::abs(e))
    throw RunError(fmt::format(
        "DAN: energy blow-up at t = {:.4g} s: the total energy rose by {:.4g} J above its "
        "lowest value, more than {} of {:.4g} J (the larger of the initial depth "
        "energy and the peak kinetic energy); the model only dissipates, so the scheme is unstable "
        "(try the "
        "'divergence' pressure form, the basal-angle modification or fewer blocks)",
        b_.time, e - energy_min_, p_.energy_growth_tolerance, scale));
}

double DanModel::stable_time_step(double courant) const {
  const std::size_t n = size();
  double k_max = 0.0;
  for (double k : b_.k) k_max = std::max(k_max, k);
  double dt = std::numeric_limits<double>::infinity();
  for (std::size_t j = 0; j + 1 < n; ++j) {
    const double length = b_.s[j + 1] - b_.s[j];
    const double h = block_depth(j);
    const double speed = std::max(std::abs(b_.v[j]), std::abs(b_.v[j + 1])) +
                         std::sqrt(std::max(k_max, 1e-3) * p_.gravity * h);
    dt = std::min(dt, courant * length / speed);
  }
  return dt;
}

double DanModel::total_mass() const {
  double m = 0.0;
  for (double V : b_.volume) m += p_.density * V;
  return m;
}

double DanModel::deformed_volume() const {
  double vol = 0.0;
  for (std::size_t j = 0; j + 1 < size(); ++j)
    vol += block_depth(j) * width_between(j) * (b_.s[j + 1] - b_.s[j]);
  return vol;
}

double DanModel::momentum() const {
  double p = 0.0;
  for (std::size_t i = 0; i < size(); ++i) p += mass_[i] * b_.v[i];
  return p;
}

double DanModel::kinetic_energy() const {
  double e = 0.0;
  for (std::size_t i = 0; i < size(); ++i) e += 0.5 * mass_[i] * b_.v[i] * b_.v[i];
  return e;
}

double DanModel::depth_energy() const {
  double e = 0.0;
  for (std::size_t j = 0; j + 1 < size(); ++j) {
    const double cos_psi = std::cos(path_.angle(0.5 * (b_.s[j] + b_.s[j + 1])));
    e += 0.5 * p_.density * p_.gravity * cos_psi * b_.volume[j] * block_depth(j);
  }
  return e;
}

double DanModel::total_energy() const {
  double e = depth_energy();
  for (std::size_t i = 0; i < size(); ++i)
    e += mass_[i] * (0.5 * b_.v[i] * b_.v[i] + p_.gravity * path_.point(b_.s[i]).y());
  return e;
}

double DanModel::max_speed() const {
  double m = 0.0;
  for (double v : b_.v) m = std::max(m, std::abs(v));
  return m;
}

bool DanModel::at_rest() const {
  // Friction stops blocks exactly, but the smoothing that follows in the same
  // step hands stopped blocks round-off speeds from moving neighbours.
  return std::all_of(b_.v.begin(), b_.v.end(), [](double v) { return std::abs(v) <= kRestSpeed; });
}

}  // namespace talus::runout
