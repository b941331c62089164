// The fluid's lateral viscous stress (two_phase_viscous.hpp; Pudasaini 2012,
// seed eqs. 50 and 66): a shear wave in a still layer decays as the viscous
// diffusion equation says, momentum is only moved between cells, and a front
// next to dry ground is not dragged.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "two_phase_helpers.hpp"

namespace talus::runout {
namespace {

using testing::run_to;
using testing::two_phase_frictionless;

// A 1 m layer of fluid on a flat bed, 4 x 64 cells of 0.1 m, open edges,
// no bed friction, eta = 50 Pa s (nu = 0.05 m^2/s at rho_f = 1000), no
// solid; the fluid's x-velocity U cos(k y) with k = pi / 6.4 m (no stress
// through the y edges, du/dy = 0: the mode fits). u depends on y only, so nothing is
// advected and the depth stays flat: d u / dt = nu u_yy, and the amplitude
// decays as exp(-nu k^2 t).
TEST(TwoPhaseViscous, ShearWaveDecaysAsDiffusionPredicts) {
  const std::size_t nx = 4, ny = 64;
  const double dx = 0.1, length = ny * dx, k = M_PI / length, nu = 0.05, end = 20.0;
  GridShape g{nx, ny, dx, dx};
  auto p = two_phase_frictionless();
  p.viscosity_alpha = nu * p.drag.fluid_density;
  p.lateral_viscosity = true;
  // Open edges (the ghost beyond is the cell): flow along x enters and
  // leaves alike, and at the y edges no face carries the stress (free slip).
  p.boundary = GridBoundary::Open;
  TwoPhaseSolver s(Terrain(g, std::vector<double>(g.cells(), 0.0)), p,
                   std::vector<double>(g.cells(), 0.0), std::vector<double>(g.cells(), 1.0));
  TwoPhaseState st = s.state();
  auto mode = [&](std::size_t j) { return std::cos(k * (static_cast<double>(j) + 0.5) * dx); };
  for (std::size_t j = 0; j < ny; ++j)
    for (std::size_t i = 0; i < nx; ++i) st.hfu[g.index(i, j)] = 0.1 * mode(j);
  // The amplitude: the velocity's projection on the mode, over 0.1 m/s.
  auto amplitude = [&](const TwoPhaseSolver& run) {
    double proj = 0.0, norm = 0.0;
    for (std::size_t j = 0; j < ny; ++j)
      for (std::size_t i = 0; i < nx; ++i) {
        const std::size_t c = g.index(i, j);
        proj += run.state().hfu[c] / run.state().hf[c] * mode(j), norm += mode(j) * mode(j);
      }
    return proj / norm / 0.1;
  };
  s.set_state(st);
  double momentum0 = 0.0;
  for (double m : st.hfu) momentum0 += m;
  run_to(s, end);
  double worst_depth = 0.0, momentum = 0.0;
  for (std::size_t c = 0; c < g.cells(); ++c) {
    worst_depth = std::max(worst_depth, std::abs(s.state().hf[c] - 1.0));
    momentum += s.state().hfu[c];
  }
  // Without the stress the wave decays only by the HLL flux's numerical
  // diffusion of a shear wave (its wave speeds are the gravity waves'
  // +-sqrt(g H), whatever the shear).
  p.lateral_viscosity = false;
  TwoPhaseSolver inviscid(Terrain(g, std::vector<double>(g.cells(), 0.0)), p,
                          std::vector<double>(g.cells(), 0.0), std::vector<double>(g.cells(), 1.0));
  inviscid.set_state(st);
  run_to(inviscid, end);
  const double ratio = amplitude(s), numerical = amplitude(inviscid);
  // Continuous: exp(-nu k^2 t) = 0.785875; the discrete operator's rate
  // nu (2 - 2 cos(k dx)) / dx^2 is smaller by (k dx)^2 / 12 = 2e-4 relative
  // (+1e-5 in the ratio), SSP-RK2's error is O((nu k^2 dt)^2) per step
  // (negligible), and the scheme's own diffusion, measured by the inviscid
  // run, multiplies it: within 1e-4 of exp(-nu k^2 t) x that run's ratio.
  const double exact = std::exp(-nu * k * k * end);
  std::printf("shear wave after %.0f s: amplitude ratio %.6f, exact %.6f; inviscid run %.6f\n", end,
              ratio, exact, numerical);
  EXPECT_GT(numerical, 0.99);  // the scheme's diffusion is small beside the stress's
  EXPECT_NEAR(ratio, exact * numerical, 1e-4);
  EXPECT_LT(worst_depth, 1e-12);  // nothing advected, the surface stays flat
  // Fluxes between cells (and along the open edges, where nothing crosses
  // them): the mode's momentum, 0 over the channel, stays 0.
  EXPECT_NEAR(momentum, momentum0, 1e-12);
}

}  // namespace
}  // namespace talus::runout
