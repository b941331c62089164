// fv2d on several ranks gives the same bits as on one (issue 33: "fv2d on 2
// and 4 ranks gives the same bits as on 1 (a grid method can be exact)").
// Run under `mpirun -n N`: rank 0 steps the grid alone, then every rank steps
// its block of rows; every step's time step, volume, outflow, kinetic energy,
// momentum sum and largest speed, and the final depths, momenta and
// earth-pressure coefficients must be equal, bit for bit. Two cases: an
// open-edged slope onto a flat with Savage-Hutter pressure, Coulomb friction
// (the mass comes to rest) and a hole of no-data cells; a walled channel with
// Voellmy friction and first order.
// Exit status 1 (on rank 0) at the first difference.
#include <fmt/format.h>

#include <cmath>
#include <cstring>
#include <vector>

#include "talus/comm/comm.hpp"
#include "talus/runout/grid/fv2d.hpp"

using namespace talus;
using runout::Fv2dParams;
using runout::Fv2dSolver;
using runout::GridShape;

namespace {

struct Case {
  const char* name;
  Fv2dParams params;
  bool hole;
  int steps;
};

// A slope falling along x onto a flat, with a channel along both and a bump;
// a cap of material near the top, which comes to rest on the flat (cells at
// rest close their faces: their flags must agree across ranks too);
// optionally a block of no-data cells in its way.
Fv2dSolver make_solver(const Case& k) {
  const GridShape g{40, 23, 1.0, 1.2};
  std::vector<double> z(g.cells()), h0(g.cells(), 0.0);
  std::vector<unsigned char> inside(g.cells(), 1);
  for (std::size_t j = 0; j < g.ny; ++j)
    for (std::size_t i = 0; i < g.nx; ++i) {
      const double x = (i + 0.5) * g.dx, y = (j + 0.5) * g.dy, yc = 0.5 * g.ny * g.dy;
      z[g.index(i, j)] = 0.6 * std::max(0.0, 22.0 - x) + 0.02 * (y - yc) * (y - yc) +
                         0.5 * std::exp(-((x - 25) * (x - 25) + (y - 10) * (y - 10)) / 8.0);
      const double r2 = (x - 8) * (x - 8) + (y - yc) * (y - yc);
      if (r2 < 25.0) h0[g.index(i, j)] = 1.5 * (1.0 - r2 / 25.0);
      if (k.hole && i >= 18 && i < 21 && j >= 13 && j < 16) inside[g.index(i, j)] = 0;
    }
  return Fv2dSolver(runout::Terrain(g, z, inside), k.params, h0);
}

struct Record {
  std::vector<double> series;  // per step: dt, volume, outflow, kinetic energy, ...
  runout::FlowState state;
  std::vector<double> k;
};

Record run(Fv2dSolver& s, int steps) {
  Record r;
  for (int n = 0; n < steps; ++n) {
    const double dt = std::min(s.stable_time_step(), 0.05);
    s.step(dt);
    const double sums[] = {dt,
                           s.volume(),
                           s.outflow_volume(),
                           s.kinetic_energy(),
                           s.momentum_sum(),
                           s.max_speed(),
                           s.max_height(),
                           s.momentum_x()};
    r.series.insert(r.series.end(), std::begin(sums), std::end(sums));
  }
  s.gather();
  r.state = s.state();
  r.k = s.earth_pressure();
  return r;
}

bool same(const std::vector<double>& a, const std::vector<double>& b) {
  return a.size() == b.size() && std::memcmp(a.data(), b.data(), a.size() * sizeof(double)) == 0;
}

}  // namespace

int main(int argc, char** argv) {
  comm::Comm::init(&argc, &argv);
  const auto& world = comm::Comm::world();
  Fv2dParams open;
  open.rheology.tan_friction = std::tan(25.0 * M_PI / 180.0);
  open.pressure.mode = runout::EarthPressureMode::SavageHutter;
  open.pressure.phi_internal = 32.0 * M_PI / 180.0;
  open.pressure.tan_phi_basal = open.rheology.tan_friction;
  open.boundary = runout::GridBoundary::Open;
  Fv2dParams walled;
  walled.rheology.law = runout::RheologyLaws::index_of(runout::VoellmyRheology::name);
  walled.rheology.tan_friction = 0.15;
  walled.rheology.turbulence = 500.0;
  walled.order = 1;
  const Case cases[] = {{"open slope onto a flat, Savage-Hutter, no-data hole", open, true, 600},
                        {"walled channel, Voellmy, first order", walled, false, 200}};
  int failures = 0;
  for (const Case& k : cases) {
    Record one;
    if (world.root()) {
      Fv2dSolver alone = make_solver(k);
      one = run(alone, k.steps);
    }
    Fv2dSolver spread = make_solver(k);
    spread.distribute(world);
    const Record many = run(spread, k.steps);
    if (!world.root()) continue;
    const bool ok = same(one.series, many.series) && same(one.state.h, many.state.h) &&
                    same(one.state.hu, many.state.hu) && same(one.state.hv, many.state.hv) &&
                    same(one.k, many.k) && one.state.time == many.state.time;
    // The case must have moved material out of its cap (and, open, out of the grid).
    const double moved = many.series[8 * (k.steps - 1) + 3];
    fmt::print(
        "{}: {} on {} rank(s) against one: {} (after {} steps: t = {:.4g} s, volume {:.6g} "
        "m3, outflow {:.4g} m3, kinetic energy {:.4g} J)\n",
        ok ? "PASS" : "FAIL", k.name, world.size(), ok ? "same bits" : "differs", k.steps,
        many.state.time, many.series[8 * (k.steps - 1) + 1], many.series[8 * (k.steps - 1) + 2],
        moved);
    if (!ok || !(moved > 0.0)) ++failures;
  }
  comm::Comm::finalize();
  return failures == 0 ? 0 : 1;
}
