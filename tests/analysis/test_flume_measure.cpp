// The flume measures on grains placed at known places along the path: the
// expected values follow from the construction, not from a run.
#include <gtest/gtest.h>

#include "talus/analysis/flume_measure.hpp"
#include "talus/analysis/flume_observer.hpp"

namespace talus::analysis {
namespace {

const geometry::FlumeGeometry kA =
    geometry::make_flume({deg2rad(33.0), 0.10, {}, {}});  // geometry A

// A grain of radius r resting on the bed at path coordinate s, lifted by h.
void put(Grains& g, double s, double r, double h = 0.0) {
  g.x.push_back(kA.point_at(s) + (r + h) * bed_normal(kA, s));
  g.r.push_back(r);
}

TEST(FlumeMeasure, BedNormalPointsIntoTheFlowAndIsUnit) {
  for (double s : {0.2, kA.chute_end_s() + 0.05, kA.arc_end_s() + 0.3}) {
    const Vec2 n = bed_normal(kA, s);
    EXPECT_NEAR(n.norm(), 1.0, 1e-12);
    EXPECT_GT(n.y(), 0.0);  // above the bed everywhere on this flume
    EXPECT_NEAR(n.dot(kA.tangent_at(s)), 0.0, 1e-12);
  }
  // Lowest point of the arc: straight below its centre.
  EXPECT_NEAR(bed_low_point(kA), kA.arc_centre.y() - 0.10, 1e-15);
}

TEST(FlumeMeasure, FrontIsTheQuantileOfPathCoordinates) {
  Grains g;
  for (int k = 0; k < 101; ++k) put(g, 0.01 * k, 1.5e-3);  // s = 0, 0.01, ..., 1.00
  // quantile 0.9 of 101 values: the 91st smallest, s = 0.90.
  const FrontSample f = measure_front(kA, g, 0.9);
  EXPECT_NEAR(f.front_s, 0.90, 1e-9);
  EXPECT_NEAR((f.front - kA.point_at(0.90)).norm(), 0.0, 1e-12);
  EXPECT_EQ(f.runup_s, 0.0);  // still on the chute
  EXPECT_EQ(f.on_chute, 101);
  EXPECT_NEAR(measure_front(kA, g, 1.0).front_s, 1.00, 1e-9);
}

TEST(FlumeMeasure, RunUpOnTheBarrier) {
  Grains g;
  const double s = kA.arc_end_s() + 0.25;
  put(g, s, 1.5e-3);
  const FrontSample f = measure_front(kA, g, 1.0);
  EXPECT_NEAR(f.runup_s, 0.25, 1e-9);
  // 0.25 m up a 33 deg barrier that starts at the arc's end.
  const double height =
      kA.barrier_start.y() + 0.25 * std::sin(33.0 * M_PI / 180) - bed_low_point(kA);
  EXPECT_NEAR(f.runup_height, height, 1e-9);
  EXPECT_EQ(f.on_chute, 0);
}

TEST(FlumeMeasure, ProfileThicknessIsTheTopOfTheHighestGrain) {
  Grains g;
  const double r = 1e-3;
  // A column of 5 grains stacked normal to the chute at s = 0.505, and one
  // grain on the barrier.
  for (int k = 0; k < 5; ++k) put(g, 0.505, r, 2 * r * k);
  put(g, kA.arc_end_s() + 0.105, r);
  const auto profile = deposit_profile(kA, g, 0.01);
  int filled = 0;
  for (const ProfileBin& b : profile) {
    if (b.count == 0) {
      EXPECT_EQ(b.thickness, 0.0);
      continue;
    }
    ++filled;
    if (b.s_low < 0.505 && 0.505 < b.s_high) {
      EXPECT_EQ(b.count, 5);
      EXPECT_NEAR(b.thickness, 10 * r, 1e-12);  // five diameters
      const Vec2 top = kA.point_at(0.505) + 10 * r * bed_normal(kA, 0.505);
      EXPECT_NEAR((b.surface - top).norm(), 0.0, 1e-12);
    } else {
      EXPECT_EQ(b.count, 1);
      EXPECT_NEAR(b.thickness, 2 * r, 1e-12);
    }
  }
  EXPECT_EQ(filled, 2);
  EXPECT_NEAR(profile.front().s_low, kA.chute_start_s(), 1e-15);
  EXPECT_NEAR(profile.back().s_high, kA.path_end_s(), 1e-15);
}

TEST(FlumeMeasure, TailIsWhereTheUnbrokenThickRunStarts) {
  std::vector<ProfileBin> p(10);
  for (int k = 0; k < 10; ++k) p[k].s_low = 0.1 * k;
  const double t[10] = {0.02, 0.0, 0.003, 0.02, 0.03, 0.05, 0.08, 0.04, 0.0, 0.0};
  for (int k = 0; k < 10; ++k) p[k].thickness = t[k];
  // Thickest is bin 6; going upstream bins 5, 4, 3 exceed 0.01, bin 2 does not.
  EXPECT_NEAR(deposit_tail(p, 0.01), 0.3, 1e-15);
  // A higher threshold cuts at bin 5 (0.05 > 0.04, 0.03 is not).
  EXPECT_NEAR(deposit_tail(p, 0.04), 0.5, 1e-15);
}

TEST(FlumeSeries, ImpulsePeakAndArrivalFromTheRows) {
  const std::vector<std::string> cols = {
      "time",        "front_s",     "runup_s",         "runup_height",
      "chute_fx",    "chute_fy",    "arc_fx",          "arc_fy",
      "barrier_fx",  "barrier_fy",  "chute_fx_peak",   "chute_fy_peak",
      "arc_fx_peak", "arc_fy_peak", "barrier_fx_peak", "barrier_fy_peak"};
  std::vector<std::vector<double>> rows;
  // 1 s in steps of 0.01 s: constant chute force, a barrier pulse of 100 N
  // between 0.5 and 0.6 s, the front moving at 2 m/s. The single-step peaks:
  // the means, but the barrier's 400 N in the interval ending at 0.55 s and
  // an arc y force of -60 N at 0.3 s, whose interval mean stays -5 N.
  for (int k = 0; k <= 100; ++k) {
    const double t = 0.01 * k, s = 2.0 * t;
    const double pulse = (t > 0.5 + 1e-9 && t <= 0.6 + 1e-9) ? 100.0 : 0.0;
    const double runup = std::max(0.0, s - kA.arc_end_s());
    const double barrier_peak = k == 55 ? 400.0 : pulse, arc_peak = k == 30 ? -60.0 : -5.0;
    rows.push_back({t, s, runup, 0.5 * runup, -10.0, -20.0, 0.0, -5.0, pulse, 0.0, -10.0, -20.0,
                    0.0, arc_peak, barrier_peak, 0.0});
  }
  const auto sum = summarise_front_series(kA, cols, rows, 0.1);
  // Each row's force is the mean over the interval ending at its time.
  EXPECT_NEAR(sum.impulse[0][0], -10.0, 1e-9);
  EXPECT_NEAR(sum.impulse[0][1], -20.0, 1e-9);
  EXPECT_NEAR(sum.impulse[2][0], 10.0, 1e-9);  // 100 N for 0.1 s
  EXPECT_NEAR(sum.peak[2][0].value, 100.0, 1e-12);
  EXPECT_NEAR(sum.peak[2][0].time, 0.51, 1e-12);
  EXPECT_NEAR(sum.final_force[1][1], -5.0, 1e-9);
  // The step peaks are the extremes of their own columns, signed.
  EXPECT_EQ(sum.step_peak[2][0].value, 400.0);
  EXPECT_NEAR(sum.step_peak[2][0].time, 0.55, 1e-12);
  EXPECT_EQ(sum.step_peak[1][1].value, -60.0);
  EXPECT_NEAR(sum.step_peak[1][1].time, 0.30, 1e-12);
  EXPECT_EQ(sum.peak[1][1].value, -5.0);
  EXPECT_NEAR(sum.final_force[2][0], 0.0, 1e-12);
  // The front passes s = chute_end_s at t = chute_end_s / 2, first sampled at the next row.
  EXPECT_NEAR(sum.reach_arc_time, std::ceil(kA.chute_end_s() / 2 / 0.01) * 0.01, 1e-9);
  EXPECT_NEAR(sum.reach_barrier_time, std::ceil(kA.arc_end_s() / 2 / 0.01) * 0.01, 1e-9);
  EXPECT_NEAR(sum.max_runup_s, 2.0 - kA.arc_end_s(), 1e-9);
  EXPECT_NEAR(sum.max_runup_time, 1.0, 1e-12);
}

}  // namespace
}  // namespace talus::analysis
