#pragma once
// The DEM method on the run loop: steps a DemRun in chunks of whole steps,
// checks its health, applies a scheduled friction change, and writes its
// files through DemOutputs. Tests and experiments use DemSimulation directly.
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <memory>
#include <optional>
#include <string>

#include "talus/dem/builder.hpp"
#include "talus/dem/friction_change.hpp"
#include "talus/dem/health.hpp"
#include "talus/dem/output_observer.hpp"
#include "talus/run/simulation.hpp"

namespace talus::run {

struct DemControl {
  double duration = 0.0;
  double series_interval = 0.0;      // s; 0 = every 100 steps
  double snapshot_interval = 0.0;    // s; 0 = first and last only; < 0 = none
  double checkpoint_interval = 0.0;  // s; 0 = none
  double ke_blowup_factor = 10.0;    // <= 0: no energy check
  std::optional<dem::FrictionChange> friction_change;
};

DemControl dem_control(const dem::DemScenario& scenario);

template <int D>
class DemSimulation : public Simulation, public WallControl {
 public:
  // Steps `run` (owned by the caller) without writing files.
  DemSimulation(dem::DemRun<D>& run, DemControl control);
  // A run of `scenario` writing into `out` (resume: continuing its files).
  DemSimulation(dem::DemScenario scenario, std::unique_ptr<dem::DemRun<D>> run,
                const std::filesystem::path& out, bool resume, int threads);

  double time() const override { return run_.system.time; }
  std::int64_t steps() const override { return run_.system.step; }
  // The last step's time (the same number as end_step_ * dt, known before start()).
  double end_time() const override {
    return std::round(control_.duration / run_.system.dt) * run_.system.dt;
  }
  double time_step() const override { return run_.system.dt; }
  double kinetic_energy() const override;
  double estimated_steps() const override {
    return control_.duration / run_.system.dt - static_cast<double>(run_.system.step);
  }
  // The report's one line of key results.
  std::string headline() const;
  Schedules schedules() const override;
  void start(bool fresh) override;
  void advance(double target, double tolerance, std::int64_t max_steps) override;
  Observer& outputs() override { return *outputs_observer_; }
  void after_series() override;
  MethodReport report() const override;
  // Positions, velocities (writable), angular velocities (writable), forces,
  // radii, masses and ids of the particles, in their current order.
  std::vector<StateArray> state_arrays() override;
  // Each neighbour build sorts the particles by cell (and drops escaped ones).
  std::int64_t reorders() const override { return run_.system.neighbours.builds; }
  WallControl* wall_control() override { return this; }
  std::vector<WallReading> walls() const override;
  void set_velocity(std::size_t wall, const Vec3& v) override;
  void set_servo(std::size_t wall, double pressure, double speed, double area) override;

  dem::DemRun<D>& dem_run() { return run_; }
  const dem::DemRun<D>& dem_run() const { return run_; }
  const dem::DemScenario* scenario() const { return scenario_ ? &*scenario_ : nullptr; }
  dem::DemOutputs<D>* files() { return files_.get(); }

 private:
  std::int64_t step_reaching(double t) const;
  geometry::Wall& wall_to_change(std::size_t wall);
  // A wall moving at `speed` must not press a particle deeper than the
  // smallest radius within one critical step (the builder's rule at t = 0).
  void check_wall_speed(const geometry::Wall& wall, double speed) const;

  std::unique_ptr<dem::DemRun<D>> owned_;
  dem::DemRun<D>& run_;
  DemControl control_;
  std::optional<dem::DemScenario> scenario_;
  std::unique_ptr<dem::DemOutputs<D>> files_;
  std::unique_ptr<Observer> outputs_observer_;
  int threads_ = 1;
  std::string device_;  // the GPU it runs on; empty on the CPU
  std::int64_t end_step_ = 0, change_step_ = 0, health_every_ = 1;
  bool changed_before_ = false;
  dem::EnergyBudget budget_;
};

}  // namespace talus::run
