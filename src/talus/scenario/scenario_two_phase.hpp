#pragma once
// The two-phase model's part of a runout scenario (run.model = "two_phase"):
// [solid], [fluid], [drag], [hydrology] and the release's solid fraction,
// read with file:line:key errors and written back. Internal to the runout
// scenario reader (scenario_runout.cpp); the format is in
// docs/scenario-format.md, section "Two-phase runout".
#include <nlohmann/json.hpp>

#include "talus/io/toml_reader.hpp"
#include "talus/runout/scenario.hpp"
#include "talus/scenario/scenario_detail.hpp"

namespace talus::io::two_phase_keys {

// The tables the model reads besides [run], [terrain], [release], [output],
// [earth_pressure].
inline constexpr const char* kTables[] = {"solid", "fluid", "drag", "hydrology"};

// [solid], [fluid], [drag] (required, required, optional) and [hydrology]
// (optional) into s.two_phase.params; the earth pressure's angles come from
// [solid]. Call after [terrain] (the rate rasters lie on its grid).
void read_tables(TomlReader& root, const detail::DemContext& ctx, runout::RunoutScenario& s);
// [release]'s solid_fraction (a number), solid_fraction_file (a raster) and
// the optional fluid_fraction that must be 1 - solid_fraction.
void read_release_fractions(TomlReader& release, const detail::DemContext& ctx,
                            runout::RunoutScenario& s);
// The same keys as resolved values, into the scenario's JSON.
void write(nlohmann::ordered_json& root, const runout::RunoutScenario& s);

}  // namespace talus::io::two_phase_keys
