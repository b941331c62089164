#pragma once
// The two-phase model (runout/grid/two_phase.hpp) on the run loop: as fv2d
// (run/methods/runout.hpp), its steps in segments with the team or one
// thread, ending early once both phases are at rest; without an output folder
// it writes nothing (tests, comparisons), with one it writes the files of
// runout/grid/two_phase_output.hpp and checkpoint.bin.
#include <filesystem>
#include <memory>

#include "talus/core/team_segments.hpp"
#include "talus/run/methods/runout.hpp"
#include "talus/run/simulation.hpp"
#include "talus/runout/checkpoint.hpp"
#include "talus/runout/grid/two_phase_output.hpp"
#include "talus/runout/scenario.hpp"

namespace talus::run {

class TwoPhaseSimulation : public Simulation {
 public:
  explicit TwoPhaseSimulation(runout::RunoutScenario scenario, int threads = 1);
  // Writes the run's files into `out`; resume = true first restores the state
  // from out/checkpoint.bin and continues the files.
  void write_to(const std::filesystem::path& out, bool resume = false);

  double time() const override { return solver_.state().time; }
  std::int64_t steps() const override { return steps_; }
  double end_time() const override { return scenario_.control.duration; }
  double time_step() const override { return last_dt_ > 0 ? last_dt_ : 1e-2; }
  double kinetic_energy() const override { return solver_.kinetic_energy(); }
  double estimated_steps() const override;
  Schedules schedules() const override;
  void start(bool fresh) override;
  void advance(double target, double tolerance, std::int64_t max_steps) override;
  bool stopped() const override { return stopped_; }
  Observer& outputs() override { return *outputs_; }
  void after_series() override;
  void finish() override;
  MethodReport report() const override;

  const runout::TwoPhaseSolver& solver() const { return solver_; }
  const runout::TwoPhaseMaxima& maxima() const { return maxima_; }

 private:
  std::vector<double> normal_heights() const;  // of the mixture
  runout::RunoutScenario scenario_;
  runout::TwoPhaseSolver solver_;
  runout::TwoPhaseMaxima maxima_;
  GridPathResults path_;
  std::unique_ptr<runout::TwoPhaseOutputs> files_;
  std::unique_ptr<Observer> outputs_;
  std::filesystem::path checkpoint_;  // empty: no files
  int threads_;
  TeamSegments segments_;
  runout::ReleasedVolumes released_;
  std::int64_t steps_ = 0;
  double last_dt_ = 0.0;
  bool stopped_ = false;
};

}  // namespace talus::run
