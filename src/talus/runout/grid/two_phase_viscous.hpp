#pragma once
// The fluid's lateral viscous stress in the two-phase model (Pudasaini 2012,
// seed eqs. 50 and 66): per unit fluid mass
//   x: nu (2 u_xx + v_xy + u_yy),  y: nu (2 v_yy + u_xy + v_xx),
// nu = eta(alpha_s) / rho_f, the divergence of the depth-integrated stress
// nu H_f [[2 u_x, u_y + v_x], [u_y + v_x, 2 v_y]]. Written as fluxes through
// the faces, so that it moves momentum between cells and never creates it. A
// face carries it only between two cells that hold fluid (a dry neighbour is
// not a wall dragging the front back); the cross derivatives at a face are
// the mean of the two cells' central ones, taken with wet neighbours only.
// Explicit: the step obeys dt nu (4 / dx^2 + 4 / dy^2) <= courant
// (TwoPhaseSolver::stable_time_step).
#include <vector>

#include "talus/runout/grid/terrain.hpp"

namespace talus::runout::two_phase_detail {

struct ViscousFluxes {
  // [0]: x-momentum, [1]: y-momentum; x holds the x-faces ((nx + 1) ny, the
  // west face of cell (i, j) at j (nx + 1) + i), y the y-faces (nx (ny + 1)).
  std::vector<double> x[2], y[2];
  std::vector<double> du_dy, dv_dx;  // per cell, central, wet neighbours only
};

// hf: fluid depth, u, v: fluid velocity, nu: kinematic viscosity per cell
// (0 where dry); a cell holds fluid when hf > dry. open: the domain's edges
// are open (else walls).
void viscous_fluxes(const Terrain& terrain, const std::vector<double>& hf,
                    const std::vector<double>& u, const std::vector<double>& v,
                    const std::vector<double>& nu, double dry, bool open, ViscousFluxes& out);

}  // namespace talus::runout::two_phase_detail
