// How the chunks share particles and pairs (dem/chunk_partition.hpp): the
// invariants the race-free, barrier-free force pass relies on, checked on the
// peer column after it has collapsed for a while (an irregular pair list).
#include <gtest/gtest.h>

#include "peer_case.hpp"
#include "support/dem_loop.hpp"
#include "talus/dem/builder.hpp"
#include "talus/dem/chunk_partition.hpp"

using namespace talus;
using namespace talus::dem;

namespace {

void check_partition(int nt, const Particles<3>& p, const NeighbourList<3>& nl) {
  ChunkPartition<3> part;
  part.prepare(nt, p, nl);
  ASSERT_EQ(part.size(), nt);
  const int n = static_cast<int>(p.size());
  // Particles and pairs are cut into consecutive pieces covering everything.
  EXPECT_EQ(part.chunk(0).p0, 0);
  EXPECT_EQ(part.chunk(0).k0, 0u);
  EXPECT_EQ(part.chunk(nt - 1).p1, n);
  EXPECT_EQ(part.chunk(nt - 1).k1, nl.pairs.size());
  for (int t = 1; t < nt; ++t) {
    EXPECT_EQ(part.chunk(t).p0, part.chunk(t - 1).p1);
    EXPECT_EQ(part.chunk(t).k0, part.chunk(t - 1).k1);
  }
  // Which chunks' pairs touch each particle.
  std::vector<std::vector<int>> touched_by(n);
  for (int t = 0; t < nt; ++t) {
    const auto& s = part.chunk(t);
    for (std::size_t k = s.k0; k < s.k1; ++k) {
      const auto& q = nl.pairs[k];
      ASSERT_LT(q.i, q.j);   // the cut relies on j > i
      ASSERT_GE(q.i, s.p0);  // a chunk's pairs start in its own particles
      ASSERT_LT(q.i, s.p1);
      for (int i : {q.i, q.j}) {
        ASSERT_GE(i, s.lo);
        ASSERT_LE(i, s.hi);
        if (touched_by[i].empty() || touched_by[i].back() != t) touched_by[i].push_back(t);
      }
    }
  }
  for (int t = 0; t < nt; ++t) {
    const auto& s = part.chunk(t);
    for (int i = s.p0; i < s.p1; ++i)
      for (int u : touched_by[i]) {
        // Only this chunk or earlier ones reach its particles, and the
        // earlier ones only up to wait_hi (what the chunk waits for).
        ASSERT_LE(u, t) << "particle " << i;
        if (u < t) {
          ASSERT_LE(i, s.wait_hi) << "particle " << i;
        }
      }
  }
  // A particle some chunk owns (forces straight into the particle arrays)
  // is touched by that chunk's pairs alone.
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

TEST(ChunkPartition, ChunksCoverEverythingAndOnlyEarlierChunksReachIn) {
  const auto& s = slumped_column();
  for (int nt : {2, 3, 4, 7, 8, 28}) {
    SCOPED_TRACE(nt);
    check_partition(nt, s.particles, s.neighbours);
  }
}

// The cut balances the estimated work: the first chunk's cost reaches half
// the total with its last particle (std::lower_bound on the running sum), so
// it exceeds the second's by less than twice the costliest particle.
TEST(ChunkPartition, CutBalancesTheEstimatedCost) {
  const auto& p = slumped_column().particles;
  const auto& nl = slumped_column().neighbours;
  ChunkPartition<3> part;
  part.prepare(2, p, nl);
  std::vector<std::size_t> rows(p.size(), 0);
  for (const auto& q : nl.pairs) ++rows[q.i];
  double c_max = 0.0;
  for (std::size_t i = 0; i < p.size(); ++i)
    c_max = std::max(c_max, ChunkPartition<3>::cost(p.contacts[i], rows[i]));
  auto cost = [&](int t) {
    double sum = 0.0;
    for (int i = part.chunk(t).p0; i < part.chunk(t).p1; ++i)
      sum += ChunkPartition<3>::cost(p.contacts[i], rows[i]);
    return sum;
  };
  const double a = cost(0), b = cost(1);
  EXPECT_GE(a, b);
  EXPECT_LT(a - b, 2.0 * c_max);
}

// Who computes which chunk (ChunkClaims): every chunk exactly once, a thread's
// own chunks first and in order, and a thread left alone takes them all.
TEST(ChunkClaims, EveryChunkOnceOwnFirst) {
  for (int team : {1, 2, 3}) {
    for (int chunks : {1, 2, 5, 8, 12}) {
      SCOPED_TRACE(std::to_string(team) + " threads, " + std::to_string(chunks) + " chunks");
      ChunkClaims claims;
      claims.reset(team, chunks);
      std::vector<int> taken_by(chunks, -1);
      std::vector<std::vector<int>> order(team);
      // Thread 0 takes until nothing is left: its own, then others' back chunks.
      for (int c = claims.take(0); c >= 0; c = claims.take(0)) {
        ASSERT_EQ(taken_by[c], -1);
        taken_by[c] = 0;
        order[0].push_back(c);
      }
      for (int t = 1; t < team; ++t)
        for (int c = claims.take(t); c >= 0; c = claims.take(t)) {
          ASSERT_EQ(taken_by[c], -1);
          taken_by[c] = t;
          order[t].push_back(c);
        }
      for (int c = 0; c < chunks; ++c) ASSERT_GE(taken_by[c], 0) << c;
      // Thread 0's own chunks come first, in order.
      const int own = chunks / team;
      for (int k = 0; k < own; ++k) ASSERT_EQ(order[0][k], k);
      // Another thread's last chunk is never taken from it (it is about to take it).
      for (int t = 1; t < team; ++t) {
        const int first = chunks * t / team, last = chunks * (t + 1) / team - 1;
        if (last >= first) {
          EXPECT_EQ(taken_by[first], t);
        }
      }
      if (team == 1) {
        EXPECT_EQ(static_cast<int>(order[0].size()), chunks);
      }
    }
  }
}
