#pragma once
// What the grid models (fv2d, two-phase) share on the run loop: the solver,
// its per-cell maxima and files, the flume results of a grid on a path, the
// checkpoint, the output schedules, and the steps in segments with the team
// or one thread (every loop of the solvers is per cell or a max, so the bits
// are the same either way). A model adds its start (what it released), its
// stop rule, its bed-normal heights and its report.
#include <algorithm>
#include <filesystem>
#include <memory>
#include <vector>

#include "talus/core/team_segments.hpp"
#include "talus/run/forward.hpp"
#include "talus/run/methods/runout.hpp"
#include "talus/run/simulation.hpp"
#include "talus/runout/checkpoint.hpp"

namespace talus::run {

// Released: what the model's checkpoint keeps of its release (a volume, or
// one per phase); runout::save_checkpoint / load_checkpoint take it.
template <class Solver, class Maxima, class Outputs, class Released>
class GridSimulation : public Simulation {
 public:
  // Writes the run's files into `out` (without: none). resume = true first
  // restores the state from out/checkpoint.bin and continues the files.
  // write = false (an MPI rank other than 0): the same state and schedules,
  // no files.
  void write_to(const std::filesystem::path& out, bool resume = false, bool write = true) {
    checkpoint_ = out / "checkpoint.bin";
    if (resume) {
      runout::RunoutResults path;
      const auto count = runout::load_checkpoint(solver_, maxima_, released_, path, checkpoint_);
      path_.restore(std::move(path));
      steps_ = count.steps, last_dt_ = count.last_time_step;
    }
    if (!write) return;
    files_ = std::make_unique<Outputs>(out, scenario_.grid, resume, time(),
                                       scenario_.control.snapshot_interval > 0.0);
    outputs_ = std::make_unique<FilesWithCheckpoint<Outputs, Solver>>(*files_, solver_, [this] {
      runout::save_checkpoint(solver_, maxima_, released_, path_.results(), {steps_, last_dt_},
                              checkpoint_);
    });
  }

  double time() const override { return solver_.state().time; }
  std::int64_t steps() const override { return steps_; }
  double end_time() const override { return scenario_.control.duration; }
  double time_step() const override { return last_dt_ > 0 ? last_dt_ : 1e-2; }
  double kinetic_energy() const override { return solver_.kinetic_energy(); }
  // From the stable step of the current state (steps shrink as the flow speeds up).
  double estimated_steps() const override {
    const double dt = std::min(solver_.stable_time_step(), scenario_.grid.max_time_step);
    return (end_time() - time()) / dt;
  }
  Schedules schedules() const override {
    return grid_schedules(scenario_.control, !checkpoint_.empty());
  }
  bool stopped() const override { return stopped_; }
  Observer& outputs() override { return *outputs_; }
  void after_series() override {
    if (path_.active()) path_.sample_front(time(), normal_heights());
  }
  void finish() override {
    if (files_) files_->write_results(solver_, maxima_);
    if (path_.active())
      path_.finish(checkpoint_.empty() ? std::filesystem::path() : checkpoint_.parent_path(),
                   time(), normal_heights(), solver_.at_rest());
  }

  const Solver& solver() const { return solver_; }
  const Maxima& maxima() const { return maxima_; }
  // The solver's fields per cell (rows from north to south, columns from
  // west to east, as the rasters and .npy maps) and the bed's elevation;
  // read-only.
  std::vector<StateArray> state_arrays() override {
    const auto& g = solver_.terrain().shape();
    auto grid = [&](const char* name, const char* unit, const std::vector<double>& field) {
      // Read-only: the view drops its write flag.
      return StateArray{
          name,         unit, StateArray::Type::Float64, const_cast<double*>(field.data()),
          {g.ny, g.nx}, false};
    };
    std::vector<StateArray> out;
    for (const auto& [name, unit, field] : solver_fields()) out.push_back(grid(name, unit, *field));
    out.push_back(grid("elevation", "m", solver_.terrain().elevation()));
    return out;
  }

 protected:
  GridSimulation(runout::RunoutScenario scenario, int threads,
                 Solver (*build)(const runout::RunoutScenario&))
      : scenario_(std::move(scenario)),
        solver_(build(scenario_)),
        path_(scenario_),
        outputs_(std::make_unique<Observer>()),
        threads_(threads),
        segments_(threads) {}

  // Steps until `target` (steps land on it, so the series is sampled at its
  // times exactly), the end, or max_steps; after each step `stop()` says
  // whether the run ends there.
  template <class Stop>
  void step_to(double target, double tolerance, std::int64_t max_steps, Stop&& stop) {
    const double end = end_time();
    step_in_segments(threads_, segments_, max_steps, [&] {
      const double t = solver_.state().time;
      if (stopped_ || t >= target - tolerance || t >= end - tolerance) return false;
      const double dt =
          std::min({solver_.stable_time_step(), scenario_.grid.max_time_step, end - t, target - t});
      solver_.step(dt);
      last_dt_ = dt;
      ++steps_;
      maxima_.observe(solver_);
      if (path_.active()) path_.observe_step(time(), normal_heights(), solver_.max_speed());
      stopped_ = stop();
      return true;
    });
  }

  // The bed-normal height per cell (the mixture's): the front along a path.
  virtual std::vector<double> normal_heights() const = 0;
  struct Field {
    const char* name;
    const char* unit;
    const std::vector<double>* values;
  };
  // The solver's state per cell, named (state_arrays).
  virtual std::vector<Field> solver_fields() const = 0;

  runout::RunoutScenario scenario_;
  Solver solver_;
  Maxima maxima_;
  GridPathResults path_;
  std::unique_ptr<Outputs> files_;
  std::unique_ptr<Observer> outputs_;
  std::filesystem::path checkpoint_;  // empty: no files
  int threads_;
  TeamSegments segments_;  // the team or one thread, segment by segment
  Released released_{};
  std::int64_t steps_ = 0;
  double last_dt_ = 0.0;
  bool stopped_ = false;
};

}  // namespace talus::run
