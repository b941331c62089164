#include "talus/runout/grid/fv2d.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>

#include "talus/core/error.hpp"
#include "talus/runout/grid/divergence.hpp"
#include "talus/runout/grid/limiter.hpp"

namespace talus::runout {
namespace {

using Index = std::ptrdiff_t;

// One side of a face, in the face's frame: u normal, v tangential, gp = k g cos^4.
struct FaceState {
  double h, u, v, gp;
};

// HLL flux (mass, normal momentum, tangential momentum) with Davis's wave
// speeds, and the exact dry-front speeds u -/+ 2c of a rarefaction into a dry
// bed (Toro 2001 §10.6) so that no mass is taken from a dry side.
inline void hll_flux(const FaceState& L, const FaceState& R, double dry, double f[3]) {
  const bool wet_l = L.h > dry, wet_r = R.h > dry;
  if (!wet_l && !wet_r) {
    f[0] = f[1] = f[2] = 0.0;
    return;
  }
  const double ul = wet_l ? L.u : 0.0, ur = wet_r ? R.u : 0.0;
  const double vl = wet_l ? L.v : 0.0, vr = wet_r ? R.v : 0.0;
  const double cl = wet_l ? std::sqrt(L.gp * L.h) : 0.0, cr = wet_r ? std::sqrt(R.gp * R.h) : 0.0;
  double sl, sr;
  if (!wet_r) {
    sl = ul - cl, sr = ul + 2.0 * cl;
  } else if (!wet_l) {
    sl = ur - 2.0 * cr, sr = ur + cr;
  } else {
    sl = std::min(ul - cl, ur - cr), sr = std::max(ul + cl, ur + cr);
  }
  const double ql = L.h * ul, qr = R.h * ur;
  const double fl[3] = {ql, ql * ul + 0.5 * L.gp * L.h * L.h, ql * vl};
  const double fr[3] = {qr, qr * ur + 0.5 * R.gp * R.h * R.h, qr * vr};
  if (sl >= 0.0) {
    f[0] = fl[0], f[1] = fl[1], f[2] = fl[2];
  } else if (sr <= 0.0) {
    f[0] = fr[0], f[1] = fr[1], f[2] = fr[2];
  } else {
    const double ul_[3] = {L.h, ql, L.h * vl}, ur_[3] = {R.h, qr, R.h * vr};
    const double inv = 1.0 / (sr - sl);
    for (int m = 0; m < 3; ++m)
      f[m] = (sr * fl[m] - sl * fr[m] + sl * sr * (ur_[m] - ul_[m])) * inv;
  }
}

// The ghost beyond an edge: a mirror (wall) or a copy (open, zero gradient).
inline FaceState ghost(const FaceState& inside, GridBoundary b) {
  return b == GridBoundary::Wall ? FaceState{inside.h, -inside.u, inside.v, inside.gp} : inside;
}

// The ranks of a solver that is not distributed.
const comm::Comm kOneRank;

}  // namespace

Fv2dSolver::Fv2dSolver(Terrain terrain, Fv2dParams params, std::vector<double> initial_depth)
    : terrain_(std::move(terrain)), p_(params), comm_(&kOneRank) {
  const std::size_t n = terrain_.shape().cells();
  if (initial_depth.size() != n)
    throw InputError(fmt::format("fv2d: {} initial depths for {} cells", initial_depth.size(), n));
  const auto& inside = terrain_.inside();
  for (std::size_t c = 0; c < n; ++c) {
    if (!(initial_depth[c] >= 0.0) || !std::isfinite(initial_depth[c]))
      throw InputError(fmt::format("fv2d: initial depth {} of cell {} must be finite and >= 0",
                                   initial_depth[c], c));
    if (!inside[c] && initial_depth[c] > 0.0)
      throw InputError(fmt::format(
          "fv2d: cell ({}, {}) is outside the domain (no elevation) but has a depth of {} m",
          c % terrain_.shape().nx, c / terrain_.shape().nx, initial_depth[c]));
  }
  if (p_.order != 1 && p_.order != 2) throw InputError("fv2d: order must be 1 or 2");
  if (p_.pressure.mode == EarthPressureMode::Hungr)
    throw InputError(
        "fv2d: the 'hungr' earth-pressure law needs block strains (1D only); use "
        "'savage_hutter' or 'constant'");
  if (!(p_.courant > 0.0 && p_.courant <= 0.5))
    throw InputError("fv2d: courant must be in (0, 0.5] (positivity of the MUSCL scheme)");
  s_.h = std::move(initial_depth);
  s_.hu.assign(n, 0.0), s_.hv.assign(n, 0.0);
  stage_ = s_, stage2_ = s_;
  g_press_.resize(n), g_bed_.resize(n);
  for (std::size_t c = 0; c < n; ++c) {
    const double c2 = terrain_.cos2()[c];
    g_bed_[c] = p_.gravity * c2;
    g_press_[c] = p_.gravity * c2 * c2;
  }
  const auto lim = earth_pressure_limits(p_.pressure.phi_internal, p_.pressure.tan_phi_basal);
  k_active_ = lim.active, k_passive_ = lim.passive;
  k_.assign(n, initial_earth_pressure(p_.pressure));
  // Both rheologies are a Coulomb part plus a part in speed^2; read the two
  // coefficients off basal_shear once so the cell loop needs no switch.
  coulomb_ = basal_shear(p_.rheology, 1.0, 0.0, 1.0, 1.0);
  turbulent_ = basal_shear(p_.rheology, 0.0, 1.0, 1.0, 1.0);
  u_.resize(n), v_.resize(n);
  for (auto* a : {&sh_x_, &su_x_, &sv_x_, &sh_y_, &su_y_, &sv_y_}) a->assign(n, 0.0);
  const auto& g = terrain_.shape();
  for (int m = 0; m < 3; ++m) fx_[m].resize((g.nx + 1) * g.ny), fy_[m].resize(g.nx * (g.ny + 1));
  quiet_.resize(n);
  find_domain_edges();
  blocks_ = {static_cast<int>(g.ny), 1};
  j0_ = 0, j1_ = static_cast<int>(g.ny);
}

void Fv2dSolver::distribute(const comm::Comm& comm) {
  const comm::RowBlocks blocks{static_cast<int>(terrain_.shape().ny), comm.size()};
  for (int r = 0; r < comm.size(); ++r)
    if (blocks.count(r) < kHaloRows)
      throw InputError(
          fmt::format("fv2d: {} grid rows cannot be shared among {} ranks (each needs at least {})",
                      blocks.rows, comm.size(), kHaloRows));
  comm_ = &comm;
  blocks_ = blocks;
  j0_ = blocks.first(comm.rank()), j1_ = blocks.first(comm.rank() + 1);
  complete_ = true;  // every rank built the same state
}

int Fv2dSolver::hi(int h) const {
  const int ny = static_cast<int>(terrain_.shape().ny);
  return j1_ + h < ny ? j1_ + h : ny;
}

void Fv2dSolver::exchange_halo(FlowState& s) {
  if (comm_->size() == 1) return;
  const std::size_t nx = terrain_.shape().nx, rows = kHaloRows * nx;
  const int r = comm_->rank(), up = r > 0 ? r - 1 : -1, down = r + 1 < comm_->size() ? r + 1 : -1;
  for (auto* a : {&s.h, &s.hu, &s.hv}) {
    double* q = a->data();
    // My first rows to the rank before me, its last rows into my rows after my block...
    comm_->shift(q + j0_ * nx, up, q + j1_ * nx, down, rows);
    // ...and my last rows to the rank after me, its first rows before my block.
    comm_->shift(q + (j1_ - kHaloRows) * nx, down, q + (j0_ - kHaloRows) * nx, up, rows);
  }
}

void Fv2dSolver::gather() {
  if (comm_->size() == 1 || complete_) return;
  std::vector<std::size_t> counts, offsets;
  blocks_.layout(terrain_.shape().nx, counts, offsets);
  for (auto* a : {&s_.h, &s_.hu, &s_.hv, &k_}) comm_->all_gather(a->data(), counts, offsets);
  complete_ = true;
}

double Fv2dSolver::rows_in_order(std::vector<double>& rows, bool gather) const {
  if (gather) {
    std::vector<std::size_t> counts, offsets;
    blocks_.layout(1, counts, offsets);
    comm_->all_gather(rows.data(), counts, offsets);
  }
  double sum = 0.0;
  for (double r : rows) sum += r;
  return sum;
}

template <class F>
double Fv2dSolver::row_ordered_sum(F f) const {
  const auto& g = terrain_.shape();
  const Index nx = static_cast<Index>(g.nx), first = read_begin(), end = read_end();
  row_sums_.assign(g.ny, 0.0);
#pragma omp parallel for schedule(static)
  for (Index j = first; j < end; ++j) {
    double sum = 0.0;
    for (Index c = j * nx; c < (j + 1) * nx; ++c) sum += f(c);
    row_sums_[j] = sum;
  }
  return rows_in_order(row_sums_, !complete_);
}

template <class F>
double Fv2dSolver::cell_max(F f) const {
  const Index nx = static_cast<Index>(terrain_.shape().nx);
  double m = 0.0;
  for (Index c = read_begin() * nx; c < read_end() * nx; ++c) m = std::max(m, f(c));
  return complete_ ? m : comm_->max(m);
}

void Fv2dSolver::find_domain_edges() {
  auto edges = runout::find_domain_edges(terrain_);
  interior_ = std::move(edges.interior);
  edge_faces_ = std::move(edges.faces);
}

void Fv2dSolver::set_state(const FlowState& state) {
  const std::size_t n = terrain_.shape().cells();
  if (state.h.size() != n || state.hu.size() != n || state.hv.size() != n)
    throw InputError(fmt::format("fv2d: a state needs {} depths and momenta", n));
  for (std::size_t c = 0; c < n; ++c)
    if (!(state.h[c] >= 0.0) || !std::isfinite(state.h[c]) || !std::isfinite(state.hu[c]) ||
        !std::isfinite(state.hv[c]))
      throw InputError(fmt::format("fv2d: cell {} of a state is negative or not finite", c));
  for (std::size_t c = 0; c < n; ++c)
    if (!terrain_.inside()[c] && (state.h[c] != 0.0 || state.hu[c] != 0.0 || state.hv[c] != 0.0))
      throw InputError(
          fmt::format("fv2d: cell {} of a state is outside the domain but not empty", c));
  s_ = state;
  complete_ = true;
}

void Fv2dSolver::restore(const FlowState& state, std::vector<double> k, double outflow) {
  if (k.size() != k_.size()) throw InputError("fv2d: the checkpoint's grid is not this scenario's");
  set_state(state);
  k_ = std::move(k);
  outflow_ = outflow;
}

double Fv2dSolver::normal_height(std::size_t c) const {
  return s_.h[c] * std::sqrt(terrain_.cos2()[c]);
}

double Fv2dSolver::speed(std::size_t c) const {
  if (s_.h[c] <= p_.dry_depth) return 0.0;
  const double u = s_.hu[c] / s_.h[c], v = s_.hv[c] / s_.h[c];
  const double w = u * terrain_.slope_x()[c] + v * terrain_.slope_y()[c];
  return std::sqrt(u * u + v * v + w * w);
}

double Fv2dSolver::volume() const {
  return row_ordered_sum([&](Index c) { return s_.h[c]; }) * terrain_.shape().cell_area();
}

double Fv2dSolver::momentum_x() const {
  return p_.density * row_ordered_sum([&](Index c) { return s_.hu[c]; }) *
         terrain_.shape().cell_area();
}

double Fv2dSolver::momentum_y() const {
  return p_.density * row_ordered_sum([&](Index c) { return s_.hv[c]; }) *
         terrain_.shape().cell_area();
}

double Fv2dSolver::kinetic_energy() const {
  const double sum = row_ordered_sum([&](Index c) {
    const double sp = speed(c);
    return s_.h[c] * sp * sp;
  });
  return 0.5 * p_.density * sum * terrain_.shape().cell_area();
}

double Fv2dSolver::momentum_sum() const {
  return p_.density * row_ordered_sum([&](Index c) { return s_.h[c] * speed(c); }) *
         terrain_.shape().cell_area();
}

double Fv2dSolver::max_speed() const {
  return cell_max([&](Index c) { return speed(c); });
}

double Fv2dSolver::max_height() const {
  return cell_max([&](Index c) { return normal_height(c); });
}

bool Fv2dSolver::at_rest() const { return max_speed() < kRestSpeed; }

double Fv2dSolver::stable_time_step() const {
  const auto& g = terrain_.shape();
  const Index nx = static_cast<Index>(g.nx);
  double rate = 0.0;
  bool wet = false;
  const Index first = read_begin() * nx, end = read_end() * nx;
#pragma omp parallel for schedule(static) reduction(max : rate) reduction(|| : wet)
  for (Index c = first; c < end; ++c) {
    const double h = s_.h[c];
    if (h <= p_.dry_depth) continue;
    wet = true;
    const double a = std::sqrt(k_[c] * g_press_[c] * h);
    const double u = s_.hu[c] / h, v = s_.hv[c] / h;
    rate = std::max(rate, (std::abs(u) + a) / g.dx + (std::abs(v) + a) / g.dy);
  }
  if (!complete_) rate = comm_->max(rate), wet = comm_->any(wet);
  if (rate == 0.0 && !wet) return std::numeric_limits<double>::infinity();
  // Gravity can set still material moving within a step even where no wave
  // speed limits it (k = 0, or everything at rest): it must not cross more
  // than `courant` of a cell in one step from rest, g dt^2 <= courant min(dx, dy).
  const double from_rest = std::sqrt(p_.courant * std::min(g.dx, g.dy) / p_.gravity);
  return rate > 0.0 ? std::min(p_.courant / rate, from_rest) : from_rest;
}

void Fv2dSolver::update_earth_pressure() {
  if (p_.pressure.mode == EarthPressureMode::Constant) return;
  const auto& g = terrain_.shape();
  const Index nx = static_cast<Index>(g.nx);
  auto vel = [&](const std::vector<double>& q, Index c) {
    return s_.h[c] > p_.dry_depth ? q[c] / s_.h[c] : 0.0;
  };
  // Two rows beside the block: the fluxes read them.
#pragma omp parallel for schedule(static)
  for (Index j = lo(2); j < hi(2); ++j) {
    for (Index i = 0; i < nx; ++i) {
      const Index c = j * nx + i;
      if (s_.h[c] <= p_.dry_depth) continue;
      const double div = velocity_divergence(
          terrain_, i, j, [&](Index k) { return vel(s_.hu, k); },
          [&](Index k) { return vel(s_.hv, k); });
      if (div > 0.0) k_[c] = k_active_;
      if (div < 0.0) k_[c] = k_passive_;
    }
  }
}

void Fv2dSolver::reconstruct(const FlowState& in) {
  const auto& g = terrain_.shape();
  const Index nx = static_cast<Index>(g.nx), ny = static_cast<Index>(g.ny);
  const double dry = p_.dry_depth;
  // Velocities on the three rows beside the block, slopes on two: the
  // fluxes the block's update and its neighbours' quiet flags read.
#pragma omp parallel for schedule(static)
  for (Index c = lo(3) * nx; c < hi(3) * nx; ++c) {
    const double h = in.h[c];
    u_[c] = h > dry ? in.hu[c] / h : 0.0;
    v_[c] = h > dry ? in.hv[c] / h : 0.0;
  }
  if (p_.order == 1) return;
    // Limited slopes per cell, in cell units, in branch-free runs along each row
    // (the compiler vectorises them); the slopes of cells on the grid's edge
    // stay 0 and those next to an outside cell are set to 0 afterwards.
#pragma omp parallel for schedule(static)
  for (Index j = lo(2); j < hi(2); ++j) {
    const Index row = j * nx;
    for (Index c = row + 1; c < row + nx - 1; ++c) {
      sh_x_[c] = limited_slope(in.h[c] - in.h[c - 1], in.h[c + 1] - in.h[c]);
      su_x_[c] = limited_slope(u_[c] - u_[c - 1], u_[c + 1] - u_[c]);
      sv_x_[c] = limited_slope(v_[c] - v_[c - 1], v_[c + 1] - v_[c]);
    }
    if (j == 0 || j == ny - 1) continue;
    for (Index c = row; c < row + nx; ++c) {
      sh_y_[c] = limited_slope(in.h[c] - in.h[c - nx], in.h[c + nx] - in.h[c]);
      su_y_[c] = limited_slope(u_[c] - u_[c - nx], u_[c + nx] - u_[c]);
      sv_y_[c] = limited_slope(v_[c] - v_[c - nx], v_[c + nx] - v_[c]);
    }
  }
  if (!terrain_.has_outside()) return;
#pragma omp parallel for schedule(static)
  for (Index c = lo(2) * nx; c < hi(2) * nx; ++c) {
    if (!(interior_[c] & 1)) sh_x_[c] = su_x_[c] = sv_x_[c] = 0.0;
    if (!(interior_[c] & 2)) sh_y_[c] = su_y_[c] = sv_y_[c] = 0.0;
  }
}

void Fv2dSolver::face_fluxes(const FlowState& in) {
  const auto& g = terrain_.shape();
  const Index nx = static_cast<Index>(g.nx), ny = static_cast<Index>(g.ny);
  const double dry = p_.dry_depth;
  const GridBoundary bc = p_.boundary;
  const auto& dom = terrain_.inside();
  // Faces normal to x: face f of row j lies between cells f - 1 and f. A side
  // beyond the grid or outside the domain is the ghost of the other side.
  // Rows one beyond the block: their quiet flags are read.
#pragma omp parallel for schedule(static)
  for (Index j = lo(1); j < hi(1); ++j) {
    for (Index f = 0; f <= nx; ++f) {
      const Index k = j * (nx + 1) + f;
      const bool has_l = f > 0 && dom[j * nx + f - 1], has_r = f < nx && dom[j * nx + f];
      if (!has_l && !has_r) {
        fx_[0][k] = fx_[1][k] = fx_[2][k] = 0.0;
        continue;
      }
      FaceState L{}, R{};
      if (has_l) {
        const Index c = j * nx + f - 1;
        L = {in.h[c] + 0.5 * sh_x_[c], u_[c] + 0.5 * su_x_[c], v_[c] + 0.5 * sv_x_[c],
             k_[c] * g_press_[c]};
      }
      if (has_r) {
        const Index c = j * nx + f;
        R = {in.h[c] - 0.5 * sh_x_[c], u_[c] - 0.5 * su_x_[c], v_[c] - 0.5 * sv_x_[c],
             k_[c] * g_press_[c]};
      }
      if (!has_l) L = ghost(R, bc);
      if (!has_r) R = ghost(L, bc);
      double flux[3];
      hll_flux(L, R, dry, flux);
      fx_[0][k] = flux[0], fx_[1][k] = flux[1], fx_[2][k] = flux[2];
    }
  }
  // Faces normal to y: face f of column i lies between rows f - 1 and f; the
  // normal velocity is v.
#pragma omp parallel for schedule(static)
  for (Index f = lo(1); f <= hi(1); ++f) {
    for (Index i = 0; i < nx; ++i) {
      const Index k = f * nx + i;
      const bool has_l = f > 0 && dom[(f - 1) * nx + i], has_r = f < ny && dom[f * nx + i];
      if (!has_l && !has_r) {
        fy_[0][k] = fy_[1][k] = fy_[2][k] = 0.0;
        continue;
      }
      FaceState L{}, R{};
      if (has_l) {
        const Index c = (f - 1) * nx + i;
        L = {in.h[c] + 0.5 * sh_y_[c], v_[c] + 0.5 * sv_y_[c], u_[c] + 0.5 * su_y_[c],
             k_[c] * g_press_[c]};
      }
      if (has_r) {
        const Index c = f * nx + i;
        R = {in.h[c] - 0.5 * sh_y_[c], v_[c] - 0.5 * sv_y_[c], u_[c] - 0.5 * su_y_[c],
             k_[c] * g_press_[c]};
      }
      if (!has_l) L = ghost(R, bc);
      if (!has_r) R = ghost(L, bc);
      double flux[3];
      hll_flux(L, R, dry, flux);
      fy_[0][k] = flux[0], fy_[1][k] = flux[2], fy_[2][k] = flux[1];
    }
  }
}

double Fv2dSolver::euler_stage(const FlowState& in, FlowState& out, double dt) {
  const auto& g = terrain_.shape();
  const Index nx = static_cast<Index>(g.nx), ny = static_cast<Index>(g.ny);
  const double dry = p_.dry_depth, rx = dt / g.dx, ry = dt / g.dy;
  const auto& bx = terrain_.slope_x();
  const auto& by = terrain_.slope_y();
  reconstruct(in);
  face_fluxes(in);
  // Pass 1: which cells friction holds at rest through this stage; the rows
  // beside the block too, as their flags close the block's faces.
#pragma omp parallel for schedule(static)
  for (Index j = lo(1); j < hi(1); ++j) {
    for (Index i = 0; i < nx; ++i) {
      const Index c = j * nx + i;
      const double h = in.h[c];
      if (h <= dry) {
        quiet_[c] = 1;
        continue;
      }
      if (in.hu[c] != 0.0 || in.hv[c] != 0.0) {
        quiet_[c] = 0;
        continue;
      }
      const Index w = j * (nx + 1) + i, s = j * nx + i;
      const double mx = -rx * (fx_[1][w + 1] - fx_[1][w]) - ry * (fy_[1][s + nx] - fy_[1][s]) -
                        dt * g_bed_[c] * h * bx[c];
      const double my = -rx * (fx_[2][w + 1] - fx_[2][w]) - ry * (fy_[2][s + nx] - fy_[2][s]) -
                        dt * g_bed_[c] * h * by[c];
      const double hold = dt * coulomb_ * g_bed_[c] * h;  // friction impulse at rest
      quiet_[c] = mx * mx + my * my <= hold * hold ? 1 : 0;
    }
  }
  // Pass 2: the update; no flux crosses a face between two quiet cells (the
  // ghost beyond an edge is as quiet as the cell inside; a cell outside the
  // domain holds nothing and is quiet). Cells outside stay empty.
  const auto& dom = terrain_.inside();
  const auto& hxx = terrain_.curvature_xx();
  const auto& hxy = terrain_.curvature_xy();
  const auto& hyy = terrain_.curvature_yy();
  bool finite = true;
#pragma omp parallel for schedule(static) reduction(&& : finite)
  for (Index j = j0_; j < j1_; ++j) {
    for (Index i = 0; i < nx; ++i) {
      const Index c = j * nx + i;
      if (!dom[c]) continue;
      const bool q = quiet_[c];
      const bool open_w = !(q && (i == 0 || quiet_[c - 1]));
      const bool open_e = !(q && (i == nx - 1 || quiet_[c + 1]));
      const bool open_s = !(q && (j == 0 || quiet_[c - nx]));
      const bool open_n = !(q && (j == ny - 1 || quiet_[c + nx]));
      const Index w = j * (nx + 1) + i, e = w + 1, s = c, n = c + nx;
      double d[3];
      for (int m = 0; m < 3; ++m)
        d[m] = -rx * ((open_e ? fx_[m][e] : 0.0) - (open_w ? fx_[m][w] : 0.0)) -
               ry * ((open_n ? fy_[m][n] : 0.0) - (open_s ? fy_[m][s] : 0.0));
      const double h0 = in.h[c], h = h0 + d[0];
      out.h[c] = h;
      if (!std::isfinite(h)) finite = false;
      if ((q && h0 > dry) || h <= dry) {  // held by friction, or dry
        out.hu[c] = out.hv[c] = 0.0;
        continue;
      }
      // The bed's reaction: its horizontal part is -sigma_n grad(b) with
      // sigma_n / rho = H cos^2 (g + U^T Hess(b) U). The centripetal part
      // turns the flow along a curved bed without changing its speed (without
      // it a concave slope break acts like a kink: horizontal momentum is
      // kept and sin^2 of the kinetic energy is lost going down, gained going
      // up). Evaluated with the stage's input velocity (explicit).
      const double u0 = h0 > dry ? in.hu[c] / h0 : 0.0, v0 = h0 > dry ? in.hv[c] / h0 : 0.0;
      const double turn0 =
          p_.curvature ? u0 * u0 * hxx[c] + 2.0 * u0 * v0 * hxy[c] + v0 * v0 * hyy[c] : 0.0;
      const double reaction = dt * h0 * terrain_.cos2()[c] * std::max(0.0, p_.gravity + turn0);
      double mx = in.hu[c] + d[1] - reaction * bx[c];
      double my = in.hv[c] + d[2] - reaction * by[c];
      // Basal friction: it stops a cell, never reverses it. Its normal stress
      // is of the stage's input depth h0, like the bed's reaction above: the
      // two are one force on the same mass. Taking the new depth for the
      // friction alone braked every cell the front had just wetted (h0 = 0:
      // no gravity, full friction) and held the front back (4 cm at 1 mm
      // depth in Mangeney's dam break on 2.5 mm cells; 0.5 cm now).
      const double u = mx / h, v = my / h, wz = u * bx[c] + v * by[c];
      const double centripetal =
          p_.curvature ? u * u * hxx[c] + 2.0 * u * v * hxy[c] + v * v * hyy[c] : 0.0;
      const double sigma = std::max(0.0, h0 * terrain_.cos2()[c] * (p_.gravity + centripetal));
      const double tau = coulomb_ * sigma + turbulent_ * p_.gravity * (u * u + v * v + wz * wz);
      const double impulse = dt * tau, m = std::sqrt(mx * mx + my * my);
      const double scale = m > impulse ? 1.0 - impulse / m : 0.0;
      out.hu[c] = mx * scale, out.hv[c] = my * scale;
      if (!std::isfinite(mx) || !std::isfinite(my)) finite = false;
    }
  }
  // Every rank stops when one finds a value that is not finite.
  if (!comm_->all(finite))
    throw RunError(fmt::format("fv2d: a depth or momentum is not finite at t = {:.6g} s", in.time));
  out.time = in.time + dt;
  // Volume through open edges of the domain (faces next to a quiet cell
  // carried nothing): per row in face order, then the rows in order (the
  // same bits on any team and any number of ranks).
  if (p_.boundary != GridBoundary::Open) return 0.0;
  row_outflow_.assign(g.ny, 0.0);
  for (const EdgeFace& f : edge_faces_) {
    const Index j = f.cell / nx;
    if (j >= j0_ && j < j1_ && !quiet_[f.cell])
      row_outflow_[j] += f.outward_length * (f.normal_x ? fx_[0][f.face] : fy_[0][f.face]);
  }
  return rows_in_order(row_outflow_, true) * dt;
}

void Fv2dSolver::step(double dt) {
  if (!(dt > 0.0)) throw RunError(fmt::format("fv2d: time step {} must be positive", dt));
  update_earth_pressure();
  const double o1 = euler_stage(s_, stage_, dt);
  exchange_halo(stage_);
  const double o2 = euler_stage(stage_, stage2_, dt);
  const Index nx = static_cast<Index>(terrain_.shape().nx);
#pragma omp parallel for schedule(static)
  for (Index c = j0_ * nx; c < j1_ * nx; ++c) {
    s_.h[c] = 0.5 * (s_.h[c] + stage2_.h[c]);
    s_.hu[c] = 0.5 * (s_.hu[c] + stage2_.hu[c]);
    s_.hv[c] = 0.5 * (s_.hv[c] + stage2_.hv[c]);
  }
  exchange_halo(s_);
  complete_ = comm_->size() == 1;
  s_.time += dt;
  outflow_ += 0.5 * (o1 + o2);
}

}  // namespace talus::runout
