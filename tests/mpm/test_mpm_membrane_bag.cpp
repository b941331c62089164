// The geotextile container released from a split barge (mpm.md "Validation
// cases", Hamad et al.), reduced: the bundled scenario on a grid twice as
// coarse (h = 0.2 m, membrane nodes 0.1 m apart), 4 s. What the source states
// qualitatively, with thresholds fixed before the first run:
//  - the bag passes the opening and falls: at the end its sand's centre of
//    mass lies below 1.2 m (it started at 2.8 m, the barge floor was at 2 m,
//    the bag is 1.6 m high);
//  - the membrane tension peaks while the bag passes the opening, then falls
//    to a residual value: the peak of the largest tension, from the start of
//    the opening until the sand's centre of mass has dropped 1 m (half the
//    bag through the gap), exceeds 1.2 times the residual (the mean of the
//    largest tension over the last 0.5 s), and the residual is above zero
//    (the sand at rest on the bed still loads the bag).
// Measured here: peak 44.1 kN/m in the gap, residual 30.7 kN/m (ratio 1.43).
// On the scenario's own grid (h = 0.1 m) the second statement does not hold
// (21.5 kN/m during the opening against a residual of 21.9 kN/m): the spike
// in the gap is a coarse-grid event and the residual depends on the no-slip
// bed (docs/validation.md "Geotextile bag"). This test guards the reduced
// case, not the claim at every resolution.
#include <gtest/gtest.h>
#include <omp.h>

#include <cstdio>

#include "talus/scenario/scenario_mpm.hpp"

namespace talus::mpm {
namespace {

double centre_of_mass_y(const Particles<2>& p) {
  double my = 0.0, m = 0.0;
  for (std::size_t i = 0; i < p.size(); ++i) {
    my += p.mass[i] * p.x[i].y();
    m += p.mass[i];
  }
  return my / m;
}

TEST(MpmGeotextileBag, PassesTheOpeningWithAPeakThenAResidualTension) {
  const int before = omp_get_max_threads();
  omp_set_num_threads(1);
  const auto file = io::load_scenario_file(
      std::string(TALUS_SOURCE_DIR) + "/scenarios/mpm/mpm_geotextile_bag.toml",
      {"grid.cell_size=0.2", "membranes.0.spacing=0.1", "run.duration=4.0"});
  const MpmScenario sc = io::parse_mpm_scenario(file);
  Solver<2> s = build_mpm<2>(sc);
  const double opening = sc.rigid_bodies[0].motion.start, y0 = centre_of_mass_y(s.particles);
  double peak = 0.0, peak_time = 0.0, residual = 0.0, passed_at = -1.0;
  int residual_rows = 0;
  while (s.time < sc.duration - 1e-9) {
    s.step(std::min(s.time_step(), sc.duration - s.time));
    const double t = s.membranes[0].max_tension(), y = centre_of_mass_y(s.particles);
    if (passed_at < 0.0 && y < y0 - 1.0) passed_at = s.time;
    if (s.time >= opening && passed_at < 0.0 && t > peak) peak = t, peak_time = s.time;
    if (s.time > sc.duration - 0.5) residual += t, ++residual_rows;
  }
  residual /= residual_rows;
  const double y_end = centre_of_mass_y(s.particles);
  std::printf(
      "centre of mass %.3f -> %.3f m; half through at %.3f s; peak %.0f N/m at %.3f s; "
      "residual %.0f N/m (ratio %.2f)\n",
      y0, y_end, passed_at, peak, peak_time, residual, peak / residual);
  omp_set_num_threads(before);
  EXPECT_LT(y_end, 1.2);
  EXPECT_GT(passed_at, opening);
  EXPECT_GT(residual, 0.0);
  EXPECT_GT(peak, 1.2 * residual);
}

}  // namespace
}  // namespace talus::mpm
