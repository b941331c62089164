// What a user of fv2d watches and maps, on Ritter's dam break in a channel
// one cell wide (dam_break.hpp; h0 0.1 m, k = 1, frictionless, 5 mm cells):
// the snapshot height maps at 0.2, 0.4, 0.6 and 0.8 s follow Ritter's profile,
// and the arrival-time map equals both the exact arrival of the 1 cm depth
// and the front read from the snapshots.
#include <fmt/format.h>
#include <gtest/gtest.h>
#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <string>

#include "dam_break.hpp"
#include "talus/io/raster.hpp"
#include "talus/run/loop.hpp"
#include "talus/run/methods/fv2d.hpp"
#include "talus/run/methods/runout.hpp"
#include "talus/runout/grid/fv2d_maxima.hpp"

namespace talus::runout {
namespace {

namespace fs = std::filesystem;

constexpr double kCell = 0.005, kReservoir = 1.0, kLength = 3.0, kEnd = 0.8;

RunoutScenario channel() {
  RunoutScenario sc;
  sc.name = "ritter_channel";
  sc.model = RunoutModel::Fv2d;
  const auto n = static_cast<std::size_t>(std::lround(kLength / kCell));
  sc.grid.shape = {n, 1, kCell, kCell};
  sc.grid.elevation.assign(n, 0.0);
  sc.grid.release_depth.assign(n, 0.0);
  for (std::size_t i = 0; (i + 0.5) * kCell < kReservoir; ++i) sc.grid.release_depth[i] = 0.1;
  sc.params.rheology.law = RheologyLaws::index_of(FrictionalRheology::name);
  sc.params.rheology.tan_friction = 0.0;
  sc.params.pressure.mode = EarthPressureMode::Constant;
  sc.params.pressure.constant = 1.0;
  sc.control.duration = kEnd;
  sc.control.series_interval = 0.1;
  sc.control.snapshot_interval = 0.2;
  sc.control.courant = 0.45;
  return sc;
}

TEST(Fv2dSnapshots, MapsFollowRitterAndArrivalMatchesTheFront) {
  const fs::path dir =
      fs::path(::testing::TempDir()) / ("talus_fv2d_snapshots_" + std::to_string(::getpid()));
  fs::remove_all(dir);
  fs::create_directories(dir);
  run::Fv2dSimulation sim(channel());
  sim.write_to(dir);
  run::RunLoop loop(sim, {});
  loop.start(true);
  loop.run();  // ends with the result maps

  const reference::DamBreak exact{0.1, 0.0, 0.0};
  const double eps = Fv2dMaxima::kArrivalHeight;  // 1 cm
  const io::Raster arrival = io::read_raster((dir / "arrival_time.tif").string());
  for (int k = 1; k <= 4; ++k) {
    const double t = 0.2 * k;
    const io::Raster h =
        io::read_raster((dir / "snapshots" / fmt::format("height_{:06d}.tif", k)).string());
    ASSERT_EQ(h.nx, arrival.nx);
    // The profile: L1 distance to Ritter's below 1 % of the released
    // volume (the kinks at both ends of the fan are smeared over a few cells).
    double l1 = 0.0, front = 0.0;
    for (std::size_t i = 0; i < h.nx; ++i) {
      const double x = (i + 0.5) * kCell - kReservoir, a = 2 * exact.c0() - x / t;
      const double ritter =
          x <= -exact.c0() * t ? 0.1 : (x >= 2 * exact.c0() * t ? 0.0 : a * a / (9 * exact.g));
      l1 += std::abs(h.at(i, 0) - ritter) * kCell;
      if (h.at(i, 0) > eps) front = i;
    }
    EXPECT_LT(l1 / (0.1 * kReservoir), 0.01) << "t = " << t;
    // The arrival map: the snapshot's 1 cm front had arrived by then, the
    // next cell had not.
    const auto f = static_cast<std::size_t>(front);
    EXPECT_LE(arrival.at(f, 0), t + 1e-12) << "t = " << t;
    EXPECT_FALSE(arrival.at(f + 1, 0) <= t) << "t = " << t;  // later, or NaN: never
  }
  // Against the exact arrival of 1 cm, x / (2 c0 - 3 sqrt(g eps)) for x > 0:
  // within 5 ms over the fan (the computed 1 cm front is within one cell,
  // 2.5 mm, of the exact one, test_front_convergence.cpp, i.e. 1.5 ms at
  // its 1.68 m/s, plus up to one time step, 1.1 ms, of observation).
  const double speed = 2 * exact.c0() - 3 * std::sqrt(exact.g * eps);
  double worst = 0.0;
  for (std::size_t i = 0; i < arrival.nx; ++i) {
    const double x = (i + 0.5) * kCell - kReservoir;
    if (x < 0.1 || x > speed * kEnd - 0.1) continue;
    worst = std::max(worst, std::abs(arrival.at(i, 0) - x / speed));
  }
  std::printf("arrival of 1 cm: largest difference to the exact %.2e s\n", worst);
  EXPECT_LT(worst, 5e-3);
  fs::remove_all(dir);
}

}  // namespace
}  // namespace talus::runout
