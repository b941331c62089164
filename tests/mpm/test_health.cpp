// The MPM run's energy watch (mpm/health.hpp): the energy a start state can
// release, the dilatancy limit below which the Drucker-Prager flow rule of
// mpm.md does non-negative plastic work, and a run past that limit stopped
// with a diagnosis instead of flying off the grid.
#include <gtest/gtest.h>
#include <omp.h>

#include <cmath>
#include <string>

#include "talus/core/error.hpp"
#include "talus/mpm/health.hpp"
#include "talus/mpm/scenario.hpp"
#include "talus/run/loop.hpp"
#include "talus/run/methods/mpm.hpp"
#include "talus/scenario/scenario.hpp"
#include "talus/scenario/scenario_mpm.hpp"

namespace talus::mpm {
namespace {

MaterialParams clay(double psi_deg) {
  MaterialParams p;
  p.model = DruckerPrager::name;
  p.density = 2400.0;
  p.youngs_modulus = 21.6e6;
  p.poisson_ratio = 0.2391;
  p.friction_angle = deg2rad(27.0);
  p.dilatancy_angle = deg2rad(psi_deg);
  p.cohesion = 18.3e3;
  return p;
}

// sin(psi) <= alpha / 3 with alpha = 0.14639 at 27 deg (mpm.md's check value):
// psi <= asin(0.048797) = 2.797 deg.
TEST(MpmHealth, DissipativeDilatancyLimitOfTheSpecsPotential) {
  EXPECT_NEAR(rad2deg(dissipative_dilatancy_limit(deg2rad(27.0))), 2.7968, 1e-3);
}

// The plastic work sigma : d(eps_p) of returns from a compressed state sheared
// past the cone. The closed form on the cone, k_c + p (9 sin(psi) - 3 alpha),
// is >= 0 at every p <= 0 below the limit; 0.7 deg above it (3.5 deg) it is
// negative for p < -k_c / (9 sin(psi) - 3 alpha) = -143 kPa, so the state is
// taken at p = -2 MPa.
TEST(MpmHealth, PlasticWorkChangesSignAtTheDilatancyLimit) {
  const double limit = rad2deg(dissipative_dilatancy_limit(deg2rad(27.0)));
  for (const double psi : {limit - 0.5, limit + 0.7}) {
    const auto dp = std::get<DruckerPrager>(make_material(clay(psi)));
    MaterialState s;
    s.cohesion = 18.3e3;
    s.stress = -2e6 * Mat3::Identity();
    Mat3 shear = Mat3::Zero();
    shear(0, 1) = shear(1, 0) = 1.0;
    double work = 0.0;
    for (int i = 0; i < 400; ++i) {
      const Mat3 plastic = dp.update_returning(s, shear, 1e-3, 0.0);
      work += (s.stress.array() * plastic.array()).sum();
    }
    ASSERT_TRUE(s.yielding) << psi;
    if (psi < limit)
      EXPECT_GE(work, 0.0) << psi;
    else
      EXPECT_LT(work, 0.0) << psi;
  }
}

// One point of 1e-3 m^3 (2D: per m of depth) at rest 0.3 m above the grid's
// bottom under g = 10, with a mean stress of -50 kPa: m g h + p^2 / (2K) V.
TEST(MpmHealth, AvailableEnergyIsPotentialPlusElastic) {
  MpmScenario sc;
  sc.dimension = 2;
  sc.solver.gravity = Vec3(0.0, -10.0, 0.0);
  sc.grid.lo = Vec3(0.0, 0.0, 0.0);
  sc.grid.hi = Vec3(1.0, 1.0, 0.0);
  sc.grid.cell_size = 0.05;
  sc.grid.faces.fill(BoundaryKind::Free);
  sc.materials = {clay(0.0)};
  sc.materials[0].name = "clay";
  Solver<2> s = build_mpm<2>(sc);
  MaterialState stressed;
  stressed.stress = -50e3 * Mat3::Identity();
  s.particles.add(Eigen::Vector2d(0.5, 0.3), Eigen::Vector2d::Zero(), 2.4, 1e-3, 0, stressed);
  const double bulk = 21.6e6 / (3.0 * (1.0 - 2.0 * 0.2391));
  EXPECT_NEAR(available_energy(s), 2.4 * 10.0 * 0.3 + 50e3 * 50e3 / (2.0 * bulk) * 1e-3, 1e-9);
}

// The plan-view clay block on 2 cm cells with psi = 10 deg: the energy grows
// within a few ms of the impact and the run stops, naming the angle.
TEST(MpmHealth, DilatantRunStopsWithTheAngleNamed) {
  const int threads = omp_get_max_threads();
  omp_set_num_threads(1);
  const auto file = io::load_scenario_file(
      std::string(TALUS_SOURCE_DIR) + "/scenarios/mpm/mpm_clay_block_plan.toml",
      {"grid.cell_size=0.02", "materials.0.dilatancy_angle=10", "run.duration=0.05"});
  const MpmScenario sc = io::parse_mpm_scenario(file);
  run::MpmSimulation<2> sim(sc, build_mpm<2>(sc));
  run::RunLoop loop(sim, {});
  try {
    loop.start(true);
    loop.run();
    ADD_FAILURE() << "the run did not stop";
  } catch (const RunError& e) {
    EXPECT_NE(std::string(e.what()).find("dilatancy angle of 10 deg is above 2.8 deg"),
              std::string::npos)
        << e.what();
  }
  omp_set_num_threads(threads);
}

}  // namespace
}  // namespace talus::mpm
