#pragma once
// How the threads of a DEM step share the particles and the pair list.
//
// The particles (sorted by cell at each neighbour-list build) are cut into
// contiguous chunks, kChunksPerThread per thread asked for, and each chunk gets
// the pairs whose first particle lies in it (pairs are sorted by it, and
// j > i). Each thread takes its own chunks first (the same every step: its
// particles stay in its core's cache), then, with more than one chunk per
// thread, chunks other threads have not yet taken (ChunkClaims); one thread
// alone takes them all. A step needs no barrier between the pair
// forces and the particle passes: a chunk finishes the particles that no
// earlier chunk's pairs reach at once, and the rest once those chunks have
// scattered their pairs; a thread scatters all the chunks it takes before it
// waits for any, so no scatter waits and no thread waits on a chunk nobody
// has started. Forces on particles that several chunks' pairs touch
// go into per-chunk buffers, summed in chunk order; which thread computes a
// chunk does not change a bit: results are deterministic for a given number
// of chunks, that is for a given thread count.
#include <algorithm>
#include <atomic>
#include <cstdint>
#include <memory>
#include <utility>
#include <vector>

#include "talus/core/team_sync.hpp"
#include "talus/dem/chunk_cut.hpp"
#include "talus/dem/neighbour_list.hpp"
#include "talus/dem/particles.hpp"

namespace talus::dem {

// Chunks per thread asked for. More would let a fast thread take a slowed
// one's work in pieces, but each cut adds a slab of shared particles: on the
// quiet 2-vCPU machine two per thread cost 4 %, four 13 % of a two-thread step.
// With one, no chunk is ever taken from another thread (ChunkClaims' rule),
// and a slowed thread is handled by running alone (core/adaptive_team.hpp).
inline constexpr int kChunksPerThread = 1;

// Which thread computes which chunk in one pass: thread t's own chunks are
// [chunks t / team, chunks (t + 1) / team); it takes them from the front, and
// others take them from the back once theirs are gone, while it has at least
// two left (a thread one chunk behind is about to take its last: taking it
// would cost the chunk's cache, not save time). Which thread takes a chunk
// changes nothing in the results, only who waits.
class ChunkClaims {
 public:
  // Hands out `chunks` chunks anew to a team of `team`; call while no thread takes.
  void reset(int team, int chunks) {
    if (team != team_) {
      ranges_ = std::make_unique<Range[]>(team);
      team_ = team;
    }
    for (int t = 0; t < team; ++t)
      ranges_[t].bounds.store(pack(static_cast<uint32_t>(int64_t{chunks} * t / team),
                                   static_cast<uint32_t>(int64_t{chunks} * (t + 1) / team)),
                              std::memory_order_relaxed);
  }

  // A chunk for thread `tid`, or -1 when none is left.
  int take(int tid) {
    if (const int c = take_end(ranges_[tid], true); c >= 0) return c;
    for (int k = 1; k < team_; ++k)
      if (const int c = take_end(ranges_[(tid + k) % team_], false); c >= 0) return c;
    return -1;
  }

 private:
  // [front, back) of a thread's untaken chunks, in one word.
  struct alignas(64) Range {
    std::atomic<uint64_t> bounds{0};
  };
  static uint64_t pack(uint32_t front, uint32_t back) { return (uint64_t{back} << 32) | front; }

  static int take_end(Range& r, bool front) {
    uint64_t b = r.bounds.load(std::memory_order_relaxed);
    for (;;) {
      const auto lo = static_cast<uint32_t>(b), hi = static_cast<uint32_t>(b >> 32);
      if (lo >= hi || (!front && hi - lo < 2)) return -1;
      const uint64_t next = front ? pack(lo + 1, hi) : pack(lo, hi - 1);
      if (r.bounds.compare_exchange_weak(b, next, std::memory_order_relaxed))
        return static_cast<int>(front ? lo : hi - 1);
    }
  }

  std::unique_ptr<Range[]> ranges_;
  int team_ = 0;
};

template <int D>
class ChunkPartition {
 public:
  using Vec = typename Space<D>::Vec;
  using Rot = typename Space<D>::Rot;

  // One chunk, and its force buffer over the particles [lo, hi] its pairs touch.
  struct Chunk {
    std::vector<Vec> f;
    std::vector<Rot> t;
    std::vector<int> contacts;
    std::size_t k0 = 0, k1 = 0;   // its pairs [k0, k1)
    int p0 = 0, p1 = 0;           // its particles [p0, p1)
    int lo = 0, hi = -1;          // the particles its pairs touch
    int own_lo = 0, own_hi = -1;  // part of [lo, hi] no other chunk's pairs touch
    int wait_hi = -1;             // [p0, wait_hi] also gets forces from earlier chunks
    int first_reach = 0;          // the first chunk whose pairs reach [p0, p1)
  };

  // The estimated cost of a particle with `contacts` contacts in the last
  // step and `rows` pair candidates as first particle. Weights from the
  // one-thread profile of the peer case: ~11 ns per particle, ~2.5 ns per
  // candidate, ~10 ns more per touching pair (half to each particle).
  static double cost(int contacts, std::size_t rows) {
    return 11.0 + 5.0 * contacts + 2.5 * static_cast<double>(rows);
  }

  int size() const { return static_cast<int>(chunks_.size()); }
  Chunk& chunk(int c) { return chunks_[c]; }
  const Chunk& chunk(int c) const { return chunks_[c]; }

  // Cuts anew into `nc` chunks after a neighbour-list build (or a change of
  // the chunk count or of the particle count); otherwise keeps the cut.
  void prepare(int nc, const Particles<D>& p, const NeighbourList<D>& nl) {
    prepare(nc, p, nl, scratch_cut_);
  }

  // The same, where `kept` holds the cut of the run's state (DemSystem): a
  // cut made for this build, particle count and chunk count is taken from it
  // rather than made anew from the contacts of the moment (a resumed run then
  // sums its forces as the uninterrupted one did); a new cut is stored there.
  void prepare(int nc, const Particles<D>& p, const NeighbourList<D>& nl, ChunkCut& kept) {
    const int n = static_cast<int>(p.size());
    if (size() == nc && built_ == nl.builds && n_ == n) return;
    chunks_.resize(nc);
    if (kept.build != nl.builds || kept.particles != n ||
        kept.starts.size() != static_cast<std::size_t>(nc)) {
      cut(nc, p, nl, kept.starts);
      kept.build = nl.builds;
      kept.particles = n;
    }
    cut_at(kept.starts, p, nl);
    const auto& pairs = nl.pairs;
    for (auto& s : chunks_) {
      s.lo = n;
      s.hi = -1;
      for (std::size_t k = s.k0; k < s.k1; ++k) {
        s.lo = std::min({s.lo, pairs[k].i, pairs[k].j});
        s.hi = std::max({s.hi, pairs[k].i, pairs[k].j});
      }
      const std::size_t span = s.hi >= s.lo ? static_cast<std::size_t>(s.hi - s.lo + 1) : 0;
      s.f.resize(span);
      s.t.resize(span);
      s.contacts.resize(span);
    }
    // What lies beyond every other chunk's [lo, hi] is the chunk's own; an
    // earlier chunk's pairs reach up to its hi.
    int reach = -1;
    for (int c = 0; c < nc; ++c) {
      auto& s = chunks_[c];
      s.own_lo = s.lo;
      s.own_hi = s.hi;
      for (int u = 0; u < nc; ++u) {
        const auto& o = chunks_[u];
        if (u == c || o.hi < o.lo) continue;
        if (u < c) s.own_lo = std::max(s.own_lo, o.hi + 1);
        if (u > c) s.own_hi = std::min(s.own_hi, o.lo - 1);
      }
      s.wait_hi = reach;
      reach = std::max(reach, s.hi);
      s.first_reach = c;
      for (int u = c - 1; u >= 0; --u)
        if (chunks_[u].hi >= s.p0) s.first_reach = u;
    }
    if (static_cast<int>(scattered_.size()) != nc) {
      scattered_ = std::vector<Flag>(nc);
      finished_ = std::vector<Flag>(nc);
    }
    built_ = nl.builds;
    n_ = n;
  }

  // Who computes which chunk in the force pass and in the drift; each is
  // reset by the serial part before its pass.
  ChunkClaims force_claims, drift_claims;

  // Zeroes what chunk `c` scatters into, over the particles its pairs touch:
  // its own particles' sums in `p`, the rest in its buffer. The own part is
  // one run inside [lo, hi]: three plain loops, no test per particle.
  void clear(int c, Particles<D>& p) {
    auto& s = chunks_[c];
    const bool has_own = s.own_lo <= s.own_hi;
    const int own_lo = has_own ? s.own_lo : s.hi + 1, own_hi = has_own ? s.own_hi : s.hi;
    zero(s.f.data(), s.t.data(), s.contacts.data(), 0, own_lo - s.lo);
    zero(p.f.data(), p.t.data(), p.contacts.data(), own_lo, own_hi + 1);
    zero(s.f.data(), s.t.data(), s.contacts.data(), own_hi + 1 - s.lo, s.hi + 1 - s.lo);
  }

  bool owned(int i) const {
    for (const auto& s : chunks_)
      if (i >= s.own_lo && i <= s.own_hi) return true;
    return false;
  }

  // Pair forces of the particles in [i0, i1) of chunk `c` that are nobody's
  // own: the sum of the buffers in chunk order. A pass of its own, apart from the wall
  // contacts: buffers of other chunks come from another core's cache, and a
  // tight loop keeps many of those reads in flight. The own runs of the
  // chunks are disjoint and in chunk order: they are stepped over, not
  // tested particle by particle.
  void sum_buffers(Particles<D>& p, int c, int i0, int i1) const {
    const int u0 = chunks_[c].first_reach;
    int i = i0;
    for (const auto& s : chunks_) {
      if (s.own_hi < s.own_lo) continue;
      for (const int stop = std::min(i1, s.own_lo); i < stop; ++i) sum_one(p, u0, c, i);
      i = std::max(i, s.own_hi + 1);
    }
    for (; i < i1; ++i) sum_one(p, u0, c, i);
  }

  // Chunk `c` has scattered its pairs of force pass `pass`.
  void mark_scattered(int c, int64_t pass) { publish(scattered_[c], pass); }
  // Chunk `c`'s particles are complete (forces and kick) for `pass`.
  void mark_finished(int c, int64_t pass) { publish(finished_[c], pass); }

  // Returns once every earlier chunk whose pairs reach chunk `c`'s particles
  // has scattered its pairs of `pass`; true when it had to sleep.
  bool wait_for_earlier(int c, int64_t pass) const {
    const auto value = static_cast<uint32_t>(pass);
    bool slept = false;
    for (int u = 0; u < c; ++u)
      if (chunks_[u].hi >= chunks_[c].p0) slept |= wait_for_value(scattered_[u].pass, value);
    return slept;
  }

  // Returns once chunk `c`'s particles are complete for `pass` (before the
  // next step moves them, on whichever thread); true when it had to sleep.
  bool wait_for_finished(int c, int64_t pass) const {
    return wait_for_value(finished_[c].pass, static_cast<uint32_t>(pass));
  }

 private:
  // One cache line per chunk. The pass is kept modulo 2^32 (a futex word): a
  // flag never runs more than one pass ahead of a thread waiting on it.
  struct alignas(64) Flag {
    std::atomic<uint32_t> pass{~0u};
  };

  static void publish(Flag& flag, int64_t pass) {
    flag.pass.store(static_cast<uint32_t>(pass), std::memory_order_release);
    flag.pass.notify_all();
  }

  static void zero(Vec* f, Rot* t, int* contacts, int i0, int i1) {
    for (int i = i0; i < i1; ++i) {
      f[i] = zero_of<Vec>();
      t[i] = Space<D>::rot_zero();
      contacts[i] = 0;
    }
  }

  // Particle i, which no chunk owns: the sum of the buffers in chunk order.
  // Only chunks [u0, c] can touch it (later chunks' pairs start after it).
  void sum_one(Particles<D>& p, int u0, int c, int i) const {
    Vec f = zero_of<Vec>();
    Rot t = Space<D>::rot_zero();
    int n = 0;
    for (int u = u0; u <= c; ++u) {
      const auto& s = chunks_[u];
      if (i < s.lo || i > s.hi) continue;
      f += s.f[i - s.lo];
      t += s.t[i - s.lo];
      n += s.contacts[i - s.lo];
    }
    p.f[i] = f;
    p.t[i] = t;
    p.contacts[i] = n;
  }

  // The first particle of each of `nc` chunks, balancing cost() over them
  // with the contacts as counted in the last step. Deterministic: it depends
  // on the state only.
  void cut(int nc, const Particles<D>& p, const NeighbourList<D>& nl,
           std::vector<int32_t>& starts) {
    const int n = static_cast<int>(p.size());
    const auto& pairs = nl.pairs;
    const std::size_t np = pairs.size();
    // Pairs are sorted by their first particle: its rows are consecutive.
    cost_.assign(static_cast<std::size_t>(n) + 1, 0.0);
    std::size_t k = 0;
    for (int i = 0; i < n; ++i) {
      const std::size_t first = k;
      while (k < np && pairs[k].i == i) ++k;
      cost_[i + 1] = cost_[i] + cost(p.contacts[i], k - first);
    }
    starts.resize(nc);
    for (int c = 0; c < nc; ++c) {
      const double target = cost_[n] * c / nc;
      const int p0 = c == 0
                         ? 0
                         : static_cast<int>(std::lower_bound(cost_.begin(), cost_.end(), target) -
                                            cost_.begin());
      starts[c] = std::clamp(p0, c == 0 ? 0 : starts[c - 1], n);
    }
  }

  // Chunk c's particles start at starts[c] (ascending, starts[0] = 0); its
  // pairs are those whose first particle it holds.
  void cut_at(const std::vector<int32_t>& starts, const Particles<D>& p,
              const NeighbourList<D>& nl) {
    const int n = static_cast<int>(p.size()), nc = size();
    const auto& pairs = nl.pairs;
    const std::size_t np = pairs.size();
    std::size_t k = 0;
    for (int c = 0; c < nc; ++c) {
      auto& s = chunks_[c];
      s.p0 = static_cast<int>(starts[c]);
      while (k < np && pairs[k].i < s.p0) ++k;
      s.k0 = k;
      if (c > 0) {
        chunks_[c - 1].p1 = s.p0;
        chunks_[c - 1].k1 = k;
      }
    }
    chunks_[nc - 1].p1 = n;
    chunks_[nc - 1].k1 = np;
  }

  std::vector<Chunk> chunks_;
  std::vector<Flag> scattered_, finished_;
  std::vector<double> cost_;  // cumulative cost of the particles
  ChunkCut scratch_cut_;      // for callers that keep no cut of their own
  int built_ = -1;            // neighbour-list build of the cut
  int n_ = -1;                // particle count of the cut
};

}  // namespace talus::dem
