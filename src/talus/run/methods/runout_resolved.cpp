
#include "talus/io/archive.hpp"
#include "talus/run/methods/runout.hpp"
#include "talus/scenario/scenario_runout.hpp"

namespace talus::run {

runout::RunoutScenario write_resolved_runout(const runout::RunoutScenario& scenario,
                                             const std::filesystem::path& out) {
  const auto path = out / "scenario.toml";
  io::write_file_atomically(path, io::runout_scenario_to_toml(scenario));
  return io::parse_runout_scenario(io::load_scenario_file(path.string(), {}));
}

}  // namespace talus::run
