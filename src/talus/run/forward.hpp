#pragma once
// An Observer that forwards the loop's calls to an object with typed calls
// (on_series(state), on_snapshot(state), on_checkpoint(state), flush(),
// whichever it has), the state fixed when it is made: a method's output
// writer, or an analysis bound into an experiment (experiments/bind.hpp).
#include <functional>

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

// A method's files with its checkpoint: at a checkpoint time the files are
// flushed, then `save` writes checkpoint.bin (so that a resumed run finds
// every row written before it).
template <class Target, class State>
class FilesWithCheckpoint final : public Forward<Target, State> {
 public:
  FilesWithCheckpoint(Target& files, const State& state, std::function<void()> save)
      : Forward<Target, State>(files, state), save_(std::move(save)) {}
  void on_checkpoint() override {
    this->target_.flush();
    save_();
  }

 private:
  std::function<void()> save_;
};

}  // namespace talus::run
