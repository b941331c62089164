#pragma once
// Runout scenarios (method = "runout"): parsing with file:line:key errors,
// every key checked, and the resolved scenario back as TOML and JSON. The
// format is documented in docs/scenario-format.md, section "Runout".
#include <nlohmann/json.hpp>
#include <string>

#include "talus/scenario/scenario.hpp"
#include "talus/runout/scenario.hpp"

namespace talus::io {

// Full validation (angles come out in radians, defaults filled in; a profile
// CSV is read here). Throws InputError for the first problem found.
runout::RunoutScenario parse_runout_scenario(const ScenarioFile& file);

// The resolved parameters as JSON (summary.json) and as a scenario file that
// parse_runout_scenario reads back to the same values (angles in degrees).
nlohmann::ordered_json runout_scenario_to_json(const runout::RunoutScenario& scenario);
std::string runout_scenario_to_toml(const runout::RunoutScenario& scenario);

// A profile CSV: a header "x,y,width" then one point per line. Errors name the
// file and line.
void read_profile_csv(const std::string& path, std::vector<Eigen::Vector2d>& points,
                      std::vector<double>& widths);

}  // namespace talus::io
