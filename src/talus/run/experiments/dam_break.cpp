// The dam-break test ([dam_break], 2D DEM): the deposit's angles and run-out
// at the end of the run, against Götz's column.
#include "talus/analysis/dam_break.hpp"

#include "talus/run/experiments/bind.hpp"
#include "talus/run/experiments/experiments.hpp"
#include "talus/run/methods/dem.hpp"

namespace talus::run {

namespace {

class DamBreak final : public Experiment {
 public:
  DamBreak(const DemSimulation<2>& sim, const dem::DamBreakParams& params,
           std::filesystem::path out)
      : sim_(sim), params_(params), out_(std::move(out)) {}
  std::string name() const override { return "dam_break"; }
  nlohmann::json finish() override {
    const auto& p = sim_.dem_run().system.particles;
    return analysis::report_dam_break(analysis::Grains{p.x, p.r}, params_, out_);
  }

 private:
  const DemSimulation<2>& sim_;
  dem::DamBreakParams params_;
  std::filesystem::path out_;
};

}  // namespace

ExperimentKind dam_break_experiment() {
  return {"dam_break", [](Simulation& sim, const RunContext& ctx) -> std::unique_ptr<Experiment> {
            auto* dem = as<DemSimulation<2>>(sim);
            if (!dem || !dem->scenario() || !dem->scenario()->dam_break) return nullptr;
            return std::make_unique<DamBreak>(*dem, *dem->scenario()->dam_break, ctx.out);
          }};
}

}  // namespace talus::run
