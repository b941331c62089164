#pragma once
// Whether a run's threads work as a team or one thread works alone, chosen
// segment by segment from the measured speed of each.
//
// On a machine where another process competes for a core, a team whose
// threads meet every step runs at the pace of the thread that lost its core:
// two threads can be several times slower than one. A method whose results do
// not depend on how many threads compute them (DEM's chunks,
// dem/chunk_partition.hpp) can switch freely: it runs segments of about
// kSegmentSeconds, mostly with the faster choice, and now and then one with
// the other to see whether things have changed. The team is only tried
// against one thread when the caller saw it held up: its threads had to sleep
// waiting for each other (core/team_sync.hpp) in at least a kSleepyShare of
// its steps, or the kernel took their cores often (involuntary context
// switches, at least one per kPreemptedEvery). On a quiet machine neither
// happens, and every segment runs the whole team. A probe that loses makes the
// next one twice as rare (up to every kMaxProbeEvery segments).
//
// TALUS_TEAM=team or TALUS_TEAM=alone in the environment fixes the choice
// (benchmarks, tests); results are the same bits either way.
#include <algorithm>
#include <cstdint>
#include <cstdlib>
#include <string_view>

namespace talus {

class AdaptiveTeam {
 public:
  static constexpr double kSegmentSeconds = 0.05;
  static constexpr int kFirstProbeEvery = 2, kMaxProbeEvery = 128;
  // A probe must beat the current choice by this factor to replace it.
  static constexpr double kSwitchMargin = 1.05;
  static constexpr double kSleepyShare = 0.25;
  static constexpr double kPreemptedEvery = 8e-3;  // s

  // Signs of a held-up team, for record().
  static bool sleepy(int64_t sleeps, int64_t steps) {
    return static_cast<double>(sleeps) >= kSleepyShare * static_cast<double>(steps);
  }
  static bool preempted(int64_t involuntary_switches, double seconds) {
    return static_cast<double>(involuntary_switches) * kPreemptedEvery >= seconds;
  }

  explicit AdaptiveTeam(int threads) : threads_(std::max(1, threads)) {
    const char* env = std::getenv("TALUS_TEAM");
    const std::string_view fixed = env ? env : "";
    if (fixed == "team") fixed_ = threads_;
    if (fixed == "alone") fixed_ = 1;
  }

  // The team size for the next segment: all threads, or 1.
  int team() const {
    if (fixed_ > 0) return fixed_;
    return threads_ > 1 && (use_team_ != probing_) ? threads_ : 1;
  }
  // The steps of the next segment (about kSegmentSeconds at the speed last
  // measured with its team size: a probe of a slowed team stays short too).
  int64_t segment_steps() const { return segment_[team() > 1]; }

  // A segment of `steps` steps took `seconds` with `team` threads; `held_up`:
  // the caller saw signs that a thread lost its core (sleepy(), preempted()).
  void record(int team, int64_t steps, double seconds, bool held_up) {
    // A segment of a few steps (the end of an output interval) is noise.
    if (threads_ <= 1 || steps < 4 || !(seconds > 0.0)) return;
    const double rate = static_cast<double>(steps) / seconds;
    const bool was_team = team > 1;
    segment_[was_team] =
        std::clamp<int64_t>(static_cast<int64_t>(rate * kSegmentSeconds), 4, 1 << 20);
    if (probing_) {
      probing_ = false;
      if (rate > kSwitchMargin * rate_[use_team_]) {
        use_team_ = was_team;
        probe_every_ = kFirstProbeEvery;
      } else {
        probe_every_ = std::min(2 * probe_every_, kMaxProbeEvery);
      }
      rate_[was_team] = rate;
      return;
    }
    rate_[was_team] = rate;
    if (was_team && !held_up) {
      since_probe_ = 0;  // nothing suggests a thread is held up
      return;
    }
    if (++since_probe_ >= probe_every_) {
      since_probe_ = 0;
      probing_ = true;
    }
  }

  bool uses_team() const { return use_team_; }

 private:
  int threads_;
  int fixed_ = 0;         // TALUS_TEAM's choice, 0 = none
  bool use_team_ = true;  // the current choice
  bool probing_ = false;  // the next segment tries the other one
  int since_probe_ = 0, probe_every_ = kFirstProbeEvery;
  int64_t segment_[2] = {16, 16};  // steps alone [0] and as a team [1]
  double rate_[2] = {0.0, 0.0};    // last measured steps/s alone [0] and as a team [1]
};

}  // namespace talus
