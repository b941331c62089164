#pragma once
// The two-phase solver's face fluxes (grid/two_phase.hpp): HLL per face with
// hydrostatic reconstruction of the fluid. Inline: called once per face in
// the solver's hot loop.
#include <algorithm>
#include <cmath>
#include <limits>

#include "talus/runout/grid/fv2d.hpp"

namespace talus::runout::two_phase_detail {

constexpr double kInf = std::numeric_limits<double>::infinity();

// One side of a face in the face's frame: each phase's depth and normal /
// tangential velocity, the bed there, the solid's pressure coefficient.
// h: the mixture's depth (for the fluid's cut); gs: the solid's pressure
// coefficient; gw: the wave speed's, c^2 = gw h.
struct Side {
  double hs, us, vs, hf, uf, vf, h, b, gs, gw;
};

// The fluxes of a face in its frame (per phase: depth, normal and tangential
// momentum) and the fluid's hydrostatic correction of its normal momentum
// that the left and the right cell add (Audusse et al. 2004).
struct FaceFlux {
  double f[6] = {0, 0, 0, 0, 0, 0};
  double left = 0.0, right = 0.0;
};

inline Side ghost(const Side& inside, GridBoundary b) {
  if (b == GridBoundary::Open) return inside;
  Side m = inside;
  m.us = -inside.us, m.uf = -inside.uf;
  return m;
}

// HLL with wave speeds covering every phase present (the exact dry-front
// speed u + 2c towards a dry side, as fv2d). The fluid by hydrostatic
// reconstruction: each side's fluid is cut to the higher of the two beds (in
// proportion to the mixture's depth there), and the pressure the cut removed
// returns as the side's correction. The solid as fv2d takes it, uncut: its
// bed term is a source with the terrain's slope (a solid at rest is held by
// friction, not by a balance of discrete pressures, and its earth pressure
// k, between k_a and k_p, would multiply any error of that balance).
inline FaceFlux face_flux(const Side& L, const Side& R, double g, double dry) {
  FaceFlux out;
  const double b_star = std::max(L.b, R.b);
  const double hl_star = std::max(0.0, L.h + L.b - b_star);
  const double hr_star = std::max(0.0, R.h + R.b - b_star);
  const double hfl = L.h > 0.0 ? L.hf * hl_star / L.h : 0.0;
  const double hfr = R.h > 0.0 ? R.hf * hr_star / R.h : 0.0;
  out.left = 0.5 * g * (L.hf * L.hf - hfl * hfl);
  out.right = 0.5 * g * (R.hf * R.hf - hfr * hfr);
  // Fluid on a wet side that the cut removes entirely, next to a wet side,
  // meets a step higher than its surface between two parts of the flow:
  // for it the face is a wall, and beyond the pressure above the wall's
  // reaction stops what moves into it (the momentum flux of HLL between the
  // side and its mirror image, h u (2 |u| + c)). The reconstruction makes
  // such steps where two cells place the bed at their face further apart
  // than a thin layer is deep (curved terrain); without the reaction that
  // layer kept accelerating without moving. At a front (the other side dry)
  // the cut is no wall: the flow advances onto the dry bed.
  if (L.hf > dry && R.h > dry && hl_star == 0.0 && L.uf > 0.0)
    out.left += L.hf * L.uf * (2.0 * L.uf + std::sqrt(g * L.h));
  if (R.hf > dry && L.h > dry && hr_star == 0.0 && R.uf < 0.0)
    out.right += R.hf * R.uf * (2.0 * R.uf - std::sqrt(g * R.h));
  const double hsl = L.hs, hsr = R.hs;
  const bool wet[4] = {hsl > dry, hfl > dry, hsr > dry, hfr > dry};
  const bool wet_l = wet[0] || wet[1], wet_r = wet[2] || wet[3];
  if (!wet_l && !wet_r) return out;
  // The solid's pressure and the wave speeds take the mixture as the phases'
  // own reconstructions give it (without fluid, exactly fv2d's face depth).
  const double mix_l = L.hs + L.hf, mix_r = R.hs + R.hf;
  const double cl = std::sqrt(L.gw * mix_l), cr = std::sqrt(R.gw * mix_r);
  const double u[4] = {wet[0] ? L.us : 0.0, wet[1] ? L.uf : 0.0, wet[2] ? R.us : 0.0,
                       wet[3] ? R.uf : 0.0};
  const double v[4] = {wet[0] ? L.vs : 0.0, wet[1] ? L.vf : 0.0, wet[2] ? R.vs : 0.0,
                       wet[3] ? R.vf : 0.0};
  double sl = kInf, sr = -kInf;
  for (int k = 0; k < 2; ++k) {
    if (wet[k]) sl = std::min(sl, u[k] - cl), sr = std::max(sr, u[k] + (wet_r ? cl : 2.0 * cl));
    if (wet[k + 2])
      sl = std::min(sl, u[k + 2] - (wet_l ? cr : 2.0 * cr)), sr = std::max(sr, u[k + 2] + cr);
  }
  const double ul[6] = {hsl, hsl * u[0], hsl * v[0], hfl, hfl * u[1], hfl * v[1]};
  const double ur[6] = {hsr, hsr * u[2], hsr * v[2], hfr, hfr * u[3], hfr * v[3]};
  const double fl[6] = {ul[1], ul[1] * u[0] + 0.5 * L.gs * hsl * mix_l, ul[1] * v[0],
                        ul[4], ul[4] * u[1] + 0.5 * g * hfl * hfl,      ul[4] * v[1]};
  const double fr[6] = {ur[1], ur[1] * u[2] + 0.5 * R.gs * hsr * mix_r, ur[1] * v[2],
                        ur[4], ur[4] * u[3] + 0.5 * g * hfr * hfr,      ur[4] * v[3]};
  if (sl >= 0.0) {
    std::copy(fl, fl + 6, out.f);
  } else if (sr <= 0.0) {
    std::copy(fr, fr + 6, out.f);
  } else {
    const double inv = 1.0 / (sr - sl);
    for (int m = 0; m < 6; ++m)
      out.f[m] = (sr * fl[m] - sl * fr[m] + sl * sr * (ur[m] - ul[m])) * inv;
  }
  return out;
}

}  // namespace talus::runout::two_phase_detail
