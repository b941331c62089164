#include "talus/run/step_limit.hpp"

#include <fmt/core.h>

#include "talus/core/error.hpp"

namespace talus::run {

void check_step_count(const std::string& file, double steps, double duration, bool allowed) {
  if (allowed || !(steps > kStepLimit)) return;
  throw InputError(fmt::format(
      "{}: the run would take about {:.3g} steps ({:.4g} s of simulated time in steps of {:.4g} "
      "s), more than 10^9: it would not finish. Check what sets the time step (the materials' "
      "density and stiffness, the smallest particle or cell, or time_step) and the duration, "
      "or pass --allow-long-run to run it anyway",
      file, steps, duration, duration / steps));
}

}  // namespace talus::run
