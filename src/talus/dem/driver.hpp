#pragma once
// The solver loop: advances a DemRun to the end time in chunks and calls the
// observers (series, snapshots, checkpoints, progress) at their intervals.
// It also watches the run's health: NaN and energy blow-up stop it with a
// diagnosis instead of producing garbage.
#include <cstdint>
#include <optional>
#include <vector>

#include "talus/dem/builder.hpp"

namespace talus::dem {

template <int D>
class DemObserver {
 public:
  virtual ~DemObserver() = default;
  virtual void on_series(const DemRun<D>&) {}
  virtual void on_snapshot(const DemRun<D>&) {}
  virtual void on_checkpoint(const DemRun<D>&) {}
  virtual void on_progress(double /*time*/, double /*end*/, double /*steps_per_s*/) {}
};

// A change of the grains' friction during the run (the beam's μ_init -> μ_p,
// Götz 2024 §5.3): from `time` on, the given materials have `friction`.
struct FrictionChange {
  double time = 0.0;
  double friction = 0.0;
  std::vector<int> materials;
};

struct RunControl {
  double duration = 0.0;
  int64_t series_every = 100;    // steps
  int64_t snapshot_every = 0;    // steps; 0 = first and last only
  int64_t checkpoint_every = 0;  // steps; 0 = none
  double ke_blowup_factor = 10.0;
  double progress_seconds = 1.0;  // wall seconds between progress calls
  std::optional<FrictionChange> friction_change;
};

RunControl make_run_control(const DemScenario& sc, double dt);

struct RunStats {
  int64_t steps = 0;
  double wall_seconds = 0.0;  // time-stepping loop only
};

// Runs from the system's current time to control.duration. `fresh` primes the
// forces of a new run; a resumed run continues from its restored state.
template <int D>
RunStats run_dem(DemRun<D>& run, const RunControl& control,
                 const std::vector<DemObserver<D>*>& observers, bool fresh);

}  // namespace talus::dem
