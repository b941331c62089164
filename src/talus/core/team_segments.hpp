#pragma once
// The segment loop of a method whose steps run with the whole team or one
// thread (core/adaptive_team.hpp): begin() picks the team for the next
// segment and releases libgomp's idle threads when going alone; end() times
// the segment and records it. DEM, MPM and fv2d step this way:
//
//   for (done = 0; done < steps;) {
//     const int64_t n = segments.begin(steps - done);
//     ... n steps with segments.team() threads ...
//     segments.end(n);
//     done += n;
//   }
//
// TeamSize sets OpenMP's default team size (for `parallel for` loops that do
// not name one) for as long as it lives.
#include <omp.h>
#include <sys/resource.h>

#include <algorithm>
#include <chrono>
#include <cstdint>
#include <optional>

#include "talus/core/adaptive_team.hpp"

namespace talus {

class TeamSegments {
 public:
  explicit TeamSegments(int threads) : threads_(std::max(1, threads)), adaptive_(threads_) {}

  // Starts a segment of at most `left` steps and returns its length (all of
  // `left` for one thread: nothing to choose).
  int64_t begin(int64_t left) {
    team_ = adaptive_.team();
    // libgomp's idle threads spin for milliseconds after a parallel region,
    // on the core the one working thread or the competing process needs:
    // going alone, release them (they are made anew for the next team).
    if (threads_ > 1 && team_ == 1 && last_team_ > 1) omp_pause_resource_all(omp_pause_soft);
    last_team_ = team_;
    start_ = Clock::now();
    switches_ = involuntary_switches();
    return threads_ > 1 ? std::min(left, adaptive_.segment_steps()) : left;
  }
  // The threads of the current segment.
  int team() const { return team_; }
  // Ends the segment after `steps` steps. `held_up`: the caller's own sign that
  // its threads waited for each other (AdaptiveTeam::sleepy); without it, the
  // kernel taking the process's cores often (AdaptiveTeam::preempted).
  void end(int64_t steps, std::optional<bool> held_up = std::nullopt) {
    const double seconds = std::chrono::duration<double>(Clock::now() - start_).count();
    const bool slowed =
        held_up ? *held_up : AdaptiveTeam::preempted(involuntary_switches() - switches_, seconds);
    adaptive_.record(team_, steps, seconds, slowed);
  }

 private:
  using Clock = std::chrono::steady_clock;
  // Times the kernel took a core from this process's threads so far.
  static int64_t involuntary_switches() {
    rusage ru{};
    getrusage(RUSAGE_SELF, &ru);
    return ru.ru_nivcsw;
  }

  int threads_;
  AdaptiveTeam adaptive_;
  int team_ = 1, last_team_ = 0;
  Clock::time_point start_;
  int64_t switches_ = 0;
};

// OpenMP's default team size while it lives (restored to `threads` after).
class TeamSize {
 public:
  explicit TeamSize(int threads) : threads_(threads) {}
  void set(int team) {
    if (threads_ > 1) omp_set_num_threads(team);
  }
  ~TeamSize() { set(threads_); }
  TeamSize(const TeamSize&) = delete;
  TeamSize& operator=(const TeamSize&) = delete;

 private:
  int threads_;
};

// Up to max_steps steps in segments, each with the team `segments` picks:
// `step()` takes one step and returns true, or returns false without stepping
// when the caller is done (its target reached, the run stopped). For methods
// whose every loop is per cell or a max, so the bits do not depend on the team.
template <class Step>
void step_in_segments(int threads, TeamSegments& segments, int64_t max_steps, Step&& step) {
  TeamSize size(threads);
  for (int64_t taken = 0; taken < max_steps;) {
    const int64_t segment = segments.begin(max_steps - taken);
    size.set(segments.team());
    int64_t stepped = 0;
    bool more = true;
    while (stepped < segment && (more = step())) ++stepped;
    taken += stepped;
    segments.end(stepped);
    if (!more || stepped == 0) break;
  }
}

}  // namespace talus
