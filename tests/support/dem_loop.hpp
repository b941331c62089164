#pragma once
// Runs a DemRun on the run layer's loop (run/loop.hpp), for tests that build
// an engine by hand and step it to a time.
#include <vector>

#include "talus/run/loop.hpp"
#include "talus/run/methods/dem.hpp"

namespace talus::test {

// fresh = false continues a run that already stepped (its forces are primed).
template <int D>
run::RunStats run_dem(dem::DemRun<D>& r, const run::DemControl& control,
                      std::vector<run::Observer*> observers = {}, bool fresh = true) {
  run::DemSimulation<D> sim(r, control);
  run::RunLoop loop(sim, std::move(observers));
  loop.start(fresh);
  return loop.run();
}

}  // namespace talus::test
