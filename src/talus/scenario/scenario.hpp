#pragma once
// Scenario files: one TOML file per run, parsed and fully validated before
// anything runs. The format is documented key by key in docs/scenario-format.md.
#include <toml++/toml.h>

#include <nlohmann/json.hpp>
#include <string>
#include <string_view>
#include <vector>

#include "talus/dem/params.hpp"

namespace talus::io {

struct ScenarioFile {
  std::string path;    // as given; relative paths inside resolve against its folder
  std::string method;  // "dem" or "runout" (later "mpm")
  toml::table table;   // with the --set overrides applied
};

// Reads and parses a scenario file, applies "--set key=value" overrides and
// checks the method. Syntax errors, bad overrides and unknown or unimplemented
// methods throw InputError naming the file and line.
ScenarioFile load_scenario_file(const std::string& path, const std::vector<std::string>& overrides);
// The same for text already in memory; path is used for messages and to
// resolve relative file names.
ScenarioFile load_scenario_text(std::string_view text, const std::string& path,
                                const std::vector<std::string>& overrides = {});

// Full validation of a DEM scenario; angles come out in radians, every
// default filled in. Throws InputError for the first problem found.
dem::DemScenario parse_dem_scenario(const ScenarioFile& file);

// The resolved parameters (defaults included) as a scenario file that
// parse_dem_scenario reads back to the same values; angles in degrees.
std::string scenario_to_toml(const dem::DemScenario& scenario);
// The same content as JSON, for summary.json.
nlohmann::json scenario_to_json(const dem::DemScenario& scenario);

}  // namespace talus::io
