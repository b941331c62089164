#pragma once
// The particle half of the hybrid method of van den Bout et al. (2021) §2.4
// (spec mpm.md "The hybrid particle method"): structured material (solid with
// its confined fluid) as depth-averaged smoothed particles on a terrain, in
// horizontal coordinates as the grid models (runout/grid/fv2d.hpp).
//
// Per step, for every particle i with neighbours j within the kernel's support:
//   areal density  rho_i = sum_j m_j W_ij, depth h_i = rho_i / rho_c;
//   velocity gradient L_i = (1 / rho_i) sum_j m_j (v_j - v_i) (x) grad_i W_ij
//     (eqs. 79-80), which drives the Drucker-Prager stress with the Jaumann
//     rate and the cohesion loss of eq. 26 (mpm::DruckerPrager, plane strain
//     through the depth as the plan-view MPM), the dilation that drives the
//     loss averaged over the material's nonlocal_length as in the plan-view
//     MPM. The seed's eq. 79 prints (m_j / rho_j); with that form the stress
//     does not do the work the forces do where the areal density varies, and
//     a block's edges were unstable (a 1e-10 m/s perturbation grew to 0.68 m/s
//     in 0.5 s): (1 / rho_i) sum_j m_j is used, the form that pairs with eq. 78;
//   depth-integrated stress S_i = h_i sigma_i - P_i I, with P_i the
//     Rankine-Bell lateral earth pressure of the weight (eq. 43) in its active
//     state, int_0^h max(0, K_a gamma z - 2 c sqrt(K_a)) dz with
//     gamma = rho_c g cos^2(theta) and the particle's current cohesion c (a
//     cracked particle spreads like granular material; the passive resistance
//     is in the solved stress);
//   acceleration sum_j m_j (S_i / rho_i^2 + S_j / rho_j^2 + f_ij^n (R_i + R_j)
//     - Pi_ij I) grad_i W_ij (eq. 78) with Monaghan's artificial viscosity
//     Pi_ij (eqs. 83-84) and Gray, Monaghan & Swift's (2001) artificial
//     stress R against the tensile instability (eqs. 85-86: R's principal
//     values -eps s / rho^2 for tensile principal values s of S, f_ij =
//     W_ij / W(d0));
//   the bed: gravity -g_e cos^2(theta) grad(b) and the basal Coulomb
//     friction tan(delta) g_e cos^2(theta) per unit mass (eq. 36 with the
//     weight as normal load), g_e = g + u^T Hess(b) u with the centripetal
//     load on curved ground (a point held on the bed then keeps its energy),
//     the friction as an impulse that stops a particle and never reverses it;
//   symplectic Euler: v += dt a, x += dt v; walls at the terrain's edges and
//     around its no-data cells (obstacles), with Coulomb friction.
// Every loop gathers over neighbours (no scatter), so the result is the same
// bits for any number of threads.
#include <vector>

#include "talus/hybrid/kernel.hpp"
#include "talus/hybrid/neighbours.hpp"
#include "talus/hybrid/particles.hpp"
#include "talus/mpm/materials.hpp"
#include "talus/runout/grid/terrain.hpp"

namespace talus::hybrid {

struct HybridParams {
  double smoothing_length = 0.0;  // l, m (the kernel's support is 2 l)
  mpm::MaterialParams material;   // model "drucker_prager"; density is rho_c
  double tan_basal_friction = 0.0;
  double wall_friction = 0.0;  // mu against the domain's no-data cells (obstacles)
  double gravity = 9.81;
  double viscosity_alpha = 1.0;        // Monaghan's alpha_Pi (the seed: close to 1)
  double viscosity_beta = 1.0;         // beta_Pi
  double artificial_stress = 0.3;      // eps (Gray et al. 2001: 0.2-0.3)
  int artificial_stress_exponent = 4;  // n
  bool earth_pressure = true;
  // The bed's centripetal load on curved ground (fv2d's term): gravity's
  // pull and the friction's load use g + u^T Hess(b) u instead of g.
  bool curvature = true;
  double courant = 0.25;  // dt = courant l / (c + max |v|)
};

// Sums over the particles, for checks and summaries.
struct HybridTotals {
  double mass = 0.0;        // kg
  double momentum_x = 0.0;  // kg m/s
  double momentum_y = 0.0;
  double kinetic_energy = 0.0;  // J
  double max_speed = 0.0;       // m/s
};

class HybridSolver {
 public:
  // particle_spacing: the initial spacing d0 of the artificial stress's
  // f_ij = W_ij / W(d0). Throws InputError for a bad parameter, a material
  // that is not Drucker-Prager, or a particle outside the terrain.
  HybridSolver(runout::Terrain terrain, HybridParams params, Particles particles,
               double particle_spacing);

  double stable_time_step() const;
  void step(double dt);  // throws RunError when a value is not finite
  double time() const { return time_; }

  const Particles& particles() const { return p_; }
  const HybridParams& params() const { return params_; }
  const runout::Terrain& terrain() const { return terrain_; }
  HybridTotals totals() const;
  // Remaining strength fraction c / c0 of particle k (1 without cohesion).
  double strength_fraction(std::size_t k) const;
  // The earth pressure's depth integral P (N/m) for a depth h, cohesion c and
  // normal gravity g cos^2(theta); exposed for tests.
  double lateral_force(double depth, double cohesion, double normal_gravity) const;

 private:
  struct Bed {
    double gx, gy;  // the bed's horizontal pull on a particle
    double load;    // its normal load per unit mass times cos^2: friction's
    double weight;  // g cos^2, the load at rest (earth pressure)
  };
  Bed bed_at(double x, double y, double u, double v) const;
  void neighbours();
  void densities();
  void stresses(double dt);
  void average_dilation();
  void accelerations();
  void integrate(double dt);

  runout::Terrain terrain_;
  HybridParams params_;
  Particles p_;
  CubicSplineKernel kernel_;
  mpm::DruckerPrager material_;
  NeighbourGrid grid_;
  double rho_c_, c0_, k_active_, sqrt_k_active_, w_d0_, sound_speed_;
  double nonlocal_ = 0.0;  // L of the cohesion loss's average (0: local)
  double time_ = 0.0;
  // Per particle: S / rho^2 and R (xx, xy, yy), the acceleration.
  std::vector<double> sxx_, sxy_, syy_, rxx_, rxy_, ryy_, ax_, ay_;
  // This step's neighbour pairs, particle by particle (CSR): j, x_i - x_j,
  // W_ij and dW/dr / r.
  std::vector<std::size_t> list_start_;
  std::vector<int> pair_j_;
  std::vector<double> pair_dx_, pair_dy_, pair_w_, pair_dw_;
  std::vector<double> gradient_;         // L per particle: xx, xy, yx, yy
  std::vector<double> loss_, averaged_;  // max(0, tr D) dt, and its nonlocal average
  std::vector<double> lattice_;          // the average's lattice: mass x loss, mass
};

}  // namespace talus::hybrid
