#include "talus/runout/grid/two_phase.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>

#include "talus/core/error.hpp"
#include "talus/runout/grid/cell_sums.hpp"
#include "talus/runout/grid/divergence.hpp"
#include "talus/runout/grid/limiter.hpp"
#include "talus/runout/grid/two_phase_flux.hpp"
#include "talus/runout/grid/two_phase_sources.hpp"

namespace talus::runout {
namespace {

using Index = std::ptrdiff_t;
using two_phase_detail::apply_sources;
using two_phase_detail::Column;
using two_phase_detail::ColumnSources;
using two_phase_detail::face_flux;
using two_phase_detail::FaceFlux;
using two_phase_detail::ghost;
using two_phase_detail::kInf;
using two_phase_detail::norm2;
using two_phase_detail::Side;

// Which faces of cell (i, j) let solid through: none between two quiet
// cells (held by friction, or without solid; the ghost beyond an edge is as
// quiet as the cell inside). Order: west, east, south, north.
inline void solid_faces_open(const std::vector<unsigned char>& quiet, Index i, Index j, Index nx,
                             Index ny, bool open[4]) {
  const Index c = j * nx + i;
  const bool q = quiet[c] != 0;
  open[0] = !(q && (i == 0 || quiet[c - 1]));
  open[1] = !(q && (i == nx - 1 || quiet[c + 1]));
  open[2] = !(q && (j == 0 || quiet[c - nx]));
  open[3] = !(q && (j == ny - 1 || quiet[c + nx]));
}

// The fields reconstructed per cell, in the order of the slope arrays.
enum Slope { kSlopeHs, kSlopeHf, kSlopeSurface, kSlopeUs, kSlopeVs, kSlopeUf, kSlopeVf };

}  // namespace

TwoPhaseSolver::TwoPhaseSolver(Terrain terrain, TwoPhaseParams params,
                               std::vector<double> solid_depth, std::vector<double> fluid_depth)
    : terrain_(std::move(terrain)), p_(params) {
  const std::size_t n = terrain_.shape().cells();
  const auto& d = p_.drag;
  if (!(d.solid_density > 0.0) || !(d.fluid_density >= 0.0) || !(d.gravity > 0.0))
    throw InputError("two-phase: densities must be > 0 (fluid >= 0) and gravity > 0");
  if (d.exponent != 1 && d.exponent != 2)
    throw InputError("two-phase: the drag exponent J must be 1 (linear) or 2 (quadratic)");
  if (p_.order != 1 && p_.order != 2) throw InputError("two-phase: order must be 1 or 2");
  if (!(p_.courant > 0.0 && p_.courant <= 0.5))
    throw InputError("two-phase: courant must be in (0, 0.5] (positivity of the MUSCL scheme)");
  if (!(p_.rainfall >= 0.0) || !(p_.infiltration >= 0.0))
    throw InputError("two-phase: rainfall and infiltration rates must be >= 0 (m/s)");
  for (const auto* map : {&p_.rainfall_map, &p_.infiltration_map}) {
    if (!map->empty() && map->size() != n)
      throw InputError(fmt::format("two-phase: a rate map needs {} values", n));
    for (double r : *map)
      if (!(r >= 0.0 && std::isfinite(r)))
        throw InputError("two-phase: rainfall and infiltration rates must be >= 0 (m/s)");
  }
  if (p_.pressure.mode == EarthPressureMode::Hungr)
    throw InputError("two-phase: the 'hungr' earth-pressure law needs block strains (1D only)");
  TwoPhaseState s;
  s.hs = std::move(solid_depth), s.hf = std::move(fluid_depth);
  s.hsu.assign(n, 0.0), s.hsv.assign(n, 0.0), s.hfu.assign(n, 0.0), s.hfv.assign(n, 0.0);
  gamma_ = d.fluid_density / d.solid_density;
  const auto lim = earth_pressure_limits(p_.pressure.phi_internal, p_.pressure.tan_phi_basal);
  k_active_ = lim.active, k_passive_ = lim.passive;
  k_.assign(n, initial_earth_pressure(p_.pressure));
  g_solid_.resize(n), g_bed_solid_.resize(n);
  set_state(s);
  stage_ = s_, stage2_ = s_;
  for (auto* a : {&us_, &vs_, &uf_, &vf_, &eta_, &mixture_}) a->assign(n, 0.0);
  for (int k = 0; k < 7; ++k) sx_[k].assign(n, 0.0), sy_[k].assign(n, 0.0);
  const auto& g = terrain_.shape();
  const std::size_t nfx = (g.nx + 1) * g.ny, nfy = g.nx * (g.ny + 1);
  for (int m = 0; m < kFields; ++m) fx_[m].assign(nfx, 0.0), fy_[m].assign(nfy, 0.0);
  cxl_.assign(nfx, 0.0), cxr_.assign(nfx, 0.0), cyl_.assign(nfy, 0.0), cyr_.assign(nfy, 0.0);
  held_.assign(n, 0);
  nu_.assign(n, 0.0);
  supply_[0].assign(n, 1.0), supply_[1].assign(n, 1.0);
  domain_ = find_domain_edges(terrain_);
  for (int k = 0; k < 2; ++k)
    depth_x_[k].assign(n, 0.0), depth_y_[k].assign(n, 0.0), share_x_[k].assign(n, 0.0),
        share_y_[k].assign(n, 0.0);
  // The bed's central slopes (per cell, in cell units) where the limited
  // slopes are taken; 0 where they are not.
  bed_slope_x_.assign(n, 0.0), bed_slope_y_.assign(n, 0.0);
  const auto& b = terrain_.elevation();
  for (std::size_t c = 0; c < n; ++c) {
    if (domain_.interior[c] & 1) bed_slope_x_[c] = 0.5 * (b[c + 1] - b[c - 1]);
    if (domain_.interior[c] & 2) bed_slope_y_[c] = 0.5 * (b[c + g.nx] - b[c - g.nx]);
  }
  update_earth_pressure();
}

void TwoPhaseSolver::set_state(const TwoPhaseState& state) {
  const std::size_t n = terrain_.shape().cells();
  for (const auto* a : {&state.hs, &state.hsu, &state.hsv, &state.hf, &state.hfu, &state.hfv})
    if (a->size() != n)
      throw InputError(fmt::format("two-phase: a state needs {} values per field", n));
  const auto& inside = terrain_.inside();
  for (std::size_t c = 0; c < n; ++c) {
    const double v[6] = {state.hs[c], state.hsu[c], state.hsv[c],
                         state.hf[c], state.hfu[c], state.hfv[c]};
    for (double x : v)
      if (!std::isfinite(x))
        throw InputError(fmt::format("two-phase: a value of cell {} is not finite", c));
    if (!(state.hs[c] >= 0.0) || !(state.hf[c] >= 0.0))
      throw InputError(fmt::format("two-phase: cell {} has a negative depth", c));
    if (!inside[c] && std::any_of(v, v + 6, [](double x) { return x != 0.0; }))
      throw InputError(
          fmt::format("two-phase: cell ({}, {}) is outside the domain (no elevation) but not empty",
                      c % terrain_.shape().nx, c / terrain_.shape().nx));
  }
  s_ = state;
}

void TwoPhaseSolver::restore(const TwoPhaseState& state, std::vector<double> k,
                             const TwoPhaseTotals& totals) {
  if (k.size() != terrain_.shape().cells())
    throw InputError("two-phase: the earth-pressure coefficients are not this grid's");
  set_state(state);
  k_ = std::move(k);
  outflow_s_ = totals.solid_outflow, outflow_f_ = totals.fluid_outflow;
  rained_ = totals.rained, infiltrated_ = totals.infiltrated;
  update_earth_pressure();
}

double TwoPhaseSolver::normal_height(std::size_t c, Phase phase) const {
  const double h = phase == Phase::Solid ? s_.hs[c] : s_.hf[c];
  return h * std::sqrt(terrain_.cos2()[c]);
}

double TwoPhaseSolver::speed(std::size_t c, Phase phase) const {
  const bool solid = phase == Phase::Solid;
  const double h = solid ? s_.hs[c] : s_.hf[c];
  if (h <= p_.dry_depth) return 0.0;
  const double u = (solid ? s_.hsu[c] : s_.hfu[c]) / h, v = (solid ? s_.hsv[c] : s_.hfv[c]) / h;
  // The bed-normal component the terrain's slope adds, as fv2d.
  const double w = u * terrain_.slope_x()[c] + v * terrain_.slope_y()[c];
  return std::sqrt(u * u + v * v + w * w);
}

double TwoPhaseSolver::kinetic_energy() const {
  double solid = 0.0, fluid = 0.0;
  for (std::size_t c = 0; c < s_.hs.size(); ++c) {
    const double vs = speed(c, Phase::Solid), vf = speed(c, Phase::Fluid);
    solid += s_.hs[c] * vs * vs, fluid += s_.hf[c] * vf * vf;
  }
  const auto& d = p_.drag;
  return 0.5 * (d.solid_density * solid + d.fluid_density * fluid) * terrain_.shape().cell_area();
}

double TwoPhaseSolver::solid_volume() const {
  return cell_sum(s_.hs) * terrain_.shape().cell_area();
}

double TwoPhaseSolver::fluid_volume() const {
  return cell_sum(s_.hf) * terrain_.shape().cell_area();
}

double TwoPhaseSolver::momentum_x() const {
  const auto& d = p_.drag;
  return (d.solid_density * cell_sum(s_.hsu) + d.fluid_density * cell_sum(s_.hfu)) *
         terrain_.shape().cell_area();
}

double TwoPhaseSolver::momentum_y() const {
  const auto& d = p_.drag;
  return (d.solid_density * cell_sum(s_.hsv) + d.fluid_density * cell_sum(s_.hfv)) *
         terrain_.shape().cell_area();
}

double TwoPhaseSolver::max_speed() const {
  double m = 0.0;
  const double dry = p_.dry_depth;
  for (std::size_t c = 0; c < s_.hs.size(); ++c) {
    if (s_.hs[c] > dry) m = std::max(m, norm2(s_.hsu[c], s_.hsv[c]) / s_.hs[c]);
    if (s_.hf[c] > dry) m = std::max(m, norm2(s_.hfu[c], s_.hfv[c]) / s_.hf[c]);
  }
  return m;
}

double TwoPhaseSolver::wave_coefficient(std::size_t c, double fluid_depth) const {
  // The solid's pressure and buoyancy, and the fluid's pressure where there is fluid.
  const double solid = g_solid_[c] + gamma_ * p_.drag.gravity;
  return fluid_depth > p_.dry_depth ? std::max(p_.drag.gravity, solid) : solid;
}

double TwoPhaseSolver::stable_time_step() const {
  const auto& g = terrain_.shape();
  const Index n = static_cast<Index>(g.cells());
  const double dry = p_.dry_depth, grav = p_.drag.gravity;
  double rate = 0.0;
  // The largest solid fraction under fluid: Julien-O'Brien's viscosity
  // alpha e^(beta alpha_s) (alpha > 0, beta >= 0) is largest there, so one
  // exp gives the same bits as the largest of every cell's.
  double solid_max = -1.0;
  bool wet = false;
#pragma omp parallel for schedule(static) reduction(max : rate, solid_max) reduction(|| : wet)
  for (Index c = 0; c < n; ++c) {
    const double hs = s_.hs[c], hf = s_.hf[c];
    if (hs + hf <= dry) continue;
    wet = true;
    const double a = std::sqrt(wave_coefficient(c, hf) * (hs + hf));
    if (hs > dry)
      rate = std::max(
          rate, (std::abs(s_.hsu[c] / hs) + a) / g.dx + (std::abs(s_.hsv[c] / hs) + a) / g.dy);
    if (hf > dry) {
      rate = std::max(
          rate, (std::abs(s_.hfu[c] / hf) + a) / g.dx + (std::abs(s_.hfv[c] / hf) + a) / g.dy);
      solid_max = std::max(solid_max, hs / (hs + hf));
    }
  }
  if (!wet) return kInf;
  // As fv2d: still material set moving by gravity crosses at most `courant` of a cell.
  const double from_rest = std::sqrt(p_.courant * std::min(g.dx, g.dy) / grav);
  double dt = rate > 0.0 ? std::min(p_.courant / rate, from_rest) : from_rest;
  if (lateral_viscosity() && solid_max >= 0.0) {  // the explicit lateral stress
    const double nu_max =
        two_phase::julien_obrien_viscosity(p_.viscosity_alpha, p_.viscosity_beta, solid_max) /
        p_.drag.fluid_density;
    const double viscous = nu_max * (4.0 / (g.dx * g.dx) + 4.0 / (g.dy * g.dy));
    if (viscous > 0.0) dt = std::min(dt, p_.courant / viscous);
  }
  return dt;
}

void TwoPhaseSolver::update_viscosity(const TwoPhaseState& in) {
  const Index n = static_cast<Index>(in.hf.size());
  const double dry = p_.dry_depth, rho_f = p_.drag.fluid_density;
#pragma omp parallel for schedule(static)
  for (Index c = 0; c < n; ++c) {
    const double hf = in.hf[c], h = in.hs[c] + hf;
    nu_[c] = hf > dry ? two_phase::julien_obrien_viscosity(p_.viscosity_alpha, p_.viscosity_beta,
                                                           in.hs[c] / h) /
                            rho_f
                      : 0.0;
  }
}

void TwoPhaseSolver::update_earth_pressure() {
  const auto& g = terrain_.shape();
  const Index nx = static_cast<Index>(g.nx), ny = static_cast<Index>(g.ny);
  const auto& dom = terrain_.inside();
  const double dry = p_.dry_depth, grav = p_.drag.gravity, gam = gamma_;
  auto vel = [&](const std::vector<double>& q, Index c) {
    return s_.hs[c] > dry ? q[c] / s_.hs[c] : 0.0;
  };
#pragma omp parallel for schedule(static)
  for (Index j = 0; j < ny; ++j) {
    for (Index i = 0; i < nx; ++i) {
      const Index c = j * nx + i;
      // The solid's earth pressure follows the divergence of its velocity (fv2d's rule).
      if (p_.pressure.mode != EarthPressureMode::Constant && s_.hs[c] > dry) {
        const double div = velocity_divergence(
            terrain_, i, j, [&](Index k) { return vel(s_.hsu, k); },
            [&](Index k) { return vel(s_.hsv, k); });
        if (div > 0.0) k_[c] = k_active_;
        if (div < 0.0) k_[c] = k_passive_;
      }
      const double c2 = dom[c] ? terrain_.cos2()[c] : 1.0;
      g_solid_[c] = k_[c] * (1.0 - gam) * grav * c2 * c2;
      g_bed_solid_[c] = (1.0 - gam) * grav * c2;
    }
  }
}

void TwoPhaseSolver::reconstruct(const TwoPhaseState& in) {
  const auto& g = terrain_.shape();
  const Index nx = static_cast<Index>(g.nx), ny = static_cast<Index>(g.ny);
  const double dry = p_.dry_depth;
  const auto& b = terrain_.elevation();
  const auto& dom = terrain_.inside();
#pragma omp parallel for schedule(static)
  for (Index c = 0; c < nx * ny; ++c) {
    const double hs = in.hs[c], hf = in.hf[c];
    us_[c] = hs > dry ? in.hsu[c] / hs : 0.0, vs_[c] = hs > dry ? in.hsv[c] / hs : 0.0;
    uf_[c] = hf > dry ? in.hfu[c] / hf : 0.0, vf_[c] = hf > dry ? in.hfv[c] / hf : 0.0;
    eta_[c] = dom[c] ? b[c] + hs + hf : 0.0;
    mixture_[c] = hs + hf;
  }
  if (p_.order == 1) {  // no slopes: the sides are the cell's values
    side_depths(in);
    return;
  }
  const std::vector<double>* field[7] = {&in.hs, &in.hf, &eta_, &us_, &vs_, &uf_, &vf_};
#pragma omp parallel for schedule(static)
  for (Index j = 0; j < ny; ++j) {
    const Index row = j * nx;
    for (int k = 0; k < 7; ++k) {
      const auto& q = *field[k];
      auto& sx = sx_[k];
      auto& sy = sy_[k];
      for (Index c = row + 1; c < row + nx - 1; ++c)
        sx[c] = limited_slope(q[c] - q[c - 1], q[c + 1] - q[c]);
      if (j == 0 || j == ny - 1) continue;
      for (Index c = row; c < row + nx; ++c)
        sy[c] = limited_slope(q[c] - q[c - nx], q[c + nx] - q[c]);
    }
  }
  if (terrain_.has_outside()) {
#pragma omp parallel for schedule(static)
    for (Index c = 0; c < nx * ny; ++c)
      for (int k = 0; k < 7; ++k) {
        if (!(domain_.interior[c] & 1)) sx_[k][c] = 0.0;
        if (!(domain_.interior[c] & 2)) sy_[k][c] = 0.0;
      }
  }
  side_depths(in);
}

void TwoPhaseSolver::side_depths(const TwoPhaseState& in) {
  const Index n = static_cast<Index>(terrain_.shape().cells());
  const bool second = p_.order == 2;
  // The mixture's depth at a cell's two sides along an axis: its surface
  // slope less the bed's central slope (so the bed at a face is nearly the
  // same seen from either side: exact for beds quadratic over three cells;
  // with the depth's own limited slope a thin layer on curved steep ground
  // met a step at a face deeper than itself and stuck). Where a side would
  // be negative it is 0 and the other twice the cell's (Kurganov & Petrova
  // 2007: the cell's mean kept). The phases share a side's depth as their
  // own limited reconstructions do.
  auto sides = [&](Index c, const std::vector<double>* s, const std::vector<double>& bed_slope,
                   std::vector<double>* depth, std::vector<double>* share) {
    const double hs = in.hs[c], hf = in.hf[c], h = hs + hf;
    const double half = second ? 0.5 * (s[kSlopeSurface][c] - bed_slope[c]) : 0.0;
    double minus = h - half, plus = h + half;
    if (!(h > 0.0)) {
      minus = plus = 0.0;
    } else if (plus < 0.0) {
      plus = 0.0, minus = 2.0 * h;
    } else if (minus < 0.0) {
      minus = 0.0, plus = 2.0 * h;
    }
    depth[0][c] = minus, depth[1][c] = plus;
    for (int k = 0; k < 2; ++k) {
      const double sign = k == 0 ? -1.0 : 1.0;
      const double hs_rec = second ? hs + 0.5 * sign * s[kSlopeHs][c] : hs;
      const double hf_rec = second ? hf + 0.5 * sign * s[kSlopeHf][c] : hf;
      share[k][c] = hs_rec + hf_rec > 0.0 ? hs_rec / (hs_rec + hf_rec) : (h > 0.0 ? hs / h : 0.0);
    }
  };
#pragma omp parallel for schedule(static)
  for (Index c = 0; c < n; ++c) {
    sides(c, sx_, bed_slope_x_, depth_x_, share_x_);
    sides(c, sy_, bed_slope_y_, depth_y_, share_y_);
  }
}

void TwoPhaseSolver::face_fluxes(const TwoPhaseState& in) {
  const auto& g = terrain_.shape();
  const Index nx = static_cast<Index>(g.nx), ny = static_cast<Index>(g.ny);
  const double dry = p_.dry_depth, grav = p_.drag.gravity;
  const GridBoundary bc = p_.boundary;
  const auto& dom = terrain_.inside();
  // A cell's side at a face (k = 1: its east / north side, 0: west /
  // south) in the face's frame (the normal velocity is v on a face normal to
  // y): depths from side_depths, the bed where the reconstructed surface
  // puts it, velocities along their limited slopes.
  auto side = [&](Index c, int k, const std::vector<double>* s, bool normal_y) {
    const double sign = k == 1 ? 1.0 : -1.0;
    const double depth = normal_y ? depth_y_[k][c] : depth_x_[k][c];
    const double hs = in.hs[c] + 0.5 * sign * s[kSlopeHs][c];  // limited, as fv2d
    const double hf = depth * (1.0 - (normal_y ? share_y_[k][c] : share_x_[k][c]));
    const double surface = eta_[c] + 0.5 * sign * s[kSlopeSurface][c];
    const double us = us_[c] + 0.5 * sign * s[kSlopeUs][c],
                 vs = vs_[c] + 0.5 * sign * s[kSlopeVs][c];
    const double uf = uf_[c] + 0.5 * sign * s[kSlopeUf][c],
                 vf = vf_[c] + 0.5 * sign * s[kSlopeVf][c];
    const double gw = wave_coefficient(c, in.hf[c]);
    return normal_y ? Side{hs, vs, us, hf, vf, uf, depth, surface - depth, g_solid_[c], gw}
                    : Side{hs, us, vs, hf, uf, vf, depth, surface - depth, g_solid_[c], gw};
  };
#pragma omp parallel for schedule(static)
  for (Index j = 0; j < ny; ++j) {
    for (Index f = 0; f <= nx; ++f) {
      const Index k = j * (nx + 1) + f;
      const bool has_l = f > 0 && dom[j * nx + f - 1], has_r = f < nx && dom[j * nx + f];
      FaceFlux flux;
      // Between two empty cells (or an empty one and the edge) nothing moves:
      // an empty cell's sides are empty too (its limited slopes are 0).
      const bool empty =
          (!has_l || mixture_[j * nx + f - 1] == 0.0) && (!has_r || mixture_[j * nx + f] == 0.0);
      if ((has_l || has_r) && !empty) {
        Side L{}, R{};
        if (has_l) L = side(j * nx + f - 1, 1, sx_, false);
        if (has_r) R = side(j * nx + f, 0, sx_, false);
        if (!has_l) L = ghost(R, bc);
        if (!has_r) R = ghost(L, bc);
        flux = face_flux(L, R, grav, dry);
      }
      for (int m = 0; m < kFields; ++m) fx_[m][k] = flux.f[m];
      cxl_[k] = flux.left, cxr_[k] = flux.right;
    }
  }
#pragma omp parallel for schedule(static)
  for (Index f = 0; f <= ny; ++f) {
    for (Index i = 0; i < nx; ++i) {
      const Index k = f * nx + i;
      const bool has_l = f > 0 && dom[(f - 1) * nx + i], has_r = f < ny && dom[f * nx + i];
      FaceFlux flux;
      const bool empty =
          (!has_l || mixture_[(f - 1) * nx + i] == 0.0) && (!has_r || mixture_[f * nx + i] == 0.0);
      if ((has_l || has_r) && !empty) {
        Side L{}, R{};
        if (has_l) L = side((f - 1) * nx + i, 1, sy_, true);
        if (has_r) R = side(f * nx + i, 0, sy_, true);
        if (!has_l) L = ghost(R, bc);
        if (!has_r) R = ghost(L, bc);
        flux = face_flux(L, R, grav, dry);
      }
      // Back to x, y components: the face frame's normal momentum is y's.
      const int to_xy[kFields] = {kHs, kYs, kXs, kHf, kYf, kXf};
      for (int m = 0; m < kFields; ++m) fy_[to_xy[m]][k] = flux.f[m];
      cyl_[k] = flux.left, cyr_[k] = flux.right;
    }
  }
}

void TwoPhaseSolver::limit_outflow(const TwoPhaseState& in, double dt) {
  const auto& g = terrain_.shape();
  const Index nx = static_cast<Index>(g.nx), ny = static_cast<Index>(g.ny);
  const double rx = dt / g.dx, ry = dt / g.dy;
  const auto& dom = terrain_.inside();
  // Per cell and phase: the share of what leaves through its faces that its
  // depth can supply (1 where it can supply all). No solid leaves through a
  // face between two quiet cells (the update skips those faces).
#pragma omp parallel for schedule(static)
  for (Index j = 0; j < ny; ++j) {
    for (Index i = 0; i < nx; ++i) {
      const Index c = j * nx + i, w = j * (nx + 1) + i, e = w + 1, s = c, n = c + nx;
      if (!dom[c]) continue;
      bool open[4];
      solid_faces_open(held_, i, j, nx, ny, open);
      for (int phase = 0; phase < 2; ++phase) {
        const int m = phase == 0 ? kHs : kHf;
        const bool solid = phase == 0;
        const double leaving = rx * ((!solid || open[1] ? std::max(0.0, fx_[m][e]) : 0.0) +
                                     (!solid || open[0] ? std::max(0.0, -fx_[m][w]) : 0.0)) +
                               ry * ((!solid || open[3] ? std::max(0.0, fy_[m][n]) : 0.0) +
                                     (!solid || open[2] ? std::max(0.0, -fy_[m][s]) : 0.0));
        // (A depth may be a round-off below 0 after an emptying: it supplies nothing.)
        const double depth = std::max(0.0, solid ? in.hs[c] : in.hf[c]);
        supply_[phase][c] = leaving > depth ? depth / leaving : 1.0;
      }
    }
  }
  // Each face's fluxes of a phase scaled by the share of the cell they leave.
  auto scale = [&](std::vector<double>* f, Index k, Index left, Index right, bool has_l,
                   bool has_r) {
    for (int phase = 0; phase < 2; ++phase) {
      const int m = phase == 0 ? kHs : kHf;
      const Index from = f[m][k] > 0.0 ? (has_l ? left : right) : (has_r ? right : left);
      const double share = supply_[phase][from];
      if (share < 1.0)
        for (int q = m; q < m + 3; ++q) f[q][k] *= share;
    }
  };
#pragma omp parallel for schedule(static)
  for (Index j = 0; j < ny; ++j)
    for (Index f = 0; f <= nx; ++f) {
      const bool has_l = f > 0 && dom[j * nx + f - 1], has_r = f < nx && dom[j * nx + f];
      if (has_l || has_r) scale(fx_, j * (nx + 1) + f, j * nx + f - 1, j * nx + f, has_l, has_r);
    }
#pragma omp parallel for schedule(static)
  for (Index f = 0; f <= ny; ++f)
    for (Index i = 0; i < nx; ++i) {
      const bool has_l = f > 0 && dom[(f - 1) * nx + i], has_r = f < ny && dom[f * nx + i];
      if (has_l || has_r) scale(fy_, f * nx + i, (f - 1) * nx + i, f * nx + i, has_l, has_r);
    }
}

double TwoPhaseSolver::euler_stage(const TwoPhaseState& in, TwoPhaseState& out, double dt,
                                   double* fluid_out) {
  const auto& g = terrain_.shape();
  const Index nx = static_cast<Index>(g.nx), ny = static_cast<Index>(g.ny);
  const double dry = p_.dry_depth, rx = dt / g.dx, ry = dt / g.dy;
  const double grav = p_.drag.gravity, gam = gamma_;
  const double rho_s = p_.drag.solid_density, rho_f = p_.drag.fluid_density;
  const auto& bx = terrain_.slope_x();
  const auto& by = terrain_.slope_y();
  const auto& dom = terrain_.inside();
  const auto& cos2 = terrain_.cos2();
  const auto& hxx = terrain_.curvature_xx();
  const auto& hxy = terrain_.curvature_xy();
  const auto& hyy = terrain_.curvature_yy();
  // The bed's curvature along a velocity (u, v): u^T Hess(b) u; 0 without
  // the centripetal term.
  auto turning = [&](Index c, double u, double v) {
    return p_.curvature ? u * u * hxx[c] + 2.0 * u * v * hxy[c] + v * v * hyy[c] : 0.0;
  };
  reconstruct(in);
  face_fluxes(in);
  if (lateral_viscosity()) {
    update_viscosity(in);
    two_phase_detail::viscous_fluxes(terrain_, in.hf, uf_, vf_, nu_, dry,
                                     p_.boundary == GridBoundary::Open, viscous_);
  }
  // The explicit change of a cell's six fields over the stage: what its faces
  // carry (fluxes, the solid's only through faces `open`: west, east, south,
  // north; the fluid's hydrostatic corrections), then the local terms (the
  // fluid's interior bed term, the solid's weight on the bed, buoyancy and
  // the phases' coupling). carried: when given, receives the faces' part.
  auto explicit_change = [&](Index c, Index i, Index j, const bool open[4], double d[kFields],
                             double* carried = nullptr) {
    const Index w = j * (nx + 1) + i, e = w + 1, s = c, n = c + nx;
    for (int m = 0; m < kFields; ++m) {
      const bool solid = m < kHf;
      const double ow = !solid || open[0], oe = !solid || open[1];
      const double os = !solid || open[2], on = !solid || open[3];
      d[m] = -rx * (oe * fx_[m][e] - ow * fx_[m][w]) - ry * (on * fy_[m][n] - os * fy_[m][s]);
    }
    d[kXf] -= rx * (cxl_[e] - cxr_[w]);
    d[kYf] -= ry * (cyl_[n] - cyr_[s]);
    if (lateral_viscosity()) {
      const auto& v = viscous_;
      d[kXf] += rx * (v.x[0][e] - v.x[0][w]) + ry * (v.y[0][n] - v.y[0][s]);
      d[kYf] += rx * (v.x[1][e] - v.x[1][w]) + ry * (v.y[1][n] - v.y[1][s]);
    }
    if (carried) std::copy(d, d + kFields, carried);
    const double hs = in.hs[c], hf = in.hf[c];
    // The fluid's bed: -g (H_f,w + H_f,e) / 2 (b_e - b_w) / dx with the
    // sides' beds; over a flat surface it balances the pressure of the
    // fluxes and corrections exactly (Audusse et al.'s second-order interior
    // term). The solid's effective weight on the bed, as fv2d, with the
    // terrain's slope.
    {
      const double hx[2] = {depth_x_[0][c], depth_x_[1][c]},
                   hy[2] = {depth_y_[0][c], depth_y_[1][c]};
      const double dbx = sx_[kSlopeSurface][c] - (hx[1] - hx[0]);
      const double dby = sy_[kSlopeSurface][c] - (hy[1] - hy[0]);
      const double fx = 0.5 * (hx[0] * (1.0 - share_x_[0][c]) + hx[1] * (1.0 - share_x_[1][c]));
      const double fy = 0.5 * (hy[0] * (1.0 - share_y_[0][c]) + hy[1] * (1.0 - share_y_[1][c]));
      d[kXf] -= rx * grav * fx * dbx, d[kYf] -= ry * grav * fy * dby;
    }
    // With fv2d's centripetal part: the bed turns the moving solid along its
    // curvature (u^T Hess(b) u, at the stage's input velocity, explicit).
    const double reaction =
        dt * hs * std::max(0.0, g_bed_solid_[c] + cos2[c] * turning(c, us_[c], vs_[c]));
    d[kXs] -= reaction * bx[c];
    d[kYs] -= reaction * by[c];
    // The phases push each other through the fluid's pressure: the fluid
    // by the gradient of the solid's depth (its flux has its own depth
    // only), the solid by buoyancy, gamma g grad(H + b). Centred; a
    // neighbour outside the domain counts as this cell.
    auto gradient = [&](const std::vector<double>& q, double step, bool has_lo, Index lo,
                        bool has_hi, Index hi) {
      const double at_lo = has_lo && dom[lo] ? q[lo] : q[c],
                   at_hi = has_hi && dom[hi] ? q[hi] : q[c];
      return 0.5 * (at_hi - at_lo) / step;
    };
    if (hs > 0.0) {
      d[kXs] -= dt * gam * grav * hs * gradient(eta_, g.dx, i > 0, c - 1, i < nx - 1, c + 1);
      d[kYs] -= dt * gam * grav * hs * gradient(eta_, g.dy, j > 0, c - nx, j < ny - 1, c + nx);
    }
    if (hf > 0.0) {
      d[kXf] -= dt * grav * hf * gradient(in.hs, g.dx, i > 0, c - 1, i < nx - 1, c + 1);
      d[kYf] -= dt * grav * hf * gradient(in.hs, g.dy, j > 0, c - nx, j < ny - 1, c + nx);
    }
  };
  auto viscosity = [&](double alpha_s) {
    return two_phase::julien_obrien_viscosity(p_.viscosity_alpha, p_.viscosity_beta, alpha_s);
  };
  const int J = p_.drag.exponent;
  // Pass 1: which cells' solid friction holds at rest through this stage
  // (fv2d's rule, with the drag the fluid exerts on the still solid).
  const bool all_open[4] = {true, true, true, true};
#pragma omp parallel for schedule(static)
  for (Index j = 0; j < ny; ++j) {
    for (Index i = 0; i < nx; ++i) {
      const Index c = j * nx + i;
      const double hs = in.hs[c];
      if (!dom[c] || hs <= dry) {
        held_[c] = 2;  // no solid: as quiet as a held one
        continue;
      }
      if (in.hsu[c] != 0.0 || in.hsv[c] != 0.0) {
        held_[c] = 0;
        continue;
      }
      double d[kFields];
      explicit_change(c, i, j, all_open, d);
      double mx = d[kXs], my = d[kYs];
      const double hf = in.hf[c], h = hs + hf;
      if (hf > dry) {
        const double as = hs / h,
                     c_drag = two_phase::drag_coefficient(p_.drag, as, 1.0 - as, viscosity(as));
        const double ux = uf_[c], uy = vf_[c], speed = norm2(ux, uy);
        const double scale = dt * h * c_drag * (J == 2 ? speed : 1.0) / rho_s;
        mx += scale * ux, my += scale * uy;
      }
      const double hold = dt * p_.tan_basal_friction * (1.0 - gam) * grav * cos2[c] * hs;
      held_[c] = mx * mx + my * my <= hold * hold ? 1 : 0;
    }
  }
  limit_outflow(in, dt);
  // Whether no face of cell (i, j) carries anything (the fields' fluxes; the
  // lateral stress's are not looked at, so with it no cell takes this path).
  const bool viscous = lateral_viscosity();
  auto no_face_carries = [&](Index i, Index j) {
    if (viscous) return false;
    const Index w = j * (nx + 1) + i, s = j * nx + i;
    const auto quiet_face = [](const std::vector<double>* f, Index k) {
      bool quiet = true;
      for (int m = 0; m < kFields; ++m) quiet = quiet && f[m][k] == 0.0;
      return quiet;
    };
    return quiet_face(fx_, w) && quiet_face(fx_, w + 1) && quiet_face(fy_, s) &&
           quiet_face(fy_, s + nx);
  };
  // Pass 2: the update. No solid crosses a face between two quiet cells.
  bool finite = true;
#pragma omp parallel for schedule(static) reduction(&& : finite)
  for (Index j = 0; j < ny; ++j) {
    for (Index i = 0; i < nx; ++i) {
      const Index c = j * nx + i;
      if (!dom[c]) continue;
      // An empty cell none of whose faces carries anything stays empty.
      if (mixture_[c] == 0.0 && no_face_carries(i, j)) {
        out.hs[c] = out.hsu[c] = out.hsv[c] = out.hf[c] = out.hfu[c] = out.hfv[c] = 0.0;
        continue;
      }
      bool open[4];
      solid_faces_open(held_, i, j, nx, ny, open);
      double d[kFields], carried[kFields];
      explicit_change(c, i, j, open, d, carried);
      const double hs0 = in.hs[c], hf0 = in.hf[c];
      // A cell the outflow limit emptied can be a round-off below 0 (~1e-25 m): 0.
      const double hs = std::max(0.0, hs0 + d[kHs]), hf = std::max(0.0, hf0 + d[kHf]), h = hs + hf;
      out.hs[c] = hs, out.hf[c] = hf;
      double ms[2] = {in.hsu[c] + d[kXs], in.hsv[c] + d[kYs]};
      double mf[2] = {in.hfu[c] + d[kXf], in.hfv[c] + d[kYf]};
      const bool solid_held = held_[c] == 1;
      const bool solid_wet = hs > dry && !solid_held, fluid_wet = hf > dry;
      if (!solid_wet) ms[0] = ms[1] = 0.0;
      if (!fluid_wet) mf[0] = mf[1] = 0.0;
      const double as = h > dry ? hs / h : 0.0;
      const double eta = fluid_wet ? viscosity(as) : 0.0;  // used only where there is fluid
      Column col{hs, hf, {ms[0], ms[1]}, {mf[0], mf[1]}};
      ColumnSources src;
      src.rho_s = rho_s, src.rho_f = rho_f, src.exponent = J;
      if (fluid_wet && hs > dry)
        src.drag = dt * h * two_phase::drag_coefficient(p_.drag, as, 1.0 - as, eta);
      // Friction on the solid's buoyant weight and its centripetal load, with
      // the velocity the stage's explicit terms gave (as fv2d).
      if (solid_wet)
        src.friction =
            dt * p_.tan_basal_friction * hs0 *
            std::max(0.0, g_bed_solid_[c] + cos2[c] * turning(c, ms[0] / hs, ms[1] / hs));
      if (fluid_wet) {
        src.fluid_linear = rho_f > 0.0 ? dt * p_.shear_factor * eta / (rho_f * hf * h) : 0.0;
        src.fluid_quadratic = dt * grav * p_.manning * p_.manning / (h * std::cbrt(h));
      }
      // Virtual mass acts on the phases' accelerations by the stage's local
      // forces (gravity, buoyancy, drag, friction, resistance), not on the
      // change of a cell's velocities by what its faces carry in and out.
      if (p_.virtual_mass && solid_wet && fluid_wet) {
        const double hs1 = hs0 + carried[kHs], hf1 = hf0 + carried[kHf];
        if (hs1 > dry && hf1 > dry) {
          src.virtual_mass = two_phase::virtual_mass_relative_factor(as, 1.0 - as, gam);
          src.rel_before[0] = (in.hfu[c] + carried[kXf]) / hf1 - (in.hsu[c] + carried[kXs]) / hs1;
          src.rel_before[1] = (in.hfv[c] + carried[kYf]) / hf1 - (in.hsv[c] + carried[kYs]) / hs1;
        }
      }
      apply_sources(col, src, solid_wet, fluid_wet);
      out.hsu[c] = col.ms[0], out.hsv[c] = col.ms[1], out.hfu[c] = col.mf[0],
      out.hfv[c] = col.mf[1];
      if (!std::isfinite(h) || !std::isfinite(col.ms[0] + col.ms[1] + col.mf[0] + col.mf[1]))
        finite = false;
    }
  }
  if (!finite)
    throw RunError(
        fmt::format("two-phase: a depth or momentum is not finite at t = {:.6g} s", in.time));
  out.time = in.time + dt;
  *fluid_out = 0.0;
  if (p_.boundary != GridBoundary::Open) return 0.0;
  double solid = 0.0, fluid = 0.0;
  for (const EdgeFace& f : domain_.faces) {
    const auto& flux = f.normal_x ? fx_ : fy_;
    if (!held_[f.cell]) solid += f.outward_length * flux[kHs][f.face];
    fluid += f.outward_length * flux[kHf][f.face];
  }
  *fluid_out = fluid * dt;
  return solid * dt;
}

void TwoPhaseSolver::step(double dt) {
  if (!(dt > 0.0)) throw RunError(fmt::format("two-phase: time step {} must be positive", dt));
  update_earth_pressure();
  double f1 = 0.0, f2 = 0.0;
  const double s1 = euler_stage(s_, stage_, dt, &f1);
  const double s2 = euler_stage(stage_, stage2_, dt, &f2);
  const Index n = static_cast<Index>(s_.hs.size());
#pragma omp parallel for schedule(static)
  for (Index c = 0; c < n; ++c) {
    s_.hs[c] = 0.5 * (s_.hs[c] + stage2_.hs[c]);
    s_.hsu[c] = 0.5 * (s_.hsu[c] + stage2_.hsu[c]);
    s_.hsv[c] = 0.5 * (s_.hsv[c] + stage2_.hsv[c]);
    s_.hf[c] = 0.5 * (s_.hf[c] + stage2_.hf[c]);
    s_.hfu[c] = 0.5 * (s_.hfu[c] + stage2_.hfu[c]);
    s_.hfv[c] = 0.5 * (s_.hfv[c] + stage2_.hfv[c]);
  }
  s_.time += dt;
  outflow_s_ += 0.5 * (s1 + s2);
  outflow_f_ += 0.5 * (f1 + f2);
  if (p_.rainfall > 0.0 || p_.infiltration > 0.0 || !p_.rainfall_map.empty() ||
      !p_.infiltration_map.empty())
    rain_and_infiltrate(dt);
}

void TwoPhaseSolver::rain_and_infiltrate(double dt) {
  // After the step (split): rain adds fluid without horizontal momentum;
  // infiltration takes fluid, at most what the cell holds, with its velocity
  // (the -I u_u of seed eqs. 52-53). Summed in cell order: the same bits on
  // any team.
  const auto& dom = terrain_.inside();
  double rained = 0.0, infiltrated = 0.0;
  for (std::size_t c = 0; c < s_.hf.size(); ++c) {
    if (!dom[c]) continue;
    const double rain = dt * (p_.rainfall_map.empty() ? p_.rainfall : p_.rainfall_map[c]);
    const double sink =
        dt * (p_.infiltration_map.empty() ? p_.infiltration : p_.infiltration_map[c]);
    const double wet = s_.hf[c] + rain;
    const double taken = std::min(sink, wet);
    const double keep = wet > 0.0 ? (wet - taken) / wet : 0.0;
    s_.hf[c] = wet - taken;
    s_.hfu[c] *= keep, s_.hfv[c] *= keep;
    rained += rain, infiltrated += taken;
  }
  const double area = terrain_.shape().cell_area();
  rained_ += rained * area, infiltrated_ += infiltrated * area;
}

}  // namespace talus::runout
