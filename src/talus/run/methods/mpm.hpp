#pragma once
// The MPM method on the run loop (run/methods/mpm.cpp).
#include <filesystem>
#include <memory>

#include "talus/core/team_segments.hpp"
#include "talus/mpm/health.hpp"
#include "talus/mpm/output_observer.hpp"
#include "talus/mpm/scenario.hpp"
#include "talus/run/simulation.hpp"

namespace talus::run {

template <int D>
class MpmSimulation : public Simulation {
 public:
  // out empty: no files (tests).
  MpmSimulation(mpm::MpmScenario scenario, mpm::Solver<D> solver,
                const std::filesystem::path& out = {}, bool resume = false, int threads = 1);

  double time() const override { return solver_.time; }
  std::int64_t steps() const override { return solver_.steps; }
  double end_time() const override { return scenario_.duration; }
  // The old loop's rule: the run ends within 1e-12 of its duration.
  double tolerance() const override { return 1e-12 * scenario_.duration; }
  double time_step() const override { return solver_.last_dt > 0 ? solver_.last_dt : 1.0; }
  double kinetic_energy() const override;
  // From the CFL step of the current state (the steps adapt as the flow goes).
  double estimated_steps() const override {
    return (end_time() - solver_.time) / solver_.time_step();
  }
  // The report's one line of key results (from the report's metrics).
  static std::string headline(const nlohmann::json& metrics);
  Schedules schedules() const override;
  void start(bool fresh) override;
  void advance(double target, double tolerance, std::int64_t max_steps) override;
  Observer& outputs() override { return *files_observer_; }
  MethodReport report() const override;
  // The material points: positions, velocities (writable), masses, volumes,
  // Cauchy stresses (3 x 3, also in 2D: plane strain), in their own order.
  std::vector<StateArray> state_arrays() override;

  mpm::Solver<D>& solver() { return solver_; }
  const mpm::MpmScenario& scenario() const { return scenario_; }

 private:
  mpm::MpmScenario scenario_;
  mpm::Solver<D> solver_;
  int threads_;
  TeamSegments segments_;  // the team or one thread, segment by segment
  std::unique_ptr<mpm::MpmOutputs<D>> files_;
  std::unique_ptr<Observer> files_observer_;
  double blowup_ = 0.0;
  mpm::EnergyBudget budget_;
};

}  // namespace talus::run
