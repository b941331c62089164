#include <gtest/gtest.h>

#include <thread>

#include "talus/core/progress.hpp"

namespace talus {

TEST(ProgressClock, DueOnlyAfterTheIntervalOrWhenForced) {
  ProgressClock hour(3600.0);
  EXPECT_FALSE(hour.due());  // an hour has not passed since construction
  EXPECT_TRUE(hour.due(true));
  ProgressClock every_call(0.0);
  EXPECT_TRUE(every_call.due());
  EXPECT_TRUE(every_call.due());
}

TEST(ProgressClock, RestartsTheIntervalAtEachReport) {
  ProgressClock clock(0.2);
  std::this_thread::sleep_for(std::chrono::milliseconds(250));
  EXPECT_TRUE(clock.due());
  EXPECT_FALSE(clock.due());  // the 0.2 s start again at the report just made
}

TEST(ProgressClock, RateCountsOnlyTheStepsOfThisRun) {
  ProgressClock clock(1.0, 1000);  // a resumed run starting at step 1000
  std::this_thread::sleep_for(std::chrono::milliseconds(20));
  const double elapsed = clock.elapsed();
  const double rate = clock.rate(1100);
  EXPECT_GE(elapsed, 0.02);
  // 100 steps in at least `elapsed` seconds (the rate reads the clock a moment later).
  EXPECT_GT(rate, 0.0);
  EXPECT_LE(rate, 100.0 / elapsed);
}

}  // namespace talus
