#pragma once
// An Observer that forwards the loop's calls to an object with typed calls
// (on_series(state), on_snapshot(state), on_checkpoint(state), flush(),
// whichever it has), the state fixed when it is made: a method's output
// writer, or an analysis bound into an experiment (experiments/bind.hpp).
#include "talus/run/observer.hpp"

namespace talus::run {

template <class Target, class State>
class Forward : public Observer {
 public:
  Forward(Target& target, const State& state) : target_(target), state_(state) {}

  void on_series() override {
    if constexpr (requires { target_.on_series(state_); }) target_.on_series(state_);
  }
  void on_snapshot() override {
    if constexpr (requires { target_.on_snapshot(state_); }) target_.on_snapshot(state_);
  }
  void on_checkpoint() override {
    if constexpr (requires { target_.on_checkpoint(state_); }) target_.on_checkpoint(state_);
  }
  void on_progress() override {
    if constexpr (requires { target_.flush(); }) target_.flush();
  }

 protected:
  Target& target_;
  const State& state_;
};

}  // namespace talus::run
