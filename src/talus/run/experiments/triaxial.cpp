// The triaxial test of a membrane-wrapped sample ([triaxial], 3D DEM):
// stress-strain curve, volume change and the summary's triaxial block.
#include "talus/analysis/triaxial.hpp"

#include "talus/run/experiments/bind.hpp"
#include "talus/run/experiments/experiments.hpp"
#include "talus/run/methods/dem.hpp"

namespace talus::run {

ExperimentKind triaxial_experiment() {
  return {"triaxial", [](Simulation& sim, const RunContext& ctx) -> std::unique_ptr<Experiment> {
            auto* dem = as<DemSimulation<3>>(sim);
            if (!dem || !dem->scenario() || !dem->scenario()->triaxial) return nullptr;
            const auto& s = dem->dem_run().system;
            return bind_analysis("triaxial",
                                 std::make_unique<analysis::TriaxialObserver>(
                                     ctx.out, *dem->scenario(), s, ctx.resume, s.time),
                                 dem->dem_run());
          }};
}

}  // namespace talus::run
