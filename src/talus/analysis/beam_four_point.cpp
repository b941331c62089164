#include "talus/analysis/beam_four_point.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "talus/analysis/beam.hpp"
#include "talus/analysis/force_network.hpp"
#include "talus/core/error.hpp"

namespace talus::analysis {

// Source eq. 43 (appendix B eq. 64): the bending moment F L / 6 between the
// rods over the section modulus t h² / 6.
double four_point_stress(double force, double span, double height, double thickness) {
  return force * span / (height * height * thickness);
}

// Source eq. 44 (65): σ / E_b with Δz = 23 F L³ / (1296 E_b I) for the total
// load F shared by the two rods at L/3 and 2L/3.
double four_point_strain(double deflection, double span, double height) {
  return deflection * 108.0 * height / (23.0 * span * span);
}

SmallStrainFit fit_small_strain(std::span<const double> strain, std::span<const double> stress,
                                double strain_limit) {
  double see = 0, ses = 0, ss = 0, sss = 0;
  int n = 0;
  for (std::size_t i = 0; i < strain.size() && i < stress.size(); ++i) {
    if (!(strain[i] > 0 && strain[i] <= strain_limit)) continue;
    see += strain[i] * strain[i];
    ses += strain[i] * stress[i];
    ss += stress[i];
    sss += stress[i] * stress[i];
    ++n;
  }
  if (n < 3)
    throw InputError(fmt::format(
        "beam fit: {} samples with 0 < strain <= {} (3 or more needed); record the series more "
        "often or load more slowly",
        n, strain_limit));
  SmallStrainFit fit;
  fit.modulus = ses / see;
  fit.points = n;
  // Σ(σ - E ε)² = Σσ² - 2 E Σσε + E² Σε², with E Σε² = Σσε.
  const double residual = sss - fit.modulus * ses;
  const double spread = sss - ss * ss / n;
  fit.r2 = spread > 0 ? 1.0 - residual / spread : 0.0;
  return fit;
}

namespace {

// Gaussian smoothing, renormalised where the kernel leaves the grid.
std::vector<double> smooth(const std::vector<double>& y, double sigma_cells) {
  const int n = static_cast<int>(y.size());
  const int reach = static_cast<int>(std::ceil(3.0 * sigma_cells));
  std::vector<double> out(n, 0.0);
  for (int i = 0; i < n; ++i) {
    double sum = 0, wsum = 0;
    for (int k = std::max(0, i - reach); k <= std::min(n - 1, i + reach); ++k) {
      const double u = (k - i) / sigma_cells, w = std::exp(-0.5 * u * u);
      sum += w * y[k];
      wsum += w;
    }
    out[i] = sum / wsum;
  }
  return out;
}

std::vector<double> derivative(const std::vector<double>& y, double h) {
  const std::size_t n = y.size();
  std::vector<double> d(n, 0.0);
  for (std::size_t i = 0; i < n; ++i) {
    const std::size_t a = i > 0 ? i - 1 : 0, b = i + 1 < n ? i + 1 : n - 1;
    d[i] = (y[b] - y[a]) / (static_cast<double>(b - a) * h);
  }
  return d;
}

}  // namespace

YieldPoint yield_from_curvature(std::span<const double> strain, std::span<const double> stress,
                                double width) {
  YieldPoint yp;
  double top = 0.0;
  for (double e : strain) top = std::max(top, e);
  // Five grid points per smoothing width.
  const double h = width / 5.0;
  const int n = static_cast<int>(top / h) + 1;
  if (!(width > 0) || n < 25) return yp;  // under 5 widths of curve: nothing to find
  // The first smoothing straight from the samples (a Gaussian-weighted mean
  // at each grid point): binning first would alias the samples' spacing
  // against the grid's, which the second derivative magnifies.
  std::vector<double> s(n, 0.0);
  for (int k = 0; k < n; ++k) {
    double sum = 0, wsum = 0;
    for (std::size_t i = 0; i < strain.size() && i < stress.size(); ++i) {
      const double u = (strain[i] - k * h) / width;
      if (!(std::abs(u) <= 4.0)) continue;
      const double w = std::exp(-0.5 * u * u);
      sum += w * stress[i];
      wsum += w;
    }
    if (!(wsum > 0)) return yp;  // a gap in the curve wider than the smoothing
    s[k] = sum / wsum;
  }
  const std::vector<double> d2 = derivative(smooth(derivative(s, h), 5.0), h);
  for (int k = 11; k < n - 10; ++k)
    if (d2[k - 1] < 0 && d2[k] >= 0) {
      const double u = d2[k - 1] / (d2[k - 1] - d2[k]);  // where d2 crosses 0
      yp.found = true;
      yp.strain = (k - 1 + u) * h;
      yp.stress = s[k - 1] + u * (s[k] - s[k - 1]);
      return yp;
    }
  return yp;
}

nlohmann::json four_point_curve(std::span<const double> strain, std::span<const double> stress,
                                double linear_strain, double yield_smoothing) {
  nlohmann::json j;
  j["largest_strain"] = *std::max_element(strain.begin(), strain.end());
  const auto top = std::max_element(stress.begin(), stress.end());
  j["largest_stress"] = *top;
  j["strain_at_largest_stress"] = strain[top - stress.begin()];
  try {
    const SmallStrainFit fit = fit_small_strain(strain, stress, linear_strain);
    j["youngs_modulus"] = fit.modulus;
    j["fit_points"] = fit.points;
    j["fit_r2"] = fit.r2;
  } catch (const InputError& e) {
    j["fit_error"] = e.what();
  }
  const YieldPoint yp = yield_from_curvature(strain, stress, yield_smoothing);
  j["yield_found"] = yp.found;
  if (yp.found) {
    j["yield_strength"] = yp.stress;
    j["yield_strain"] = yp.strain;
  }
  return j;
}

FourPointObserver::FourPointObserver(std::filesystem::path out, const dem::DemScenario& sc,
                                     const dem::DemSystem<3>& s)
    : out_(std::move(out)) {
  if (!sc.beam || sc.beam->test != dem::BeamTest::FourPoint)
    throw InputError("[beam]: no four-point test");
  const BeamMembrane beam = find_beam_membrane(sc, s);
  membrane_ = beam.index;
  nominal_ = beam.rest_size;
  b_ = *sc.beam;
  std::filesystem::create_directories(out_);
  csv_ = std::make_unique<io::CsvSeries>(
      out_ / "beam.csv",
      std::vector<std::string>{"time", "rod_travel", "rod_force", "bottom_centre_z", "deflection",
                               "strain", "stress", "support_reaction_z", "kinetic_energy",
                               "grain_contacts", "mean_contact_force", "mean_normal_force",
                               "mean_tangential_force", "coulomb_fraction"},
      false);
}

void FourPointObserver::on_series(const dem::DemRun<3>& run) {
  const auto& s = run.system;
  const auto& mb = s.membranes[membrane_];
  const auto& rig = *mb.rig;
  const double z = mean_z(rig.measured, mb.body.x);
  const bool bending = s.time >= b_.bending_start && rig.supported;
  if (bending && !started_) {
    started_ = true;
    z0_ = z;
    const BeamSection sec = measure_section(rig, mb.body.x);
    span_ = sec.span;
    width_ = sec.width;
    height_ = sec.height;
  }
  // The rods' mean force since the last row (a single step's jitters).
  const double force = s.time > last_time_
                           ? (rig.rod_impulse - last_impulse_) / (s.time - last_time_)
                           : rig.rod_force;
  last_time_ = s.time;
  last_impulse_ = rig.rod_impulse;
  double dz = 0, eps = 0, sigma = 0;
  if (started_) {
    dz = z0_ - z;
    eps = four_point_strain(dz, span_, height_);
    sigma = four_point_stress(force, span_, height_, width_);
    strain_.push_back(eps);
    stress_.push_back(sigma);
  }
  // The supports' part of the fixed particles' reaction (last step): the rods hold -F.
  const double support = mb.reaction.z() + rig.rod_force;
  const double ke = dem::kinetic_energy(s.particles) + dem::membrane::kinetic_energy(mb);
  const ForceNetwork net = force_network(run.stepper->pair_contact_forces());
  csv_->row({s.time, b_.rod_travel_at(s.time), force, z, dz, eps, sigma, support, ke,
             static_cast<double>(net.contacts), net.mean_force, net.mean_normal,
             net.mean_tangential, net.coulomb_fraction});
}

nlohmann::json FourPointObserver::finish() const {
  csv_->flush();
  nlohmann::json j;
  j["test"] = "four_point";
  j["bending_start"] = b_.bending_start;
  j["nominal_size"] = {nominal_.x(), nominal_.y(), nominal_.z()};
  j["span"] = span_;
  j["width"] = width_;
  j["height"] = height_;
  if (b_.bending_friction) j["bending_friction"] = *b_.bending_friction;
  if (strain_.empty()) return j;
  j.update(four_point_curve(strain_, stress_, kFourPointLinearStrain, b_.yield_smoothing));
  // The same curve with the membrane's rest length, height and width, as the
  // source computes it (its supports are at the ends of a beam that the
  // vacuum shrinks a little): σ scales by L / (h² t), E = σ/ε by L³ / (h³ t).
  const double l = nominal_.x() / span_, hr = height_ / nominal_.z(), tr = width_ / nominal_.y();
  if (j.contains("youngs_modulus"))
    j["youngs_modulus_nominal"] = j["youngs_modulus"].get<double>() * l * l * l * hr * hr * hr * tr;
  if (j["yield_found"].get<bool>())
    j["yield_strength_nominal"] = j["yield_strength"].get<double>() * l * hr * hr * tr;
  return j;
}

}  // namespace talus::analysis
