// The hollow sphere compressed between plates ([hollow_sphere], 3D DEM).
#include "talus/analysis/hollow_sphere.hpp"

#include "talus/run/experiments/bind.hpp"
#include "talus/run/experiments/experiments.hpp"
#include "talus/run/methods/dem.hpp"

namespace talus::run {

ExperimentKind hollow_sphere_experiment() {
  return {"hollow_sphere",
          [](Simulation& sim, const RunContext& ctx) -> std::unique_ptr<Experiment> {
            auto* dem = as<DemSimulation<3>>(sim);
            if (!dem || !dem->scenario() || !dem->scenario()->hollow_sphere) return nullptr;
            const auto& s = dem->dem_run().system;
            return bind_analysis("hollow_sphere",
                                 std::make_unique<analysis::HollowSphereObserver>(
                                     ctx.out, *dem->scenario(), s, ctx.resume, s.time),
                                 dem->dem_run());
          }};
}

}  // namespace talus::run
