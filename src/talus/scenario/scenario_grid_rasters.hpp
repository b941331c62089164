#pragma once
// The rasters of the grid models (run.model = "fv2d", "two_phase"): the
// terrain fixes the grid and the CRS, every other raster lies on it (the
// release may be resampled onto it). Errors name file, line and key. Internal
// to the scenario readers.
#include <string>
#include <string_view>
#include <vector>

#include "talus/io/toml_reader.hpp"
#include "talus/runout/scenario.hpp"
#include "talus/scenario/scenario_detail.hpp"

namespace talus::io::grid_rasters {

// How a raster's values are read at `key`.
enum class GridRole {
  Terrain,   // fixes the grid; no-data cells become NaN (outside the domain)
  OnGrid,    // must lie on the terrain's grid; no-data cells become 0, negatives refused
  Resampled  // may lie on another grid of the terrain's CRS: averaged onto it by area
};

// Reads the raster named at `key` (its path, resolved, into `file`).
std::vector<double> read_grid(TomlReader& r, std::string_view key, const detail::DemContext& ctx,
                              std::string& file, runout::GridSpec& g, GridRole role);

// The terrain's no-data cells lie outside the domain; a terrain without data
// is refused.
void mark_domain(TomlReader& r, runout::GridSpec& g);

}  // namespace talus::io::grid_rasters
