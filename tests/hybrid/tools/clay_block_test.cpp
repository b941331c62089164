// The clay block against an obstacle (van den Bout et al. 2021 §3) with the
// hybrid particles, single phase in plan view (the set-up of
// clay_block_setup.hpp, which follows the plan-view MPM's). The seed: the
// weaker block fractures from the obstacle corner along the flow over about
// half its length, the stronger one deforms only near the impact. Asserted
// with the plan-view MPM test's measures (tests/app/test_clay_block_plan_run.py)
// on 5 mm cells after 0.15 s (the crack is drawn by 0.05 s in the full
// study, docs/validation/hybrid.md): the weak block's corner-line crack
// reaches at least half the length; the strong one's stays within the front
// third, where at least 95 % of its broken particles started.
#include <gtest/gtest.h>

#include "hybrid/clay_block_setup.hpp"

namespace talus::hybrid {
namespace {

using namespace testing;

CrackMeasures run_block(bool strong) {
  ClayBlock b = clay_block_on_obstacle(0.005, strong);
  HybridSolver solver(b.terrain, b.params, b.seeded.particles, b.seeded.spacing);
  run_to(solver, 0.15);
  return measure_crack(solver, b.seeded.particles);
}

TEST(HybridClayBlock, WeakCracksAlongTheFlowStrongOnlyNearTheImpact) {
  const CrackMeasures weak = run_block(false), strong = run_block(true);
  EXPECT_GE(weak.corner_crack, 0.5);
  EXPECT_LE(strong.corner_crack, 1.0 / 3.0);
  EXPECT_GE(strong.broken_in_front_third, 0.95);
  std::printf("weak: crack %.3f, strong: crack %.3f, %.3f of its broken in the front third\n",
              weak.corner_crack, strong.corner_crack, strong.broken_in_front_third);
}

}  // namespace
}  // namespace talus::hybrid
