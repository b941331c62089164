// The Mancarella & Hungr flume ([flume]; 2D DEM and 2D MPM): front along the
// path, run-up, deposit and barrier forces into <out>/flume and the
// summary's flume block, and the headline a barrier designer reads first.
#include <fmt/core.h>

#include "talus/analysis/flume_observer.hpp"
#include "talus/analysis/mpm_flume_observer.hpp"
#include "talus/run/experiments/bind.hpp"
#include "talus/run/experiments/experiments.hpp"
#include "talus/run/methods/dem.hpp"
#include "talus/run/methods/mpm.hpp"

namespace talus::run {

namespace {

std::string when(const nlohmann::json& t) {  // -1: never
  return t.get<double>() < 0 ? std::string("never") : fmt::format("{:.3f} s", t.get<double>());
}

class DemFlume final : public Bound<analysis::FlumeObserver, dem::DemRun<2>> {
 public:
  DemFlume(std::unique_ptr<analysis::FlumeObserver> a, const dem::DemRun<2>& run,
           double series_interval)
      : Bound("flume", std::move(a), run), series_interval_(series_interval) {}

  std::string headline(const nlohmann::json& f) const override {
    const auto& b = f["forces"]["barrier"];
    return fmt::format(
               "flume: front at the arc {}, at the barrier {}; run-up {:.3f} m along the barrier "
               "({:.3f} m high), {:.3f} m at most; main deposit from s = {:.3f} m, {} grains "
               "upstream of it",
               when(f["front"]["reach_arc_time"]), when(f["front"]["reach_barrier_time"]),
               f["runup"]["final_s"].get<double>(), f["runup"]["final_height"].get<double>(),
               f["runup"]["max_s"].get<double>(), f["deposit"]["tail_s"].get<double>(),
               f["deposit"]["stranded"].get<int>()) +
           "\n" +
           fmt::format(
               "flume: barrier per metre of width: x impulse {:.1f} N s, peak F_x {:.0f} N ({:.3g} "
               "ms mean) and {:.0f} N (single step), F_x at the end {:.0f} N",
               b["impulse_x"].get<double>(), b["peak_fx"].get<double>(), series_interval_ * 1e3,
               b["peak_step_fx"].get<double>(), b["final_fx"].get<double>());
  }

 private:
  double series_interval_;
};

std::unique_ptr<Experiment> attach_dem(DemSimulation<2>& dem, const RunContext& ctx) {
  const auto& f = *dem.scenario()->flume;
  const auto& s = dem.dem_run().system;
  auto obs = std::make_unique<analysis::FlumeObserver>(ctx.out, geometry::make_flume(f.shape), f, s,
                                                       ctx.resume, s.time);
  // Snapshots carry each grain's initial layer.
  const auto* layers = obs.get();
  dem.files()->decorate = [layers](const dem::DemSystem<2>& system, io::ParticleFrame& frame) {
    layers->add_layers(system, frame);
  };
  return std::make_unique<DemFlume>(std::move(obs), dem.dem_run(),
                                    dem.scenario()->output.series_interval);
}

}  // namespace

ExperimentKind flume_experiment() {
  return {"flume", [](Simulation& sim, const RunContext& ctx) -> std::unique_ptr<Experiment> {
            if (auto* dem = as<DemSimulation<2>>(sim);
                dem && dem->scenario() && dem->scenario()->flume && dem->files())
              return attach_dem(*dem, ctx);
            auto* mpm = as<MpmSimulation<2>>(sim);
            if (!mpm || !mpm->scenario().flume) return nullptr;
            const auto& s = mpm->solver();
            return bind_analysis("flume",
                                 std::make_unique<analysis::MpmFlumeObserver>(
                                     ctx.out, *mpm->scenario().flume, s, ctx.resume, s.time),
                                 s);
          }};
}

}  // namespace talus::run
