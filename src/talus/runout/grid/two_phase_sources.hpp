#pragma once
// The two-phase solver's implicit sources of one cell (grid/two_phase.hpp):
// resistance, drag, friction and virtual mass. Inline: called once per cell
// in the solver's hot loop.
#include <algorithm>
#include <cmath>

namespace talus::runout::two_phase_detail {

// |(x, y)|; std::hypot's care for overflow costs a tenth of a step here.
inline double norm2(double x, double y) { return std::sqrt(x * x + y * y); }

// What is left of a speed w by a resistance linear and quadratic in the new
// speed w', taken fully implicitly: w' (1 + a + b w') = w, so
// w' / w = 2 / (1 + a + sqrt((1 + a)^2 + 4 b w)). Never reverses, stable for
// any step, and a balance of a constant force against the resistance is its
// fixed point exactly (the Manning depth, the drag's terminal slip).
inline double implicit_keep(double a, double b, double w) {
  const double one_a = 1.0 + a;
  if (b == 0.0) return 1.0 / one_a;  // the same without a square root of a square
  return 2.0 / (one_a + std::sqrt(one_a * one_a + 4.0 * b * w));
}

// One cell after the explicit part of a stage: each phase's depth and
// momentum per unit of its density (H_p U_p).
struct Column {
  double hs, hf;
  double ms[2], mf[2];
};

// The stage's implicit sources of a cell, each already times dt: the drag
// (dt H C), the solid's Coulomb friction (per unit solid density), the
// fluid's laminar (linear) and Manning (quadratic) resistance; the virtual
// mass factor r with the relative velocity before the local forces acted
// (after what the cell's faces carried).
struct ColumnSources {
  double rho_s = 0.0, rho_f = 0.0;
  int exponent = 1;
  double drag = 0.0, friction = 0.0, fluid_linear = 0.0, fluid_quadratic = 0.0;
  double virtual_mass = 1.0, rel_before[2] = {0.0, 0.0};
};

// In this order: the fluid's resistance; the drag, implicit in the relative
// velocity (momentum conserving); the solid's friction as an impulse shared
// through that implicit drag (it stops the solid, never reverses it); then
// virtual mass scales the change of the relative velocity since rel_before. With the
// friction inside the implicit coupling, the slip at which a constant force
// difference balances the drag is the stage's fixed point exactly.
// solid / fluid: the phase moves (wet and not held by friction).
inline void apply_sources(Column& col, const ColumnSources& src, bool solid, bool fluid) {
  if (fluid) {
    const double w = norm2(col.mf[0], col.mf[1]) / col.hf;
    const double keep = implicit_keep(src.fluid_linear, src.fluid_quadratic, w);
    col.mf[0] *= keep, col.mf[1] *= keep;
  }
  if (!solid && !fluid) return;
  const double m_s = src.rho_s * col.hs, m_f = src.rho_f * col.hf;
  if (!solid) {  // a still solid (held, or none): drag on the fluid alone
    if (src.drag == 0.0) return;
    const double a = src.drag / m_f, w = norm2(col.mf[0], col.mf[1]) / col.hf;
    const double keep = src.exponent == 2 ? implicit_keep(0.0, a, w) : implicit_keep(a, 0.0, w);
    col.mf[0] *= keep, col.mf[1] *= keep;
    return;
  }
  double us[2] = {col.ms[0] / col.hs, col.ms[1] / col.hs};
  if (!fluid) {
    const double w = norm2(us[0], us[1]), impulse = src.friction / col.hs;
    const double scale = w > impulse ? 1.0 - impulse / w : 0.0;
    col.ms[0] *= scale, col.ms[1] *= scale;
    return;
  }
  // Reciprocals once: this runs for every wet cell twice a step, and a chain
  // of divisions was a fifth of the solver's time.
  const double inv_hf = 1.0 / col.hf;
  double uf[2] = {col.mf[0] * inv_hf, col.mf[1] * inv_hf};
  const double total = m_s + m_f, inv_total = 1.0 / total;
  const double inv_ms = 1.0 / m_s, inv_mf = 1.0 / m_f;
  const double rel[2] = {uf[0] - us[0], uf[1] - us[1]};
  const double a = src.drag * (inv_ms + inv_mf), w = norm2(rel[0], rel[1]);
  const double keep = src.exponent == 2 ? implicit_keep(0.0, a, w) : implicit_keep(a, 0.0, w);
  for (int k = 0; k < 2; ++k) {
    const double p = m_s * us[k] + m_f * uf[k];
    us[k] = (p - m_f * keep * rel[k]) * inv_total;
    uf[k] = us[k] + keep * rel[k];
  }
  // An impulse j on the solid, with the drag implicit, changes its velocity
  // by j beta: beta = (1 - (1 - keep) m_f / (m_s + m_f)) / m_s.
  const double beta = (1.0 - (1.0 - keep) * m_f * inv_total) * inv_ms;
  const double w_s = norm2(us[0], us[1]);
  if (w_s > 0.0 && src.friction > 0.0) {
    const double j = std::min(src.rho_s * src.friction, w_s / beta);
    const double along = j / w_s, to_fluid = (1.0 - m_s * beta) * inv_mf;
    for (int k = 0; k < 2; ++k) {
      const double impulse = -along * us[k];
      us[k] += beta * impulse;
      uf[k] += to_fluid * impulse;
    }
  }
  if (src.virtual_mass < 1.0)
    for (int k = 0; k < 2; ++k) {
      const double p = m_s * us[k] + m_f * uf[k];
      const double r = src.rel_before[k] + src.virtual_mass * (uf[k] - us[k] - src.rel_before[k]);
      us[k] = (p - m_f * r) * inv_total;
      uf[k] = us[k] + r;
    }
  for (int k = 0; k < 2; ++k) col.ms[k] = us[k] * col.hs, col.mf[k] = uf[k] * col.hf;
}

}  // namespace talus::runout::two_phase_detail
