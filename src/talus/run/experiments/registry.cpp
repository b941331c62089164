#include "talus/run/experiments/experiments.hpp"

namespace talus::run {

const std::vector<ExperimentKind>& experiments() {
  // One line per experiment.
  static const std::vector<ExperimentKind> all = {
      flume_experiment(),         dam_break_experiment(), triaxial_experiment(),
      hollow_sphere_experiment(), gripper_experiment(),   beam_experiment(),
  };
  return all;
}

std::vector<std::unique_ptr<Experiment>> attach_experiments(Simulation& sim,
                                                            const RunContext& ctx) {
  std::vector<std::unique_ptr<Experiment>> attached;
  for (const auto& kind : experiments())
    if (auto e = kind.attach(sim, ctx)) attached.push_back(std::move(e));
  return attached;
}

}  // namespace talus::run
