#pragma once
// The depth-averaged methods on the run loop: DAN (1D, run/methods/dan.cpp)
// here, and what the grid models (fv2d.hpp, two_phase.hpp, both on
// grid_simulation.hpp) share besides. All may end early once the mass is at
// rest. Without an output folder they write nothing (calibration,
// comparisons, tests); with one they write checkpoint.bin at
// output.checkpoint_interval (runout/checkpoint.hpp).
#include <filesystem>
#include <functional>
#include <memory>
#include <nlohmann/json.hpp>
#include <optional>
#include <vector>

#include "talus/core/team_segments.hpp"
#include "talus/run/method.hpp"
#include "talus/run/simulation.hpp"
#include "talus/runout/builder.hpp"
#include "talus/runout/grid/fv2d_maxima.hpp"
#include "talus/runout/grid/fv2d_output.hpp"
#include "talus/runout/grid/path_grid.hpp"
#include "talus/runout/output_observer.hpp"
#include "talus/runout/results.hpp"
#include "talus/runout/scenario.hpp"

namespace talus::run {

// The flume results of a grid model on a path (grid/path_grid.hpp): nothing
// unless scenario.grid.on_path. The methods feed it the bed-normal depth per
// cell; at the end it writes path.csv, front.csv and deposit.csv and adds
// DAN's flume figures to summary.json's metrics (what `talus compare` reads).
class GridPathResults {
 public:
  explicit GridPathResults(const runout::RunoutScenario& scenario);
  bool active() const { return tracker_.has_value(); }
  void observe_step(double time, const std::vector<double>& depth, double max_speed);
  void sample_front(double time, const std::vector<double>& depth);
  void finish(const std::filesystem::path& out, double time, const std::vector<double>& depth,
              bool at_rest);
  void add_metrics(nlohmann::json& metrics) const;
  // For checkpoints: what was gathered so far (empty when not active).
  runout::RunoutResults results() const;
  void restore(runout::RunoutResults results);

 private:
  std::optional<runout::PathGridTracker> tracker_;
};

class DanSimulation : public Simulation {
 public:
  explicit DanSimulation(runout::RunoutScenario scenario);
  // Writes the run's files into `out` (without: none). resume = true first
  // restores the state from out/checkpoint.bin and continues the files.
  void write_to(const std::filesystem::path& out, bool resume = false);

  double time() const override { return setup_.model.blocks().time; }
  std::int64_t steps() const override { return steps_; }
  double end_time() const override { return scenario_.control.duration; }
  double time_step() const override { return last_dt_ > 0 ? last_dt_ : 1e-4; }
  double kinetic_energy() const override { return setup_.model.kinetic_energy(); }
  // Known for a fixed time step only (the automatic one follows the flow).
  double estimated_steps() const override;
  Schedules schedules() const override;
  void start(bool fresh) override;
  void advance(double target, double tolerance, std::int64_t max_steps) override;
  bool stopped() const override { return stopped_; }
  Observer& outputs() override { return *outputs_; }
  void finish() override;
  MethodReport report() const override;
  // The blocks, read-only: boundary blocks' path coordinates s and speeds v
  // (n), the mass blocks' volumes and earth-pressure coefficients k (n - 1).
  std::vector<StateArray> state_arrays() override {
    const auto& b = setup_.model.blocks();
    auto array = [](const char* name, const char* unit, const std::vector<double>& values) {
      return StateArray{name,
                        unit,
                        StateArray::Type::Float64,
                        const_cast<double*>(values.data()),
                        {values.size()},
                        false};
    };
    return {array("s", "m", b.s), array("v", "m/s", b.v), array("volume", "m^3", b.volume),
            array("k", "", b.k)};
  }

  const runout::RunoutResults& results() const { return tracker_.results(); }
  const runout::DanModel& model() const { return setup_.model; }

 private:
  runout::RunoutScenario scenario_;
  runout::DanSetup setup_;
  runout::RunoutTracker tracker_;
  std::unique_ptr<runout::DanOutputs> files_;
  std::unique_ptr<Observer> outputs_;
  std::filesystem::path checkpoint_;  // empty: no files
  std::int64_t steps_ = 0;
  double last_dt_ = 0.0;
  bool stopped_ = false;
};

// Writes the resolved scenario into out/scenario.toml (unless `write` is
// false: an MPI rank other than 0) and reads it back: a fresh run starts from
// the numbers a resumed one will read (an angle through degrees and back may
// differ in its last bit), on every rank alike.
runout::RunoutScenario write_resolved_runout(const runout::RunoutScenario& scenario,
                                             const std::filesystem::path& out, bool write = true);

// The output intervals of a grid model's run (fv2d, two-phase): series
// always; checkpoints and snapshot maps only when asked for and with files.
Schedules grid_schedules(const runout::RunoutControl& control, bool files);
// summary.json's "resolved" block of a grid model's run.
nlohmann::json grid_resolved(const runout::GridSpec& grid, int threads);

// A grid model's run as the registry creates it: parsed and built before
// the folder is made (bad input leaves nothing behind); a fresh run starts
// from the resolved scenario it writes (write_resolved_runout).
// On several ranks (a model that spreads over them), rank 0 makes the folder
// and writes; the others compute alike, without files.
template <class GridSimulation>
std::unique_ptr<Simulation> create_grid_run(runout::RunoutScenario scenario,
                                            const RunContext& ctx) {
  auto sim = std::make_unique<GridSimulation>(scenario, ctx.threads);
  if (!ctx.resume) {
    if (ctx.writes()) ctx.prepare();
    sim = std::make_unique<GridSimulation>(write_resolved_runout(scenario, ctx.out, ctx.writes()),
                                           ctx.threads);
  }
  if constexpr (requires { sim->distribute(*ctx.ranks); })
    if (ctx.ranks && ctx.ranks->size() > 1) sim->distribute(*ctx.ranks);
  sim->write_to(ctx.out, ctx.resume, ctx.writes());
  return sim;
}

// A RunUp as summary.json writes it.
nlohmann::json runup_json(const runout::RunUp& runup);

// The warning of a runout run that ends before its mass has come to rest: its
// deposit and run-out are not final.
std::string still_moving(double time, double max_speed);

// Runs a DAN scenario to its end without writing anything (for `talus
// compare`, calibration and tests): the results of the finished run.
runout::RunoutResults simulate_dan(const runout::RunoutScenario& scenario);

}  // namespace talus::run
