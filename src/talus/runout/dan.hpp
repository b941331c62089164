#pragma once
// DAN: Hungr's (1995) 1D Lagrangian depth-averaged runout model along a curved
// path, as in spec runout.md §1 and Kuen (2011) §2.2.4. n boundary blocks at
// path coordinates S_i carry the velocities; between them n - 1 mass blocks of
// constant volume V_j, so mass is conserved by construction. Per step:
//   depth of mass block  h_j = 2 V_j / ((S_{j+1} - S_j)(B_j + B_{j+1}))
//   boundary depth       H_i = (h_{i-1} + h_i) / 2, ends H = h / 2
//   pressure gradient    k dH/ds from eq. 2.35 (typo corrected)
//   acceleration         a_i = g sin(alpha) - g cos(psi) k dH/ds - T / (rho H)
//   basal stress         from the rheology, normal stress rho H (g cos psi + v^2 kappa)
//   velocity             v_i = v_i' + a_i dt, friction never reverses a block
//   smoothing            momentum-conserving form of eq. 2.40 (smoothing.hpp)
//   position             S_i = S_i' + dt v_i (semi-implicit Euler; see below)
//   earth pressure       k_j from the strain of block j (earth_pressure.hpp)
// The position update deviates from Kuen's eq. 2.31, S_i = S_i' + dt/2 (v_i +
// v_i'): with v_i = v_i' + dt a(S') that scheme multiplies the energy of an
// oscillation of frequency w by 1 + (w dt)^2 / 2 every step (the determinant
// of its update matrix), so block-to-block pressure waves grow unless the
// smoothing damps them; on the flume it blew up at 400 blocks. Using the new
// velocity (symplectic Euler) has determinant 1 and is stable for w dt < 2.
// Depths are measured normal to the path and block lengths along it (eq. 2.32
// as printed); the release is cut into vertical slices (release.hpp).
//
// Pressure term: eq. 2.35 (the spec's form, default) writes k dH/ds as the
// mean of one-sided slopes of H, each times its block's k. Where k jumps from
// block to block (k_a next to k_p) that form is not the gradient of the blocks'
// pressures: a block at k_p between two at k_a exerts no force on its
// neighbours, and the pressure forces do work that no strain of the blocks
// pays for. On the flume without the basal-angle modification (Savage-Hutter
// switch, and Hungr's law as well) that work pumps energy into the deposit at
// 200-400 blocks until it climbs over the barrier. PressureForm::Divergence is
// the conservative form of the same term, the force on boundary block i being
// the difference of its two blocks' pressure resultants
// P_j = k_j rho g cos(psi) h_j^2 / 2 (what fv2d's fluxes are): its work is
// sum_j P_j dL_j, so k_a while stretching and k_p while compressing only ever
// dissipate. For uniform k both forms are k dh/ds to second order.
//
// Energy check: friction, smoothing and the k_a/k_p hysteresis only dissipate,
// so the total energy (kinetic, of the boundary blocks' heights on the path, and
// of the depth, sum rho g cos(psi) V_j h_j / 2) can only fall, up to the
// discretisation error. A step after which it has risen above its lowest value
// so far by more than energy_growth_tolerance times the larger of the initial
// depth energy and the largest kinetic energy so far throws a RunError naming
// the time. On the flume (docs/validation.md) healthy runs regrow by at most
// 0.11 of that scale (0.108 measured; the profile scenario 0.08) (the Hungr law stores and returns
// some energy in k; the explicit step's energy error), the unstable ones by 1 to 2.
#include <vector>

#include "talus/runout/earth_pressure.hpp"
#include "talus/runout/path.hpp"
#include "talus/runout/rheology.hpp"
#include "talus/runout/smoothing.hpp"

namespace talus::runout {

enum class PressureForm {
  Gradient,   // Kuen eq. 2.35 (spec runout.md §1): k dH/ds from one-sided slopes
  Divergence  // difference of the blocks' pressure resultants (conservative)
};

struct DanParams {
  double density = 1630.0;  // bulk, kg/m^3
  double gravity = 9.81;    // m/s^2, acting in -y
  BasalRheology rheology;
  EarthPressure pressure;
  SmoothingParams smoothing;
  bool centripetal = true;  // the v^2 kappa term in the basal normal stress
  PressureForm pressure_form = PressureForm::Gradient;
  // Largest allowed regrowth of the total energy (see above); <= 0: no check.
  double energy_growth_tolerance = 0.25;
};

// The state: everything that changes in time, plus the constant volumes.
struct DanBlocks {
  std::vector<double> s;       // boundary blocks' path coordinates, increasing (n)
  std::vector<double> v;       // their velocities along the path (n)
  std::vector<double> volume;  // mass blocks' volumes, constant (n - 1)
  std::vector<double> k;       // mass blocks' earth-pressure coefficients (n - 1)
  double time = 0.0;
};

class DanModel {
 public:
  // Throws InputError for fewer than 2 boundary blocks, non-increasing s,
  // a volume <= 0 or mismatched sizes. blocks.k empty: initial_earth_pressure.
  DanModel(RunoutPath path, DanParams params, DanBlocks blocks);

  // One explicit step. Throws RunError when blocks cross or a value is not
  // finite (time step too large for the block spacing).
  void step(double dt);

  // A time step for which the pressure waves and the blocks' motion cross at
  // most `courant` of the shortest mass block.
  double stable_time_step(double courant) const;

  const DanBlocks& blocks() const { return b_; }
  const RunoutPath& path() const { return path_; }
  const DanParams& params() const { return p_; }
  std::size_t size() const { return b_.s.size(); }

  // Derived quantities of the current state.
  double block_depth(std::size_t j) const;     // h_j
  double boundary_depth(std::size_t i) const;  // H_i
  double node_mass(std::size_t i) const { return mass_[i]; }
  double total_mass() const;       // rho sum V_j (constant)
  double deformed_volume() const;  // sum h_j B_j (S_{j+1} - S_j): equals sum V_j
  double momentum() const;         // sum m_i v_i along the path
  double kinetic_energy() const;
  // Kinetic + boundary blocks' m g y on the path + depth energy (see above), J.
  double total_energy() const;
  double depth_energy() const;  // sum rho g cos(psi) V_j h_j / 2, J
  double max_speed() const;

  // The energy check's memory: part of a checkpoint.
  struct EnergyWatch {
    double lowest = 0.0, kinetic_peak = 0.0, depth_start = 0.0;
  };
  EnergyWatch energy_watch() const { return {energy_min_, kinetic_peak_, depth_energy_start_}; }
  // Continues from a checkpoint of this model: the blocks must have its sizes
  // and volumes (else InputError).
  void restore(DanBlocks blocks, EnergyWatch watch);

  // Every block slower than kRestSpeed (held by friction).
  bool at_rest() const;
  static constexpr double kRestSpeed = 1e-6;  // m/s

 private:
  double width_between(std::size_t j) const;
  double pressure_gradient(std::size_t i, const std::vector<double>& h,
                           const std::vector<double>& H) const;
  double pressure_divergence(std::size_t i, const std::vector<double>& h) const;
  void check_energy();

  RunoutPath path_;
  DanParams p_;
  DanBlocks b_;
  std::vector<double> mass_;  // boundary blocks' lumped masses, rho (V_{i-1} + V_i) / 2
  std::vector<double> h_, H_, v_new_, x_, s_old_, scratch_;
  double energy_min_ = 0.0, kinetic_peak_ = 0.0, depth_energy_start_ = 0.0;
};

}  // namespace talus::runout
