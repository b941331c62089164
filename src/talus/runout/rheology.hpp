#pragma once
// Basal resistance of a depth-averaged flow (DAN's "rheologies", Hungr 1995;
// Kuen 2011 §2.2.5): the shear stress at the bed from the effective normal
// stress, the speed and the depth. One plain struct chosen by name and one
// switch, so the time loop pays no virtual call and a new law is one more case
// (DAN also offers plastic, Newtonian, turbulent, Bingham, Coulomb-viscous and
// power-law flow).
#include <cmath>

namespace talus::runout {

enum class RheologyKind { Frictional, Voellmy };

struct BasalRheology {
  RheologyKind kind = RheologyKind::Frictional;
  double tan_friction = 0.0;         // tan(phi_b) (frictional) or mu (Voellmy)
  double pore_pressure_ratio = 0.0;  // r_u: sigma_eff = (1 - r_u) sigma (frictional)
  double turbulence = 500.0;         // Voellmy xi, m/s^2
};

// Magnitude of the basal shear stress (Pa), acting against the motion.
// sigma_n: total normal stress at the bed (Pa, >= 0), speed: |v| (m/s),
// density (kg/m^3), g (m/s^2). Frictional (spec runout.md, with the tan(phi_b)
// that Kuen's eq. 2.39 lost): tau = (1 - r_u) sigma_n tan(phi_b). Voellmy:
// tau = sigma_n mu + rho g v^2 / xi.
inline double basal_shear(const BasalRheology& r, double sigma_n, double speed, double density,
                          double g) {
  switch (r.kind) {
    case RheologyKind::Frictional:
      return (1.0 - r.pore_pressure_ratio) * sigma_n * r.tan_friction;
    case RheologyKind::Voellmy:
      return sigma_n * r.tan_friction + density * g * speed * speed / r.turbulence;
  }
  return 0.0;
}

}  // namespace talus::runout
