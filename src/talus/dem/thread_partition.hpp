#pragma once
// How the threads of a DEM step share the particles and the pair list.
//
// The particles (sorted by cell at each neighbour-list build) are cut into one
// contiguous range per thread, and each thread gets the pairs whose first
// particle lies in its range (pairs are sorted by it, and j > i). A thread
// drifts, scatters and finishes mostly its own particles, so little crosses
// between the cores, and a step needs no barrier between the pair forces and
// the particle passes: a thread finishes the particles that no earlier
// thread's pairs reach at once, waits for those threads' scatter only before
// the rest. Forces on particles that several threads' pairs touch go into
// per-thread buffers, summed in thread order: deterministic for a given
// thread count.
#include <omp.h>

#include <algorithm>
#include <atomic>
#include <cstdint>
#include <thread>
#include <utility>
#include <vector>

#include "talus/dem/neighbour_list.hpp"
#include "talus/dem/particles.hpp"

namespace talus::dem {

template <int D>
class ThreadPartition {
 public:
  using Vec = typename Space<D>::Vec;
  using Rot = typename Space<D>::Rot;

  // One thread's share, and its force buffer.
  struct Share {
    std::vector<Vec> f;
    std::vector<Rot> t;
    std::vector<int> contacts;
    std::size_t k0 = 0, k1 = 0;   // its pairs [k0, k1)
    int p0 = 0, p1 = 0;           // its particles [p0, p1)
    int lo = 0, hi = -1;          // the particles its pairs touch
    int own_lo = 0, own_hi = -1;  // part of [lo, hi] no other thread's pairs touch
    int wait_hi = -1;             // [p0, wait_hi] also gets forces from earlier threads
  };

  // The estimated cost of a particle with `contacts` contacts in the last
  // step and `rows` pair candidates as first particle. Weights from the
  // one-thread profile of the peer case: ~11 ns per particle, ~2.5 ns per
  // candidate, ~10 ns more per touching pair (half to each particle).
  static double cost(int contacts, std::size_t rows) {
    return 11.0 + 5.0 * contacts + 2.5 * static_cast<double>(rows);
  }

  int size() const { return static_cast<int>(shares_.size()); }
  Share& share(int t) { return shares_[t]; }

  // Cuts anew for `nt` threads after a neighbour-list build (or a change of
  // the team or of the particle count); otherwise keeps the cut.
  void prepare(int nt, const Particles<D>& p, const NeighbourList<D>& nl) {
    const int n = static_cast<int>(p.size());
    if (size() == nt && built_ == nl.builds && n_ == n) return;
    shares_.resize(nt);
    cut(nt, p, nl);
    const auto& pairs = nl.pairs;
    for (auto& s : shares_) {
      s.f.resize(n);
      s.t.resize(n);
      s.contacts.resize(n);
      s.lo = n;
      s.hi = -1;
      for (std::size_t k = s.k0; k < s.k1; ++k) {
        s.lo = std::min({s.lo, pairs[k].i, pairs[k].j});
        s.hi = std::max({s.hi, pairs[k].i, pairs[k].j});
      }
    }
    // What lies beyond every other thread's [lo, hi] is the thread's own; an
    // earlier thread's pairs reach up to its hi.
    int reach = -1;
    for (int t = 0; t < nt; ++t) {
      auto& s = shares_[t];
      s.own_lo = s.lo;
      s.own_hi = s.hi;
      for (int u = 0; u < nt; ++u) {
        const auto& o = shares_[u];
        if (u == t || o.hi < o.lo) continue;
        if (u < t) s.own_lo = std::max(s.own_lo, o.hi + 1);
        if (u > t) s.own_hi = std::min(s.own_hi, o.lo - 1);
      }
      s.wait_hi = reach;
      reach = std::max(reach, s.hi);
    }
    if (static_cast<int>(done_.size()) != nt) done_ = std::vector<Flag>(nt);
    built_ = nl.builds;
    n_ = n;
  }

  // The calling thread's particles [first, second): the cut, or equal shares
  // before the first cut or when the team or the particle count changed.
  std::pair<int, int> particle_range(int n) const {
    const int nt = omp_get_num_threads(), t = omp_get_thread_num();
    if (nt <= 1) return {0, n};
    if (size() == nt && n_ == n) return {shares_[t].p0, shares_[t].p1};
    return {static_cast<int>(static_cast<int64_t>(n) * t / nt),
            static_cast<int>(static_cast<int64_t>(n) * (t + 1) / nt)};
  }

  // Zeroes what thread `t` scatters into, over the particles its pairs touch:
  // its own particles' sums in `p`, the rest in its buffer. The own part is
  // one run inside [lo, hi]: three plain loops, no test per particle.
  void clear(int t, Particles<D>& p) {
    auto& s = shares_[t];
    const bool has_own = s.own_lo <= s.own_hi;
    const int own_lo = has_own ? s.own_lo : s.hi + 1, own_hi = has_own ? s.own_hi : s.hi;
    zero(s.f.data(), s.t.data(), s.contacts.data(), s.lo, own_lo);
    zero(p.f.data(), p.t.data(), p.contacts.data(), own_lo, own_hi + 1);
    zero(s.f.data(), s.t.data(), s.contacts.data(), own_hi + 1, s.hi + 1);
  }

  bool owned(int i) const {
    for (const auto& s : shares_)
      if (i >= s.own_lo && i <= s.own_hi) return true;
    return false;
  }

  // Pair forces of the particles in [i0, i1) that are nobody's own: the sum
  // of the buffers in thread order. A pass of its own, apart from the wall
  // contacts: buffers of other threads come from another core's cache, and a
  // tight loop keeps many of those reads in flight. The own runs of the
  // threads are disjoint and in thread order: they are stepped over, not
  // tested particle by particle.
  void sum_buffers(Particles<D>& p, int i0, int i1) const {
    int i = i0;
    for (const auto& s : shares_) {
      if (s.own_hi < s.own_lo) continue;
      for (const int stop = std::min(i1, s.own_lo); i < stop; ++i) sum_one(p, i);
      i = std::max(i, s.own_hi + 1);
    }
    for (; i < i1; ++i) sum_one(p, i);
  }

  // Thread `t` has scattered its pairs of force pass `pass`.
  void mark_scattered(int t, int64_t pass) { done_[t].pass.store(pass, std::memory_order_release); }

  // Spins until every thread before `t` has scattered its pairs of `pass`;
  // yields now and then, in case a thread is not running.
  void wait_for_earlier(int t, int64_t pass) const {
    for (int u = 0; u < t; ++u)
      for (int spins = 0; done_[u].pass.load(std::memory_order_acquire) < pass; ++spins)
        if (spins > 4000) std::this_thread::yield();
  }

 private:
  static void zero(Vec* f, Rot* t, int* contacts, int i0, int i1) {
    for (int i = i0; i < i1; ++i) {
      f[i] = zero_of<Vec>();
      t[i] = Space<D>::rot_zero();
      contacts[i] = 0;
    }
  }

  // Particle i, which no thread owns: the sum of the buffers in thread order.
  void sum_one(Particles<D>& p, int i) const {
    Vec f = zero_of<Vec>();
    Rot t = Space<D>::rot_zero();
    int c = 0;
    for (const auto& s : shares_) {
      if (i < s.lo || i > s.hi) continue;
      f += s.f[i];
      t += s.t[i];
      c += s.contacts[i];
    }
    p.f[i] = f;
    p.t[i] = t;
    p.contacts[i] = c;
  }

  // One cache line per thread.
  struct alignas(64) Flag {
    std::atomic<int64_t> pass{-1};
  };

  // The cut balances cost() over the threads, with the contacts as counted in
  // the last step. Deterministic: it depends on the state only.
  void cut(int nt, const Particles<D>& p, const NeighbourList<D>& nl) {
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
    k = 0;
    for (int t = 0; t < nt; ++t) {
      auto& s = shares_[t];
      const double target = cost_[n] * t / nt;
      s.p0 = t == 0 ? 0
                    : static_cast<int>(std::lower_bound(cost_.begin(), cost_.end(), target) -
                                       cost_.begin());
      s.p0 = std::clamp(s.p0, t == 0 ? 0 : shares_[t - 1].p0, n);
      while (k < np && pairs[k].i < s.p0) ++k;
      s.k0 = k;
      if (t > 0) {
        shares_[t - 1].p1 = s.p0;
        shares_[t - 1].k1 = k;
      }
    }
    shares_[nt - 1].p1 = n;
    shares_[nt - 1].k1 = np;
  }

  std::vector<Share> shares_;
  std::vector<Flag> done_;
  std::vector<double> cost_;  // cumulative cost of the particles
  int built_ = -1;            // neighbour-list build of the cut
  int n_ = -1;                // particle count of the cut
};

}  // namespace talus::dem
