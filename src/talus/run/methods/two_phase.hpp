#pragma once
// The two-phase model (runout/grid/two_phase.hpp) on the run loop: as fv2d
// (run/methods/runout.hpp), its steps in segments with the team or one
// thread, ending early once both phases are at rest; without an output folder
// it writes nothing (tests, comparisons), with one it writes the files of
// runout/grid/two_phase_output.hpp and checkpoint.bin.
#include <filesystem>
#include <memory>

#include "talus/run/methods/grid_simulation.hpp"
#include "talus/runout/grid/two_phase_output.hpp"
#include "talus/runout/scenario.hpp"

namespace talus::run {

class TwoPhaseSimulation final
    : public GridSimulation<runout::TwoPhaseSolver, runout::TwoPhaseMaxima, runout::TwoPhaseOutputs,
                            runout::ReleasedVolumes> {
 public:
  explicit TwoPhaseSimulation(runout::RunoutScenario scenario, int threads = 1);
  void start(bool fresh) override;
  void advance(double target, double tolerance, std::int64_t max_steps) override;
  MethodReport report() const override;

 private:
  std::vector<double> normal_heights() const override;  // of the mixture
  // Each phase's vertical depth and momenta per unit density (state's fields).
  std::vector<Field> solver_fields() const override {
    const auto& s = solver_.state();
    return {{"hs", "m", &s.hs}, {"hsu", "m^2/s", &s.hsu}, {"hsv", "m^2/s", &s.hsv},
            {"hf", "m", &s.hf}, {"hfu", "m^2/s", &s.hfu}, {"hfv", "m^2/s", &s.hfv}};
  }
};

}  // namespace talus::run
