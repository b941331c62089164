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
#include <vector>

#include "talus/runout/earth_pressure.hpp"
#include "talus/runout/path.hpp"
#include "talus/runout/rheology.hpp"
#include "talus/runout/smoothing.hpp"

namespace talus::runout {

struct DanParams {
  double density = 1630.0;  // bulk, kg/m^3
  double gravity = 9.81;    // m/s^2, acting in -y
  BasalRheology rheology;
  EarthPressure pressure;
  SmoothingParams smoothing;
  bool centripetal = true;  // the v^2 kappa term in the basal normal stress
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
  double max_speed() const;
  // Every block slower than kRestSpeed (held by friction).
  bool at_rest() const;
  static constexpr double kRestSpeed = 1e-6;  // m/s

 private:
  double width_between(std::size_t j) const;
  double pressure_gradient(std::size_t i, const std::vector<double>& h,
                           const std::vector<double>& H) const;

  RunoutPath path_;
  DanParams p_;
  DanBlocks b_;
  std::vector<double> mass_;  // boundary blocks' lumped masses, rho (V_{i-1} + V_i) / 2
  std::vector<double> h_, H_, v_new_, x_, s_old_, scratch_;
};

}  // namespace talus::runout
