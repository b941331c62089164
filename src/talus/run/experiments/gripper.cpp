// The granular gripper: a membrane bag jammed around an object and lifted
// ([gripper], 3D DEM).
#include "talus/analysis/gripper.hpp"

#include "talus/run/experiments/bind.hpp"
#include "talus/run/experiments/experiments.hpp"
#include "talus/run/methods/dem.hpp"

namespace talus::run {

ExperimentKind gripper_experiment() {
  return {"gripper", [](Simulation& sim, const RunContext& ctx) -> std::unique_ptr<Experiment> {
            auto* dem = as<DemSimulation<3>>(sim);
            if (!dem || !dem->scenario() || !dem->scenario()->gripper) return nullptr;
            return bind_analysis("gripper",
                                 std::make_unique<analysis::GripperObserver>(
                                     ctx.out, *dem->scenario(), dem->dem_run().system),
                                 dem->dem_run());
          }};
}

}  // namespace talus::run
