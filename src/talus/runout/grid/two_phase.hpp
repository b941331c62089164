#pragma once
// Two-phase (solid-fluid) depth-averaged flow on a terrain grid: the model of
// van den Bout et al. (2021) §2.3 for unstructured material (f_sc = f_fc = 0,
// which is Pudasaini's 2012 model; spec runout.md §3), on the finite-volume
// machinery of fv2d (fv2d.hpp): cells of the terrain grid, HLL fluxes with
// MUSCL reconstruction (monotonised central), two-stage SSP Runge-Kutta, CFL
// steps, no-data cells outside the domain, walls or open edges.
//
// Unknowns per cell, each phase p in {s (solid), f (fluid)}: its depth
// H_p = alpha_p H (volume per unit horizontal area; H = H_s + H_f, alpha_s +
// alpha_f = 1) and its horizontal momentum H_p U_p. Per unit horizontal area
// and unit density of the phase:
//   dH_p/dt + div(H_p U_p) = 0
//   fluid:  d(H_f U_f)/dt + div(H_f U_f U_f) = -g H_f grad(H + b)
//           - g n^2 |U_f| U_f H_f / H^(4/3) - chi eta U_f / (rho_f H) + D / rho_f
//   solid:  d(H_s U_s)/dt + div(H_s U_s U_s) = -gamma g H_s grad(H + b)
//           - grad(1/2 k (1 - gamma) g cos^4 H_s H) - (1 - gamma) g cos^2 H_s grad(b)
//           - tan(delta) sigma_s U_s / |U_s| - D / rho_s
// with sigma_s = H_s cos^2 ((1 - gamma) g + U_s^T Hess(b) U_s) the solid's
// bed normal stress per unit density (its buoyant weight and, as fv2d's, its
// centripetal load on a curved bed, which also enters its bed reaction)
// with gamma = rho_f / rho_s. The fluid pressure is hydrostatic in the
// vertical over the mixture's depth (seed eqs. 37-38): it pushes the fluid
// and, as buoyancy, the solid (whose basal normal stress and earth pressure
// are of its buoyant weight, (1 - gamma)). The solid's own terms are fv2d's
// Savage-Hutter ones, so alpha_f = 0 with gamma = 0 is fv2d's granular model;
// alpha_s = 0 is the shallow-water equations with Manning friction. The
// interphase force D = H C (U_f - U_s) |U_f - U_s|^(J - 1) has Pudasaini's
// drag coefficient C (two_phase_closures.hpp) and acts with virtual mass;
// eta = alpha e^(beta alpha_s); chi is the fluid's vertical shear factor
// (chi eta U / H is the bed shear of a laminar sheet; 3 for a parabolic
// profile, Iverson & Denlinger 2001).
//
// The discretisation:
// - Fluxes: the fluid's pressure 1/2 g H_f^2 (its own depth; the rest of
//   -g H_f grad(H), -g H_f grad(H_s), is a centred source, as is the solid's
//   buoyancy -gamma g H_s grad(H + b)), the solid's 1/2 k (1 - gamma) g cos^4
//   H_s H. HLL with wave speeds covering both phases. Face values: the
//   solid's depth and all velocities along limited slopes; the mixture's
//   depth from the limited free-surface slope less the bed's central slope
//   (Kurganov & Petrova's fix where a side would be negative), the fluid
//   its share of it.
// - The fluid's bed by hydrostatic reconstruction (Audusse et al. 2004) with
//   the second-order interior term: a lake at rest over any bed, dry islands
//   included, stays at rest to round-off. The solid's as fv2d's: its
//   effective weight with the terrain's slope (a solid at rest is held by
//   friction, not by a discrete balance of pressures; with k between k_a and
//   k_p in the balance its errors were multiplied by k_p at fronts).
// - Each phase's fluxes out of a cell are scaled down to what the cell holds
//   (depths never negative, mass still exact: fluxes cancel pairwise).
// - Stiff sources implicitly, after the explicit update of a stage
//   (apply_sources, two_phase_sources.hpp): the fluid's Manning and laminar resistance,
//   the drag (momentum conserving, implicit in the relative velocity), the
//   solid's Coulomb friction as an impulse shared through that implicit drag
//   (stops, never reverses; a solid at rest stays held while friction can
//   hold it against fluxes, gravity and drag, as in fv2d), then virtual
//   mass, which scales the change of the relative velocity those local
//   forces make (with gravity, buoyancy and the phases' coupling) by r,
//   finite as alpha_f -> 0. None of these limits the step, so alpha_s or
//   alpha_f -> 0 does not make it stiff. A constant force difference against
//   the drag is balanced at the exact terminal slip; relaxation towards it
//   is first order in time.
// - Virtual mass leaves out what a cell's faces carry in and out (advection
//   and each phase's own pressure flux): applied to the whole change of the
//   cell velocities it did not converge with the grid (new material arriving
//   at a front is not an acceleration).
// - A face between two wet cells whose reconstructed beds differ by more
//   than a thin layer is deep (curved, steep ground) closes for that layer:
//   there it acts as a wall (the layer's momentum into it is reflected) --
//   without that, the layer accelerated in place without moving. The side
//   depths take the bed's central slope (Kurganov & Petrova's positivity
//   fix where a side would be negative), which makes such steps third-order
//   small on smooth ground; a bed continuous across faces (Chen & Noelle
//   2022) would remove them.
#include <vector>

#include "talus/runout/earth_pressure.hpp"
#include "talus/runout/grid/domain_edges.hpp"
#include "talus/runout/grid/fv2d.hpp"
#include "talus/runout/grid/terrain.hpp"
#include "talus/runout/grid/two_phase_viscous.hpp"
#include "talus/runout/two_phase_closures.hpp"

namespace talus::runout {

struct TwoPhaseParams {
  two_phase::DragParams drag;       // densities, gravity, grain size, drag law
  double tan_basal_friction = 0.0;  // tan(delta), the solid's Coulomb friction
  EarthPressure pressure{EarthPressureMode::SavageHutter};
  double manning = 0.0;       // n, s m^-1/3 (fluid)
  double rainfall = 0.0;      // R, m/s of fluid depth on every cell of the domain
  double infiltration = 0.0;  // I, m/s, at most the fluid a cell holds
  // Per cell instead of the constants (m/s; empty: the constant everywhere).
  std::vector<double> rainfall_map, infiltration_map;
  double viscosity_alpha = 0.0;  // Pa s, eta = alpha e^(beta alpha_s)
  double viscosity_beta = 0.0;   // -
  double shear_factor = 3.0;     // chi
  // The fluid's lateral viscous stress (two_phase_viscous.hpp); off by
  // default: with a steep eta(alpha_s) (beta = 10) the flow's thin edges,
  // alpha_s -> 1, make it stiff and the debris release converged worse
  // (docs/validation/two-phase.md).
  bool lateral_viscosity = false;
  // Virtual mass (seed eq. 35) on the stage's local forces (see the .cpp).
  bool virtual_mass = true;
  // The solid's centripetal load on curved beds (fv2d's term): its bed normal
  // stress is H_s cos^2 ((1 - gamma) g + U_s^T Hess(b) U_s) per unit density.
  bool curvature = true;
  int order = 2;
  double courant = 0.45;
  double dry_depth = 1e-6;  // m: a thinner phase carries no velocity
  GridBoundary boundary = GridBoundary::Wall;
};

enum class Phase { Solid, Fluid };

// What crossed the model's boundaries so far (m^3): through open edges, from
// rain, into the ground.
struct TwoPhaseTotals {
  double solid_outflow = 0.0, fluid_outflow = 0.0, rained = 0.0, infiltrated = 0.0;
};

struct TwoPhaseState {
  std::vector<double> hs, hsu, hsv;  // solid: H_s, H_s U_s, H_s V_s per cell
  std::vector<double> hf, hfu, hfv;  // fluid: H_f, H_f U_f, H_f V_f
  double time = 0.0;
};

class TwoPhaseSolver {
 public:
  // Depths of each phase per cell (>= 0, finite, 0 outside the domain), at
  // rest. Throws InputError for a size mismatch, a bad depth or parameter.
  TwoPhaseSolver(Terrain terrain, TwoPhaseParams params, std::vector<double> solid_depth,
                 std::vector<double> fluid_depth);

  double stable_time_step() const;  // infinity when every cell is dry
  void step(double dt);             // throws RunError when a value is not finite

  const TwoPhaseState& state() const { return s_; }
  void set_state(const TwoPhaseState& state);  // checks sizes, signs, finiteness
  // Continues from a checkpoint: the state, the solid's earth-pressure
  // coefficients (kept where it neither spreads nor converges) and the totals.
  // Throws InputError for sizes that are not this grid's.
  void restore(const TwoPhaseState& state, std::vector<double> k, const TwoPhaseTotals& totals);
  const std::vector<double>& earth_pressure() const { return k_; }
  TwoPhaseTotals totals() const { return {outflow_s_, outflow_f_, rained_, infiltrated_}; }
  const Terrain& terrain() const { return terrain_; }
  const TwoPhaseParams& params() const { return p_; }

  double solid_volume() const;  // sum H_s dA, m^3
  double fluid_volume() const;
  double solid_outflow() const { return outflow_s_; }  // left through open edges
  double fluid_outflow() const { return outflow_f_; }
  double rained_volume() const { return rained_; }  // m^3 of fluid added by rain
  double infiltrated_volume() const { return infiltrated_; }
  double momentum_x() const;  // sum (rho_s H_s U_s + rho_f H_f U_f) dA
  double momentum_y() const;
  double max_speed() const;  // of either phase, horizontal

  // Per cell and phase: the bed-normal depth H_p cos(theta) and the
  // bed-parallel speed (0 where the phase is thinner than dry_depth).
  double normal_height(std::size_t c, Phase phase) const;
  double speed(std::size_t c, Phase phase) const;
  double kinetic_energy() const;  // 1/2 sum rho_p H_p |u_p,bed|^2 dA, J
  bool at_rest() const { return max_speed() < kRestSpeed; }
  static constexpr double kRestSpeed = 1e-6;  // m/s, as fv2d

 private:
  // The six fields of a cell: each phase's depth and x, y momentum.
  enum Field { kHs, kXs, kYs, kHf, kXf, kYf, kFields };
  void update_earth_pressure();
  void rain_and_infiltrate(double dt);
  // c^2 / H of the fastest wave in cell c holding fluid_depth of fluid.
  double wave_coefficient(std::size_t c, double fluid_depth) const;
  void reconstruct(const TwoPhaseState& in);
  void side_depths(const TwoPhaseState& in);
  void face_fluxes(const TwoPhaseState& in);
  // Scales each phase's fluxes out of a cell down to what its depth holds.
  void limit_outflow(const TwoPhaseState& in, double dt);
  double euler_stage(const TwoPhaseState& in, TwoPhaseState& out, double dt, double* fluid_out);

  Terrain terrain_;
  TwoPhaseParams p_;
  TwoPhaseState s_, stage_, stage2_;
  double gamma_ = 0.0;
  std::vector<double> k_;            // earth-pressure coefficient per cell
  std::vector<double> g_solid_;      // the solid's pressure coefficient k (1 - gamma) g cos^4
  std::vector<double> g_bed_solid_;  // its effective weight's, (1 - gamma) g cos^2
  double k_active_ = 1.0, k_passive_ = 1.0;
  double outflow_s_ = 0.0, outflow_f_ = 0.0;
  double rained_ = 0.0, infiltrated_ = 0.0;
  // Per stage: primitive values, limited slopes (x, y) of H_s, H_f, the
  // surface and the four velocities, face fluxes with the hydrostatic
  // corrections of each side, the solid's held flags.
  std::vector<double> us_, vs_, uf_, vf_, eta_;
  std::vector<double> mixture_;  // H_s + H_f of the stage's input
  std::vector<double> sx_[7], sy_[7];
  std::vector<double> fx_[kFields], fy_[kFields];
  std::vector<double> cxl_, cxr_, cyl_, cyr_;  // the fluid's normal momentum
  std::vector<unsigned char> held_;
  std::vector<double> supply_[2];  // per phase: the share of its outflow a cell can supply
  DomainEdges domain_;
  // Per cell: the bed's central slopes; each axis' side depths (0: west /
  // south, 1: east / north) and the solid's share of them.
  std::vector<double> bed_slope_x_, bed_slope_y_;
  std::vector<double> depth_x_[2], depth_y_[2], share_x_[2], share_y_[2];
  // The fluid's kinematic viscosity per cell and its lateral stress's fluxes.
  std::vector<double> nu_;
  two_phase_detail::ViscousFluxes viscous_;
  bool lateral_viscosity() const {
    return p_.lateral_viscosity && p_.viscosity_alpha > 0.0 && p_.drag.fluid_density > 0.0;
  }
  void update_viscosity(const TwoPhaseState& in);  // nu_ of `in`'s solid fractions
};

}  // namespace talus::runout
