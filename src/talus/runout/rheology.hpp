#pragma once
// Basal resistance of a depth-averaged flow (DAN's "rheologies", Hungr 1995;
// Kuen 2011 §2.2.5): the shear stress at the bed from the effective normal
// stress, the speed and the depth. Each law is a small type that declares its
// name and keys (core/declared_keys.hpp) next to its stress, and one entry in
// RheologyLaws; the reader and writer take the keys from there. DAN also
// offers plastic, Newtonian, turbulent, Bingham, Coulomb-viscous and
// power-law flow: each would be one more type here.
#include <array>
#include <cmath>
#include <cstddef>
#include <string_view>

#include "talus/core/declared_keys.hpp"

namespace talus::runout {

// The coefficients of every law; each law reads its own.
struct BasalRheology {
  // Index in RheologyLaws (an index, not a name: basal_shear runs per cell).
  std::size_t law = 0;
  double tan_friction = 0.0;         // tan(phi_b) (frictional) or mu (Voellmy)
  double pore_pressure_ratio = 0.0;  // r_u: sigma_eff = (1 - r_u) sigma (frictional)
  double turbulence = 500.0;         // Voellmy xi, m/s^2
};
using RheologyKey = DeclaredKey<BasalRheology>;

// Frictional (spec runout.md, with the tan(phi_b) that Kuen's eq. 2.39 lost):
// tau = (1 - r_u) sigma_n tan(phi_b).
struct FrictionalRheology {
  static constexpr std::string_view name = "frictional";
  static constexpr std::array<RheologyKey, 2> keys{
      required_key("basal_friction", &BasalRheology::tan_friction, between(0, 90, false, true),
                   KeyUnit::TanOfDegrees),
      optional_key("pore_pressure_ratio", &BasalRheology::pore_pressure_ratio, 0.0,
                   between(0.0, 1.0, false, true))};
  static KeyProblem check(const BasalRheology&) { return {}; }
  static double shear(const BasalRheology& r, double sigma_n, double, double, double) {
    return (1.0 - r.pore_pressure_ratio) * sigma_n * r.tan_friction;
  }
};

// Voellmy: tau = sigma_n mu + rho g v^2 / xi.
struct VoellmyRheology {
  static constexpr std::string_view name = "voellmy";
  static constexpr std::array<RheologyKey, 2> keys{
      required_key("friction_coefficient", &BasalRheology::tan_friction, non_negative()),
      required_key("turbulence", &BasalRheology::turbulence, positive())};
  static KeyProblem check(const BasalRheology&) { return {}; }
  static double shear(const BasalRheology& r, double sigma_n, double speed, double density,
                      double g) {
    return sigma_n * r.tan_friction + density * g * speed * speed / r.turbulence;
  }
};

// The laws a scenario may name, the first the default.
using RheologyLaws = LawList<FrictionalRheology, VoellmyRheology>;

// Magnitude of the basal shear stress (Pa), acting against the motion.
// sigma_n: total normal stress at the bed (Pa, >= 0), speed: |v| (m/s),
// density (kg/m^3), g (m/s^2).
inline double basal_shear(const BasalRheology& r, double sigma_n, double speed, double density,
                          double g) {
  return RheologyLaws::visit(
      r.law, [&]<class Law>() { return Law::shear(r, sigma_n, speed, density, g); });
}

}  // namespace talus::runout
