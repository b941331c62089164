#pragma once
// fv2d (2D depth-averaged runout on a terrain grid, runout/grid/fv2d.hpp) on
// the run loop: grid_simulation.hpp with its released volume, the stop at
// rest and RAMMS' momentum rule, and its report.
#include "talus/run/methods/grid_simulation.hpp"
#include "talus/runout/grid/fv2d_maxima.hpp"
#include "talus/runout/grid/fv2d_output.hpp"

namespace talus::run {

class Fv2dSimulation final
    : public GridSimulation<runout::Fv2dSolver, runout::Fv2dMaxima, runout::Fv2dOutputs, double> {
 public:
  explicit Fv2dSimulation(runout::RunoutScenario scenario, int threads = 1);
  // Steps this rank's rows of the grid (docs/mpi.md); refused for a grid on a
  // flume path.
  void distribute(const comm::Comm& ranks);
  // A resumed run's maxima and released volume come from its checkpoint.
  void start(bool fresh) override;
  void advance(double target, double tolerance, std::int64_t max_steps) override;
  MethodReport report() const override;

 private:
  std::vector<double> normal_heights() const override;
  // h (m, vertical depth), hu and hv (m^2/s).
  std::vector<Field> solver_fields() const override {
    const auto& s = solver_.state();
    return {{"h", "m", &s.h}, {"hu", "m^2/s", &s.hu}, {"hv", "m^2/s", &s.hv}};
  }
  bool momentum_stop_ = false;  // stopped by run.stop_momentum_fraction
};

}  // namespace talus::run
