#include "talus/scenario/scenario_grid_rasters.hpp"

#include <fmt/format.h>

#include <cmath>
#include <limits>

#include "talus/core/error.hpp"
#include "talus/io/raster.hpp"
#include "talus/io/raster_resample.hpp"

namespace talus::io::grid_rasters {
namespace {

void take_terrain_grid(TomlReader& r, std::string_view key, const std::string& file,
                       const Raster& raster, runout::GridSpec& g) {
  if (const std::string why = crs_not_metric(raster.projection); !why.empty())
    r.fail(key, fmt::format("{}: {}", file, why));
  if (std::abs(raster.dx - raster.dy) > 1e-9 * raster.dx)
    r.fail(key, fmt::format("{}: cells of {} x {} m; expected square cells (resample it, e.g. "
                            "gdalwarp -tr {} {})",
                            file, raster.dx, raster.dy, raster.dx, raster.dx));
  g.shape = {raster.nx, raster.ny, raster.dx, raster.dy};
  g.x_west = raster.x_west, g.y_north = raster.y_north, g.projection = raster.projection;
}

// The terrain's grid as an empty raster.
Raster terrain_grid(const runout::GridSpec& g) {
  Raster ref;
  ref.nx = g.shape.nx, ref.ny = g.shape.ny, ref.dx = g.shape.dx, ref.dy = g.shape.dy;
  ref.x_west = g.x_west, ref.y_north = g.y_north;
  return ref;
}

void check_terrain_crs(TomlReader& r, std::string_view key, const std::string& file,
                       const Raster& raster, const runout::GridSpec& g) {
  if (const std::string why = crs_mismatch(raster.projection, g.projection); !why.empty())
    r.fail(key, fmt::format("{}: {}", file, why));
}

// Another raster must lie on the terrain's grid, in its CRS.
void check_on_terrain_grid(TomlReader& r, std::string_view key, const std::string& file,
                           const Raster& raster, const runout::GridSpec& g) {
  check_terrain_crs(r, key, file, raster, g);
  const Raster ref = terrain_grid(g);
  if (!same_grid(raster, ref))
    r.fail(key,
           fmt::format("{}: the grid ({} x {} cells of {} x {} m) is not the terrain's "
                       "({} x {} cells of {} m, same corner)",
                       file, raster.nx, raster.ny, raster.dx, raster.dy, ref.nx, ref.ny, ref.dx));
}

// The release on another grid of the terrain's CRS, averaged onto the
// terrain's cells by area (raster_resample.hpp); refused when part of its
// volume lies beyond the terrain.
std::vector<double> release_on_terrain_grid(TomlReader& r, std::string_view key,
                                            const std::string& file, const Raster& release,
                                            runout::GridSpec& g) {
  const Raster ref = terrain_grid(g);
  std::vector<double> depth = resample_area_weighted(release, ref);
  double on_terrain = 0.0;
  for (double d : depth) on_terrain += d;
  on_terrain *= ref.dx * ref.dy;
  const double total = raster_integral(release);
  if (std::abs(total - on_terrain) > 1e-9 * total)
    r.fail(key, fmt::format("{}: {:.6g} m^3 of the {:.6g} m^3 released lie beyond the terrain's "
                            "extent; expected a release inside the terrain",
                            file, total - on_terrain, total));
  g.release_resampling = fmt::format(
      "area-weighted average of {} x {} cells of {} x {} m onto the terrain's {} m cells (volume "
      "kept: {:.6g} m^3)",
      release.nx, release.ny, release.dx, release.dy, ref.dx, on_terrain);
  return depth;
}

}  // namespace

// A NaN is a no-data cell only when the raster says so (no-data value NaN).
std::vector<double> read_grid(TomlReader& r, std::string_view key, const detail::DemContext& ctx,
                              std::string& file, runout::GridSpec& g, GridRole role) {
  const bool terrain = role == GridRole::Terrain, resample = role == GridRole::Resampled;
  file = detail::required_file(r, key, ctx);
  Raster raster;
  try {
    raster = read_raster(file);
  } catch (const InputError& e) {
    r.fail(key, e.what());
  }
  if (terrain)
    take_terrain_grid(r, key, file, raster, g);
  else if (resample)
    check_terrain_crs(r, key, file, raster, g);
  else
    check_on_terrain_grid(r, key, file, raster, g);
  for (std::size_t j = 0; j < raster.ny; ++j)
    for (std::size_t i = 0; i < raster.nx; ++i) {
      double& v = raster.at(i, j);
      const std::string cell = fmt::format("{}: cell (column {}, row {})", file, i, j);
      if (raster.is_nodata(v)) {
        v = terrain ? std::numeric_limits<double>::quiet_NaN() : 0.0;
      } else if (!std::isfinite(v)) {
        r.fail(key, fmt::format("{} is {}; expected a number (or declare NaN the raster's no-data "
                                "value)",
                                cell, v));
      } else if (!terrain && v < 0.0) {
        r.fail(key, fmt::format("{} is negative ({})", cell, v));
      }
    }
  if (resample && !same_grid(raster, terrain_grid(g)))
    return release_on_terrain_grid(r, key, file, raster, g);
  return std::move(raster.values);
}

// The terrain's no-data cells lie outside the domain.
void mark_domain(TomlReader& r, runout::GridSpec& g) {
  std::size_t inside = 0;
  g.inside.assign(g.elevation.size(), 1);
  for (std::size_t c = 0; c < g.elevation.size(); ++c) {
    if (std::isnan(g.elevation[c]))
      g.inside[c] = 0;
    else
      ++inside;
  }
  if (inside == 0)
    r.fail("file", fmt::format("{}: every cell is no-data; expected elevations", g.terrain_file));
  if (inside == g.elevation.size()) g.inside.clear();
}

}  // namespace talus::io::grid_rasters
