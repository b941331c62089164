// How the threads share particles and pairs (dem/thread_partition.hpp): the
// invariants the race-free, barrier-free force pass relies on, checked on the
// peer column after it has collapsed for a while (an irregular pair list).
#include <gtest/gtest.h>

#include "peer_case.hpp"
#include "support/dem_loop.hpp"
#include "talus/dem/builder.hpp"
#include "talus/dem/thread_partition.hpp"

using namespace talus;
using namespace talus::dem;

namespace {

void check_partition(int nt, const Particles<3>& p, const NeighbourList<3>& nl) {
  ThreadPartition<3> part;
  part.prepare(nt, p, nl);
  ASSERT_EQ(part.size(), nt);
  const int n = static_cast<int>(p.size());
  // Particles and pairs are cut into consecutive pieces covering everything.
  EXPECT_EQ(part.share(0).p0, 0);
  EXPECT_EQ(part.share(0).k0, 0u);
  EXPECT_EQ(part.share(nt - 1).p1, n);
  EXPECT_EQ(part.share(nt - 1).k1, nl.pairs.size());
  for (int t = 1; t < nt; ++t) {
    EXPECT_EQ(part.share(t).p0, part.share(t - 1).p1);
    EXPECT_EQ(part.share(t).k0, part.share(t - 1).k1);
  }
  // Which threads' pairs touch each particle.
  std::vector<std::vector<int>> touched_by(n);
  for (int t = 0; t < nt; ++t) {
    const auto& s = part.share(t);
    for (std::size_t k = s.k0; k < s.k1; ++k) {
      const auto& q = nl.pairs[k];
      ASSERT_LT(q.i, q.j);   // the cut relies on j > i
      ASSERT_GE(q.i, s.p0);  // a thread's pairs start in its own particles
      ASSERT_LT(q.i, s.p1);
      for (int i : {q.i, q.j}) {
        ASSERT_GE(i, s.lo);
        ASSERT_LE(i, s.hi);
        if (touched_by[i].empty() || touched_by[i].back() != t) touched_by[i].push_back(t);
      }
    }
  }
  for (int t = 0; t < nt; ++t) {
    const auto& s = part.share(t);
    for (int i = s.p0; i < s.p1; ++i)
      for (int u : touched_by[i]) {
        // Only this thread or earlier ones reach its particles, and the
        // earlier ones only up to wait_hi (what the thread waits for).
        ASSERT_LE(u, t) << "particle " << i;
        if (u < t) {
          ASSERT_LE(i, s.wait_hi) << "particle " << i;
        }
      }
  }
  // A particle some thread owns (forces straight into the particle arrays)
  // is touched by that thread's pairs alone.
  for (int i = 0; i < n; ++i)
    if (part.owned(i)) {
      ASSERT_EQ(touched_by[i].size(), 1u) << "particle " << i;
    }
}

}  // namespace

// The peer column after 4000 steps: it has slumped, contacts vary along it.
// Run once for both tests.
const DemSystem<3>& slumped_column() {
  static const auto run = [] {
    const auto sc = cases::peer_column(10, 10, 20);
    auto r = build_dem<3>(sc, {});
    run::DemControl c;
    c.duration = 4000 * sc.run.time_step;
    test::run_dem<3>(*r, c);
    return r;
  }();
  return run->system;
}

TEST(ThreadPartition, SharesCoverEverythingAndOnlyEarlierThreadsReachIn) {
  const auto& s = slumped_column();
  for (int nt : {2, 3, 4, 7}) {
    SCOPED_TRACE(nt);
    check_partition(nt, s.particles, s.neighbours);
  }
}

// The cut balances the estimated work: the first thread's cost reaches half
// the total with its last particle (std::lower_bound on the running sum), so
// it exceeds the second's by less than twice the costliest particle.
TEST(ThreadPartition, CutBalancesTheEstimatedCost) {
  const auto& p = slumped_column().particles;
  const auto& nl = slumped_column().neighbours;
  ThreadPartition<3> part;
  part.prepare(2, p, nl);
  std::vector<std::size_t> rows(p.size(), 0);
  for (const auto& q : nl.pairs) ++rows[q.i];
  double c_max = 0.0;
  for (std::size_t i = 0; i < p.size(); ++i)
    c_max = std::max(c_max, ThreadPartition<3>::cost(p.contacts[i], rows[i]));
  auto cost = [&](int t) {
    double sum = 0.0;
    for (int i = part.share(t).p0; i < part.share(t).p1; ++i)
      sum += ThreadPartition<3>::cost(p.contacts[i], rows[i]);
    return sum;
  };
  const double a = cost(0), b = cost(1);
  EXPECT_GE(a, b);
  EXPECT_LT(a - b, 2.0 * c_max);
}
