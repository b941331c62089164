// The walls' single-step force extremes (geometry::Wall::force_max/min, kept by
// the stepper, reset by the run loop after each series row) on one undamped
// impact, where the peak is known: a linear spring without dashpot stops a
// particle of mass m arriving at v after an overlap v sqrt(m/k), so the
// largest contact force is v sqrt(k m) (the half period of the oscillator,
// pi sqrt(m/k), is the contact's duration; it returns at v).
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "support/dem_loop.hpp"
#include "talus/dem/contact/laws.hpp"
#include "verification_cases.hpp"

using namespace talus;
using namespace talus::dem;
using namespace talus::dem::verification;

namespace {

template <int D>
struct Row {
  double time;
  Vec3 max, min, impulse;
};

template <int D>
class FloorRecorder final : public run::Observer {
 public:
  explicit FloorRecorder(const DemRun<D>& run) : run_(run) {}
  void on_series() override {
    const auto& w = run_.system.walls.at(0);
    rows.push_back({run_.system.time, w.force_max, w.force_min, w.impulse});
  }
  std::vector<Row<D>> rows;

 private:
  const DemRun<D>& run_;
};

template <class Dim>
class WallForcePeak : public ::testing::Test {};
using Dims = ::testing::Types<Dim2, Dim3>;
TYPED_TEST_SUITE(WallForcePeak, Dims);

TYPED_TEST(WallForcePeak, SingleStepPeakOfAnImpactAndResetPerRow) {
  constexpr int D = TypeParam::value;
  const double R = 1.5e-3, rho = 2672, v = 2.0, k = 1e7;
  const double m = rho * Space<D>::volume(R);
  const double t_c = M_PI * std::sqrt(m / k);
  const double dt = t_c / 4000;  // as test_verification_linear.cpp
  DemScenario sc = scenario(D, LinearSpringDashpot::name, dt, Vec3::Zero());
  sc.materials.push_back(linear_material("sand", rho, k, k, 0.0, 0.3));
  sc.materials.push_back(rigid_material("rigid"));
  sc.walls.push_back(floor_wall<D>("rigid"));
  add_balls(sc, {ball((R + 0.5 * v * dt) * up<D>(), -v * up<D>(), R, "sand")});
  auto run = build_dem<D>(sc, {});
  // Rows at 1.5 t_c (the whole contact inside), 3 t_c and 4.5 t_c (the
  // particle flies off, no contact).
  run::DemControl c;
  c.duration = 4.5 * t_c;
  c.series_interval = 6000 * dt;
  c.snapshot_interval = -1;
  FloorRecorder<D> rec(*run);
  test::run_dem<D>(*run, c, {&rec});
  ASSERT_EQ(rec.rows.size(), 4u);  // t = 0 and three intervals

  // t = 0: no step closed yet, so no extremes.
  EXPECT_GT(rec.rows[0].min[kUp<D>], rec.rows[0].max[kUp<D>]);
  // The floor is pushed down: its peak is the most negative up force. With
  // 4000 steps per contact the step misses the exact peak by at most
  // (pi / 4000)^2 / 8 ~ 8e-8 relative, and Verlet's energy error is of the
  // same order: tolerance 1e-5 relative.
  const double peak = v * std::sqrt(k * m);
  const Row<D>& hit = rec.rows[1];
  EXPECT_NEAR(hit.min[kUp<D>], -peak, 1e-5 * peak);
  EXPECT_EQ(hit.max[kUp<D>], 0.0);  // the steps before the first touch
  // The interval's mean force, from the impulse (2 m v: without a dashpot the
  // particle leaves at v, to the same O((pi / 4000)^2) as the peak: tolerance
  // 1e-5 relative), is 2.36x lower than the peak (2 m v / 1.5 t_c against
  // v sqrt(k m): 1.5 pi / 2; the two tolerances add up to 2e-5).
  const double mean = hit.impulse[kUp<D>] / (1.5 * t_c);
  const double expected_mean = -2.0 * m * v / (1.5 * t_c);
  EXPECT_NEAR(mean, expected_mean, 1e-5 * std::abs(expected_mean));
  EXPECT_NEAR(hit.min[kUp<D>] / mean, 1.5 * M_PI / 2.0, 2e-5 * 1.5 * M_PI / 2.0);
  // The later intervals see no contact: the extremes were reset after each row.
  for (std::size_t r = 2; r < rec.rows.size(); ++r) {
    EXPECT_EQ(rec.rows[r].max[kUp<D>], 0.0) << r;
    EXPECT_EQ(rec.rows[r].min[kUp<D>], 0.0) << r;
    EXPECT_EQ(rec.rows[r].impulse[kUp<D>], hit.impulse[kUp<D>]) << r;
  }
}

}  // namespace
