// What DAN and fv2d share on the run loop: the resolved scenario a run starts
// from, and the warning of a run that ends with its mass still moving.
#include <fmt/format.h>

#include "talus/io/archive.hpp"
#include "talus/run/methods/runout.hpp"
#include "talus/scenario/scenario_runout.hpp"

namespace talus::run {

std::string still_moving(double time, double max_speed) {
  return fmt::format(
      "the mass is still moving at the end (t = {:.4g} s, up to {:.3g} m/s): the deposit and "
      "run-out are not final; lengthen run.duration",
      time, max_speed);
}

runout::RunoutScenario write_resolved_runout(const runout::RunoutScenario& scenario,
                                             const std::filesystem::path& out) {
  const auto path = out / "scenario.toml";
  io::write_file_atomically(path, io::runout_scenario_to_toml(scenario));
  return io::parse_runout_scenario(io::load_scenario_file(path.string(), {}));
}

}  // namespace talus::run
