#pragma once
// Binds an analysis object to the loop: its typed calls (on_series(run),
// on_checkpoint(run), finish(run) or finish(), whichever it has) become an
// Experiment's, with the state it reads fixed at attachment.
#include <memory>
#include <string>
#include <utility>

#include "talus/run/experiment.hpp"
#include "talus/run/forward.hpp"

namespace talus::run {

template <class Analysis, class State>
class Bound : public Experiment {
 public:
  Bound(std::string name, std::unique_ptr<Analysis> analysis, const State& state)
      : name_(std::move(name)), a_(std::move(analysis)), calls_(*a_, state), state_(state) {}

  std::string name() const override { return name_; }
  void on_series() override { calls_.on_series(); }
  void on_snapshot() override { calls_.on_snapshot(); }
  void on_checkpoint() override { calls_.on_checkpoint(); }
  nlohmann::json finish() override {
    if constexpr (requires { a_->finish(state_); })
      return a_->finish(state_);
    else
      return a_->finish();
  }

 private:
  std::string name_;
  std::unique_ptr<Analysis> a_;
  Forward<Analysis, State> calls_;
  const State& state_;
};

template <class Analysis, class State>
std::unique_ptr<Experiment> bind_analysis(std::string name, std::unique_ptr<Analysis> analysis,
                                          const State& state) {
  return std::make_unique<Bound<Analysis, State>>(std::move(name), std::move(analysis), state);
}

// The simulation as a method's type, or null when it runs another method.
template <class Sim>
Sim* as(Simulation& sim) {
  return dynamic_cast<Sim*>(&sim);
}

}  // namespace talus::run
