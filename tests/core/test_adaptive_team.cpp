// The choice between a team and one thread alone (core/adaptive_team.hpp),
// fed with made-up segment timings.
#include <gtest/gtest.h>

#include <cstdlib>

#include "talus/core/adaptive_team.hpp"

using namespace talus;

namespace {

// One segment with the team size the chooser asks for; `team_rate` and
// `alone_rate` in steps/s, the team's waits sleeping in `sleepy` of its steps.
int segment(AdaptiveTeam& a, double team_rate, double alone_rate, double sleepy) {
  const int team = a.team();
  const int64_t steps = a.segment_steps();
  const double rate = team > 1 ? team_rate : alone_rate;
  a.record(team, steps, static_cast<double>(steps) / rate,
           team > 1 && AdaptiveTeam::sleepy(static_cast<int64_t>(sleepy * steps), steps));
  return team;
}

}  // namespace

// A quiet machine: the threads do not sleep waiting for each other, and one
// thread is never tried.
TEST(AdaptiveTeam, QuietMachineKeepsTheTeam) {
  unsetenv("TALUS_TEAM");
  AdaptiveTeam a(2);
  for (int k = 0; k < 1000; ++k) ASSERT_EQ(segment(a, 1800.0, 1000.0, 0.01), 2) << k;
}

// A busy machine: the team is slower than one thread and its waits sleep;
// after a probe the run goes on alone, and tries the team again ever more
// rarely: in 1000 segments at most ~1000 / 128 + 8 team segments.
TEST(AdaptiveTeam, BusyMachineGoesAloneAndProbesRarely) {
  unsetenv("TALUS_TEAM");
  AdaptiveTeam a(2);
  int team_segments = 0;
  for (int k = 0; k < 1000; ++k) team_segments += segment(a, 500.0, 1000.0, 1.0) > 1;
  EXPECT_FALSE(a.uses_team());
  EXPECT_LE(team_segments, 1000 / AdaptiveTeam::kMaxProbeEvery + 8);
  // The other process ends: the next probe of the team wins and it stays.
  int alone_after = 0;
  for (int k = 0; k < 300; ++k) alone_after += segment(a, 1800.0, 1000.0, 0.0) == 1;
  EXPECT_TRUE(a.uses_team());
  EXPECT_LE(alone_after, AdaptiveTeam::kMaxProbeEvery + 2);
}

// Segments last about kSegmentSeconds at the measured speed.
TEST(AdaptiveTeam, SegmentsFollowTheSpeed) {
  unsetenv("TALUS_TEAM");
  AdaptiveTeam a(2);
  segment(a, 2000.0, 1000.0, 0.0);
  EXPECT_EQ(a.segment_steps(), static_cast<int64_t>(2000.0 * AdaptiveTeam::kSegmentSeconds));
}

TEST(AdaptiveTeam, EnvironmentFixesTheChoice) {
  setenv("TALUS_TEAM", "alone", 1);
  AdaptiveTeam alone(4);
  setenv("TALUS_TEAM", "team", 1);
  AdaptiveTeam team(4);
  unsetenv("TALUS_TEAM");
  for (int k = 0; k < 100; ++k) {
    ASSERT_EQ(segment(alone, 4000.0, 1000.0, 0.0), 1);
    ASSERT_EQ(segment(team, 100.0, 1000.0, 1.0), 4);
  }
}
