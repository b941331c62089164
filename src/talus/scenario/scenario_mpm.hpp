#pragma once
// MPM scenario files (method = "mpm"): [run], [grid], [[materials]],
// [[bodies]], [output]. Documented key by key in docs/scenario-format.md.
#include <nlohmann/json.hpp>
#include <string>

#include "talus/scenario/scenario.hpp"
#include "talus/mpm/scenario.hpp"

namespace talus::io {

// Full validation; angles come out in radians, every default filled in.
// Throws InputError (file:line: [table] 'key': ...) for the first problem.
mpm::MpmScenario parse_mpm_scenario(const ScenarioFile& file);

// The resolved parameters as a scenario file that parse_mpm_scenario reads
// back to the same values (angles in degrees), and as JSON for summary.json.
nlohmann::ordered_json mpm_scenario_to_json(const mpm::MpmScenario& sc);
std::string mpm_scenario_to_toml(const mpm::MpmScenario& sc);

}  // namespace talus::io
