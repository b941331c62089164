#pragma once
// Waiting for the other threads of a team without taking the core they need.
//
// OpenMP's barriers in libgomp spin for a long time before they sleep (about
// 300 000 rounds unless OMP_WAIT_POLICY is set): on a machine where another
// process competes for a core, a waiting thread then burns the time slice its
// partner needs to arrive, and two threads run slower than one. The waits here
// spin briefly (a running partner arrives within microseconds), then sleep in
// the kernel (std::atomic::wait, a futex on Linux) until they are notified.
#include <atomic>
#include <chrono>
#include <cstdint>

#if defined(__x86_64__) || defined(__i386__)
#include <immintrin.h>
#endif

namespace talus {

// How long a wait spins before it sleeps: longer than the imbalance of a
// step on a quiet machine (microseconds), far shorter than the time slice
// (milliseconds) of a thread that lost its core.
inline constexpr std::chrono::microseconds kSpinTime{50};

inline void cpu_relax() {
#if defined(__x86_64__) || defined(__i386__)
  _mm_pause();
#endif
}

// Returns once `a` holds `value`: spins briefly, then sleeps until notified;
// the return value says whether it had to sleep (a sign of a partner that
// lost its core). Whoever stores the awaited value must call a.notify_all().
template <class T>
bool wait_for_value(const std::atomic<T>& a, T value) {
  using Clock = std::chrono::steady_clock;
  const auto until = Clock::now() + kSpinTime;
  for (int round = 1;; ++round) {
    if (a.load(std::memory_order_acquire) == value) return false;
    cpu_relax();
    if (round % 32 == 0 && Clock::now() > until) break;
  }
  bool slept = false;
  for (T seen = a.load(std::memory_order_acquire); seen != value;
       seen = a.load(std::memory_order_acquire)) {
    a.wait(seen, std::memory_order_acquire);
    slept = true;
  }
  return slept;
}

// A barrier for a team of threads whose last arriving thread runs a serial
// part before it releases the others: one synchronisation where an OpenMP
// barrier followed by `single` needs two. The serial part runs on whichever
// thread comes last, so it must not depend on the thread's number.
class TeamBarrier {
 public:
  // Sets the team size; call while no thread waits.
  void reset(int team) {
    team_ = team;
    arrived_.store(0, std::memory_order_relaxed);
  }

  // Returns whether this thread had to sleep (wait_for_value).
  template <class Serial>
  bool arrive_and_wait(Serial&& serial) {
    const uint32_t generation = generation_.load(std::memory_order_acquire);
    if (arrived_.fetch_add(1, std::memory_order_acq_rel) + 1 == team_) {
      serial();
      arrived_.store(0, std::memory_order_relaxed);
      generation_.store(generation + 1, std::memory_order_release);
      generation_.notify_all();
      return false;
    }
    return wait_for_value(generation_, generation + 1);
  }

 private:
  int team_ = 1;
  std::atomic<int> arrived_{0};
  std::atomic<uint32_t> generation_{0};
};

}  // namespace talus
