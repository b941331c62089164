// The granular beam in three- or four-point bending ([beam], 3D DEM).
#include "talus/analysis/beam.hpp"

#include "talus/analysis/beam_four_point.hpp"
#include "talus/run/experiments/bind.hpp"
#include "talus/run/experiments/experiments.hpp"
#include "talus/run/methods/dem.hpp"

namespace talus::run {

ExperimentKind beam_experiment() {
  return {"beam", [](Simulation& sim, const RunContext& ctx) -> std::unique_ptr<Experiment> {
            auto* dem = as<DemSimulation<3>>(sim);
            if (!dem || !dem->scenario() || !dem->scenario()->beam) return nullptr;
            const auto& sc = *dem->scenario();
            const auto& s = dem->dem_run().system;
            if (sc.beam->test == dem::BeamTest::ThreePoint)
              return bind_analysis("beam", std::make_unique<analysis::BeamObserver>(ctx.out, sc, s),
                                   dem->dem_run());
            return bind_analysis("beam",
                                 std::make_unique<analysis::FourPointObserver>(ctx.out, sc, s),
                                 dem->dem_run());
          }};
}

}  // namespace talus::run
