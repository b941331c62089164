#pragma once
// A runout scenario as plain data, filled and validated by
// io::parse_runout_scenario (angles in radians). The model is built from it by
// build_dan (builder.hpp), which reads no files.
#include <optional>
#include <string>
#include <vector>

#include "talus/geometry/flume.hpp"
#include "talus/runout/dan.hpp"
#include "talus/runout/grid/fv2d.hpp"
#include "talus/runout/grid/two_phase.hpp"

namespace talus::runout {

enum class PathKind { Flume, Profile };
enum class ReleaseKind { Flume, Polygon };

struct PathSpec {
  PathKind kind = PathKind::Flume;
  geometry::FlumeShape flume;  // Flume
  // Profile: points (x, y) and widths, read from the CSV by io.
  std::string profile_file;
  std::vector<Vec2> profile_points;
  std::vector<double> profile_widths;
  double smoothing_length = 0.0;        // m
  std::optional<double> barrier_start;  // s where the barrier starts (profile)
  double width = 1.0;                   // channel width (flume), m
  double spacing = 1e-3;                // path table resolution, m
};

struct ReleaseSpec {
  ReleaseKind kind = ReleaseKind::Flume;  // the triangle behind the flume's gate
  std::vector<Vec2> polygon;              // Polygon
  std::size_t blocks = 100;               // boundary blocks
};

// [run] model: "dan" (1D along a path), "fv2d" (2D on a terrain grid) or
// "two_phase" (2D solid-fluid on a terrain grid).
enum class RunoutModel { Dan, Fv2d, TwoPhase };

// The two-phase model's inputs besides the grid's (model = "two_phase"): the
// phases, the closures and the rates (m/s in params, mm/h in the file), and
// the release's solid fraction alpha_s, a constant or a raster on the
// terrain's grid (io fills both).
struct TwoPhaseSpec {
  TwoPhaseParams params;
  double solid_fraction = 0.5;
  std::string solid_fraction_file, rainfall_file, infiltration_file;
  std::vector<double> solid_fraction_map;  // per cell; empty: the constant
};

// The 2D models' grids, read from rasters by io (all on the terrain's grid):
// bed elevation (NaN where the terrain raster has no data: outside the
// domain), obstacle heights added to it (a barrier), and the released
// thickness (measured vertically; no-data cells are 0).
struct GridSpec {
  std::string terrain_file, obstacles_file, release_file;
  GridShape shape;
  std::vector<double> elevation, obstacles, release_depth;
  std::vector<unsigned char> inside;   // per cell 1 in the domain, 0 not; empty: all in
  double x_west = 0.0, y_north = 0.0;  // map coordinates of the outer corner
  std::string projection;              // WKT of the terrain raster
  // How the release raster was brought onto the terrain's grid; empty when it
  // lies on it.
  std::string release_resampling;
  int order = 2;
  GridBoundary boundary = GridBoundary::Wall;
  // Instead of rasters, the grid can be a flume path (PathSpec) extruded
  // across its width (grid/path_grid.hpp): `rows` rows of cells `cell_size`
  // long along x, walls on every side. The run then also reports the 1D
  // flume results (front along the path, run-up, deposit, as DAN), the front
  // being the last column deeper than front_depth (bed-normal).
  bool on_path = false;
  double cell_size = 0.0;  // m along x
  std::size_t rows = 3;
  double front_depth = 1e-3;   // m
  double dry_depth = 1e-6;     // m
  double max_time_step = 0.1;  // s
};

// How long a runout run goes and when it writes (both models).
struct RunoutControl {
  double duration = 1.0;             // s
  double time_step = 0.0;            // s; 0 = from the stability limit every step (DAN)
  double courant = 0.5;              // DAN
  double series_interval = 0.01;     // s; also the front sampling
  double snapshot_interval = 0.0;    // s; 0 = first and last only
  double checkpoint_interval = 0.0;  // s; 0 = none (checkpoint.bin to resume from)
  bool stop_at_rest = true;          // end early once the mass has stopped
  // fv2d: end early once the momentum sum has fallen below this fraction of
  // its peak (RAMMS' stop rule); 0 = never.
  double stop_momentum_fraction = 0.0;
};

struct RunoutScenario {
  std::string name, description;
  RunoutModel model = RunoutModel::Dan;
  GridSpec grid;  // model = fv2d or two_phase
  TwoPhaseSpec two_phase;
  DanParams params;
  PathSpec path;
  ReleaseSpec release;
  RunoutControl control;
  double tail_fraction = 0.1;
};

}  // namespace talus::runout
