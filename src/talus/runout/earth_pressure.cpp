#include "talus/runout/earth_pressure.hpp"

#include <algorithm>
#include <cmath>

namespace talus::runout {

EarthPressureLimits earth_pressure_limits(double phi_internal, double tan_phi_basal) {
  const double c2 = std::cos(phi_internal) * std::cos(phi_internal);
  // phi_b,mod > phi_i would make the root imaginary: clamp to phi_i (root 0).
  const double tan2 =
      std::min(tan_phi_basal * tan_phi_basal, std::tan(phi_internal) * std::tan(phi_internal));
  const double root = std::sqrt(std::max(0.0, 1.0 - c2 * (1.0 + tan2)));
  return {2.0 * (1.0 - root) / c2 - 1.0, 2.0 * (1.0 + root) / c2 - 1.0};
}

double initial_earth_pressure(const EarthPressure& model) {
  if (model.mode == EarthPressureMode::Constant) return model.constant;
  const auto lim = earth_pressure_limits(model.phi_internal, model.tan_phi_basal);
  if (model.mode == EarthPressureMode::SavageHutter) return lim.active;
  return std::clamp(model.constant, lim.active, lim.passive);
}

double update_earth_pressure(const EarthPressure& model, double k, double d_strain, double dh_dx) {
  if (model.mode == EarthPressureMode::Constant) return model.constant;
  const double tan_mod = model.modify_basal_angle ? model.tan_phi_basal - model.lambda * k * dh_dx
                                                  : model.tan_phi_basal;
  const auto lim = earth_pressure_limits(model.phi_internal, tan_mod);
  if (model.mode == EarthPressureMode::SavageHutter) {
    if (d_strain > 0) return lim.active;
    if (d_strain < 0) return lim.passive;
    return std::clamp(k, lim.active, lim.passive);
  }
  const double stiffness = (lim.passive - lim.active) / model.passive_strain;
  return std::clamp(k - stiffness * d_strain, lim.active, lim.passive);
}

}  // namespace talus::runout
