#pragma once
// 2D depth-averaged granular flow on a terrain grid (spec runout.md §2): the
// Savage-Hutter equations written over the horizontal plane, solved with a
// finite-volume HLL scheme (MUSCL reconstruction of h, u, v with the monotonised-central limiter;
// two-stage SSP Runge-Kutta; CFL time step).
//
// Unknowns per cell: H, the flow thickness measured vertically (volume per
// unit horizontal area), and the horizontal momentum (H u, H v). On a plane
// of inclination theta, transforming Savage & Hutter's bed-parallel equations
// (bed-normal depth h_n = H cos(theta), bed-parallel speed |u| / cos(theta))
// to horizontal coordinates gives exactly
//   dH/dt + div(H U) = 0
//   d(H U)/dt + div(H U U + 1/2 k g cos^4(theta) H^2 I)
//       = -g cos^2(theta) H grad(b) - tau / rho * U / |U|
// so a block slides with g (sin - cos tan(phi_b)) along the slope. On curved
// terrain cos(theta) comes from the local gradient and the basal normal
// stress gets the centripetal term: sigma_n = rho H cos^2 (g + U^T Hess(b) U)
// (the bed-normal acceleration of a particle moving with U on z = b(x, y)),
// both in the friction and in the bed's reaction -sigma_n grad(b) / rho that
// replaces -g cos^2 H grad(b) above (it turns the flow along a curved bed
// without changing its speed: a frictionless point mass keeps its energy).
// The friction magnitude is the rheology's bed stress (rheology.hpp) with the
// bed-parallel speed sqrt(|U|^2 + (U . grad b)^2).
//
// At rest, Coulomb friction is a reaction, not a force: a cell that starts a
// stage at rest stays there when the driving impulse of the stage (fluxes and
// gravity) is below what friction can hold, and no flux at all crosses a face
// between two cells that are each held or dry. That keeps a pile below the
// friction angle exactly at rest (HLL's numerical diffusion would otherwise
// creep mass downhill forever). Mass fluxes cancel pairwise between cells, so
// mass is conserved to round-off; outflow through open edges is counted.
//
// The domain: every cell of the grid, less those the terrain marks outside (a
// raster's no-data cells). Those hold nothing, and a face between a cell
// inside and one outside is an edge like the grid's own: a wall, or open
// (what crosses it leaves and is counted).
//
// Earth pressure k (earth_pressure.hpp): Constant, or Savage-Hutter's k_a
// where the flow spreads (div U > 0) and k_p where it converges, kept while
// div U = 0 (as the 1D model does at zero strain). Hungr's strain law is 1D
// (block strains) and is not offered here.
//
// On several ranks (distribute()) each steps a block of rows and exchanges
// three rows with each neighbour after every stage: a cell's update reads
// fluxes one row away, which read slopes two rows away, which read the state
// three rows away. Every pass runs over the rows its consumers read, so a
// rank computes the rows beside its block exactly as their owner does, and
// the results are the same bits on any number of ranks (and threads): sums
// are taken row by row and the rows then added in order.
#include <vector>

#include "talus/comm/comm.hpp"
#include "talus/comm/row_blocks.hpp"
#include "talus/runout/earth_pressure.hpp"
#include "talus/runout/grid/domain_edges.hpp"
#include "talus/runout/grid/terrain.hpp"
#include "talus/runout/rheology.hpp"

namespace talus::runout {

enum class GridBoundary { Wall, Open };

struct Fv2dParams {
  double density = 2000.0;  // kg/m^3
  double gravity = 9.81;    // m/s^2, acting in -z
  BasalRheology rheology;
  EarthPressure pressure{EarthPressureMode::SavageHutter};
  bool curvature = true;    // centripetal term in the basal normal stress
  int order = 2;            // 1: piecewise constant, 2: MUSCL (monotonised central)
  double courant = 0.45;    // dt (a_x / dx + a_y / dy) <= courant
  double dry_depth = 1e-6;  // m: thinner cells carry no velocity
  GridBoundary boundary = GridBoundary::Wall;
};

struct FlowState {
  std::vector<double> h, hu, hv;  // H, H u, H v per cell
  double time = 0.0;
};

class Fv2dSolver {
 public:
  // initial_depth: H per cell (>= 0, finite). Throws InputError for a size
  // mismatch, a negative depth, order not 1 or 2, or the Hungr pressure mode.
  Fv2dSolver(Terrain terrain, Fv2dParams params, std::vector<double> initial_depth);

  // Largest step allowed by the CFL condition (and by gravity starting still
  // material); infinity when every cell is dry.
  double stable_time_step() const;
  // One SSP-RK2 step. Throws RunError when a value is not finite.
  void step(double dt);

  // On several ranks, complete on this rank's rows and the three beside
  // them; gather() completes it.
  const FlowState& state() const { return s_; }

  // Spreads the rows over the ranks of `comm`, which must outlive the
  // solver. Every rank still holds the whole grid: the work is divided, the
  // memory not yet. Throws InputError when a rank would get fewer than
  // kHaloRows rows. From then on step and gather are collective (every rank
  // calls them, in the same order), and so are stable_time_step, the sums
  // and the maxima between a step and the next gather; while the state is
  // complete on every rank (before the first step, after gather) they are
  // computed on each rank alone, with the same bits.
  void distribute(const comm::Comm& comm);
  // Completes state() and the earth-pressure coefficients on every rank.
  void gather();
  const comm::Comm& ranks() const { return *comm_; }
  const comm::RowBlocks& blocks() const { return blocks_; }
  int first_row() const { return j0_; }
  int end_row() const { return j1_; }
  static constexpr int kHaloRows = 3;
  // Replaces depths, momenta and time (e.g. a moving start). Throws
  // InputError for a size mismatch or a negative or non-finite value.
  void set_state(const FlowState& state);
  // Continues from a checkpoint: the state, the earth-pressure coefficients
  // (kept where the flow neither spreads nor converges) and the outflow so
  // far. Throws InputError for sizes that are not this grid's.
  void restore(const FlowState& state, std::vector<double> k, double outflow);
  const Terrain& terrain() const { return terrain_; }
  const Fv2dParams& params() const { return p_; }
  const std::vector<double>& earth_pressure() const { return k_; }

  // Per cell: bed-normal flow height H cos(theta), bed-parallel speed.
  double normal_height(std::size_t c) const;
  double speed(std::size_t c) const;

  double volume() const;  // sum H dA (m^3)
  double mass() const { return p_.density * volume(); }
  double outflow_volume() const { return outflow_; }  // left through open edges
  double momentum_x() const;                          // rho sum H u dA
  double momentum_y() const;
  double kinetic_energy() const;  // 1/2 rho sum H |u_bed|^2 dA
  // rho sum H |u_bed| dA, the momentum sum of RAMMS' stop rule; the same bits
  // on any number of threads.
  double momentum_sum() const;
  double max_speed() const;
  double max_height() const;  // bed-normal
  bool at_rest() const;       // every cell slower than kRestSpeed
  static constexpr double kRestSpeed = 1e-6;

 private:
  void update_earth_pressure();
  // One forward-Euler stage from `in` into `out`; returns the volume that left
  // through open edges.
  double euler_stage(const FlowState& in, FlowState& out, double dt);
  void reconstruct(const FlowState& in);
  void face_fluxes(const FlowState& in);
  void find_domain_edges();
  // The three state rows on each side of this rank's block, from its neighbours.
  void exchange_halo(FlowState& s);
  // Rows [j0 - h, j1 + h) clipped to the grid.
  int lo(int h) const { return j0_ - h > 0 ? j0_ - h : 0; }
  int hi(int h) const;
  // The rows whose state this rank holds: all while it is complete, else its block.
  int read_begin() const { return complete_ ? 0 : j0_; }
  int read_end() const { return complete_ ? static_cast<int>(terrain_.shape().ny) : j1_; }
  // The sum of per-row partial sums in row order, once `gather` has brought
  // the other ranks' rows (each rank filled its own).
  double rows_in_order(std::vector<double>& rows, bool gather) const;
  // sum over cells of f(c), row by row, then the rows in order (all ranks).
  template <class F>
  double row_ordered_sum(F f) const;
  // max over cells of f(c) >= 0 (all ranks).
  template <class F>
  double cell_max(F f) const;

  Terrain terrain_;
  Fv2dParams p_;
  FlowState s_, stage_, stage2_;
  std::vector<double> k_;                // earth-pressure coefficient per cell
  std::vector<double> g_press_, g_bed_;  // g cos^4, g cos^2 per cell
  double k_active_ = 1.0, k_passive_ = 1.0;
  double coulomb_ = 0.0, turbulent_ = 0.0;  // tau = coulomb sigma + turbulent rho g |u|^2
  double outflow_ = 0.0;
  // Per-stage work arrays: reconstructed slopes, face fluxes, held flags.
  std::vector<double> u_, v_, sh_x_, su_x_, sv_x_, sh_y_, su_y_, sv_y_;
  std::vector<double> fx_[3], fy_[3];
  std::vector<unsigned char> quiet_;
  // Per cell: bit 1 set when both x-neighbours are in the domain, bit 2 both
  // y-neighbours (where a limited slope can be taken); the domain's edge faces.
  std::vector<unsigned char> interior_;
  std::vector<EdgeFace> edge_faces_;
  mutable std::vector<double> row_sums_;  // row_ordered_sum's, kept between steps
  std::vector<double> row_outflow_;       // a stage's outflow per row
  const comm::Comm* comm_;                // the ranks; one unless distributed
  comm::RowBlocks blocks_;
  int j0_ = 0, j1_ = 0;   // this rank's rows
  bool complete_ = true;  // the state is whole on this rank (no collective needed)
};

}  // namespace talus::runout
