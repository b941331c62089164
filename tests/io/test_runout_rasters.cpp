// Rasters a 2D runout refuses (issue 28, section 4): a terrain in degrees or
// in feet, rasters in two CRSs, non-square cells, south-up rows, two bands, a
// folder, NaN release depths that no no-data value declares. The rasters are
// written here with GDAL into a temporary folder.
#include <cpl_conv.h>
#include <gdal.h>
#include <gtest/gtest.h>
#include <ogr_srs_api.h>
#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <fstream>

#include "scenario_cases.hpp"
#include "talus/core/error.hpp"
#include "talus/io/raster.hpp"
#include "talus/runout/grid/fv2d_builder.hpp"
#include "talus/runout/grid/fv2d_maxima.hpp"
#include "talus/runout/grid/fv2d_output.hpp"
#include "talus/scenario/scenario_runout.hpp"

namespace talus::io {
namespace {

namespace fs = std::filesystem;
using cases::error_of;

fs::path folder() {
  const auto* test = ::testing::UnitTest::GetInstance()->current_test_info();
  const fs::path dir = fs::path(testing::TempDir()) /
                       ("talus_rasters_" + std::to_string(::getpid()) + "_" + test->name());
  fs::create_directories(dir / "folder.tif");
  return dir;
}

std::string wkt_of(int epsg) {
  OGRSpatialReferenceH srs = OSRNewSpatialReference(nullptr);
  EXPECT_EQ(OSRImportFromEPSG(srs, epsg), OGRERR_NONE) << epsg;
  char* text = nullptr;
  OSRExportToWkt(srs, &text);
  const std::string wkt = text ? text : "";
  CPLFree(text);
  OSRDestroySpatialReference(srs);
  return wkt;
}

// 6 x 4 cells, 1 m deep (release) or a plane rising to the west (terrain).
Raster grid(bool terrain, double dx = 5.0, double dy = 5.0, int epsg = 32632) {
  Raster r;
  r.nx = 6, r.ny = 4, r.dx = dx, r.dy = dy, r.x_west = 500000, r.y_north = 5200000;
  r.projection = wkt_of(epsg);
  for (std::size_t j = 0; j < r.ny; ++j)
    for (std::size_t i = 0; i < r.nx; ++i) r.values.push_back(terrain ? 100.0 - i : 1.0);
  return r;
}

// Files GDAL writes but write_geotiff never does: several bands, rows south-up.
void write_raw(const fs::path& path, int bands, bool south_up) {
  GDALAllRegister();
  GDALDatasetH ds =
      GDALCreate(GDALGetDriverByName("GTiff"), path.c_str(), 6, 4, bands, GDT_Float64, nullptr);
  ASSERT_NE(ds, nullptr);
  double gt[6] = {500000, 5, 0, south_up ? 5199980.0 : 5200000.0, 0, south_up ? 5.0 : -5.0};
  GDALSetGeoTransform(ds, gt);
  GDALSetProjection(ds, wkt_of(32632).c_str());
  std::vector<double> values(24, 1.0);
  for (int b = 1; b <= bands; ++b)
    EXPECT_EQ(GDALRasterIO(GDALGetRasterBand(ds, b), GF_Write, 0, 0, 6, 4, values.data(), 6, 4,
                           GDT_Float64, 0, 0),
              CE_None);
  GDALClose(ds);
}

const char* kScenario = R"(method = "runout"
[run]
model = "fv2d"
duration = 1.0
[terrain]
file = "terrain.tif"
[material]
density = 2000
internal_friction = 35
rheology = "voellmy"
friction_coefficient = 0.2
turbulence = 500
[release]
type = "raster"
file = "release.tif"
)";
const int kTerrainLine = 6, kReleaseLine = 15;

// Parses the scenario over terrain.tif and release.tif in dir, with overrides.
runout::RunoutScenario parse(const fs::path& dir, const std::vector<std::string>& sets = {}) {
  const fs::path file = dir / "runout.toml";
  std::ofstream(file) << kScenario;
  return parse_runout_scenario(load_scenario_file(file.string(), sets));
}

// The error names the scenario, the line of the key (0: set with --set), the
// raster and why.
void expect_refused(const fs::path& dir, int line, const std::string& key,
                    const std::string& raster, const std::string& why,
                    const std::vector<std::string>& sets = {}) {
  const std::string message = error_of([&] { parse(dir, sets); });
  const std::string file = (dir / "runout.toml").string();
  const std::string head = line > 0 ? file + ":" + std::to_string(line) + ":" : file + ": --set";
  EXPECT_EQ(message.rfind(head, 0), 0u) << message << "\nexpected to start with " << head;
  EXPECT_NE(message.find(line > 0 ? "'" + key + "'" : key), std::string::npos) << message;
  EXPECT_NE(message.find(raster), std::string::npos) << message;
  EXPECT_NE(message.find(why), std::string::npos) << message;
}

TEST(RunoutRasters, ProjectedSquareNorthUpRastersAreRead) {
  const fs::path dir = folder();
  write_geotiff((dir / "terrain.tif").string(), grid(true));
  write_geotiff((dir / "release.tif").string(), grid(false));
  const auto sc = parse(dir);
  EXPECT_EQ(sc.grid.shape.nx, 6u);
  EXPECT_EQ(sc.grid.shape.dx, 5.0);
  EXPECT_EQ(sc.grid.release_depth.size(), 24u);
  EXPECT_EQ(sc.grid.elevation[1], 99.0);
}

TEST(RunoutRasters, TerrainCrsMustBeInMetres) {
  const fs::path dir = folder();
  write_geotiff((dir / "release.tif").string(), grid(false, 5, 5, 4326));
  write_geotiff((dir / "terrain.tif").string(), grid(true, 5, 5, 4326));  // WGS 84
  expect_refused(dir, kTerrainLine, "file", "terrain.tif", "is geographic (cells in degrees)");
  write_geotiff((dir / "terrain.tif").string(), grid(true, 5, 5, 2227));  // US survey feet
  expect_refused(dir, kTerrainLine, "file", "terrain.tif", "expected a projected CRS in metres");
}

TEST(RunoutRasters, ReleaseInAnotherCrsIsRefused) {
  const fs::path dir = folder();
  write_geotiff((dir / "terrain.tif").string(), grid(true));
  write_geotiff((dir / "release.tif").string(), grid(false, 5, 5, 32633));
  expect_refused(dir, kReleaseLine, "file", "release.tif",
                 "CRS 'WGS 84 / UTM zone 33N' is not the terrain's 'WGS 84 / UTM zone 32N'");
}

TEST(RunoutRasters, NonSquareCellsAreRefused) {
  const fs::path dir = folder();
  write_geotiff((dir / "terrain.tif").string(), grid(true, 5, 7));
  write_geotiff((dir / "release.tif").string(), grid(false, 5, 7));
  expect_refused(dir, kTerrainLine, "file", "terrain.tif", "cells of 5 x 7 m; expected square");
}

TEST(RunoutRasters, SouthUpAndTwoBandRastersAreRefused) {
  const fs::path dir = folder();
  write_geotiff((dir / "terrain.tif").string(), grid(true));
  write_raw(dir / "release.tif", 1, true);
  expect_refused(dir, kReleaseLine, "file", "release.tif", "south-up raster (pixel height 5 > 0)");
  write_raw(dir / "release.tif", 2, false);
  expect_refused(dir, kReleaseLine, "file", "release.tif", "has 2 bands; expected one");
  write_raw(dir / "release.tif", 1, false);
  EXPECT_NO_THROW(parse(dir));
}

TEST(RunoutRasters, AFolderIsNotAMissingFile) {
  const fs::path dir = folder();
  write_geotiff((dir / "release.tif").string(), grid(false));
  expect_refused(dir, 0, "terrain.file", "folder.tif", "is a folder",
                 {"terrain.file=\"folder.tif\""});
  const std::string message = error_of([&] { read_raster((dir / "folder.tif").string()); });
  EXPECT_NE(message.find("folder.tif: is a folder"), std::string::npos) << message;
}

TEST(RunoutRasters, NanReleaseDepthsNeedANoDataValue) {
  const fs::path dir = folder();
  write_geotiff((dir / "terrain.tif").string(), grid(true));
  Raster release = grid(false);
  release.at(2, 1) = std::nan("");
  write_geotiff((dir / "release.tif").string(), release);
  expect_refused(dir, kReleaseLine, "file", "release.tif",
                 "cell (column 2, row 1) is nan; expected a number");
  release.nodata = std::nan("");  // declared: the cell is empty
  write_geotiff((dir / "release.tif").string(), release);
  const auto sc = parse(dir);
  EXPECT_EQ(sc.grid.release_depth[1 * 6 + 2], 0.0);
  EXPECT_EQ(sc.grid.release_depth[1 * 6 + 3], 1.0);
}

TEST(RunoutRasters, ReleaseOnAnotherGridIsAveragedOntoTheTerrains) {
  // Terrain: 6 x 4 cells of 5 m from (500000, 5200000). Release: 3 x 2
  // cells of 7 m from (500003, 5199996), depths 1..6 m: an offset, coarser
  // grid whose cells cut the terrain's.
  const fs::path dir = folder();
  write_geotiff((dir / "terrain.tif").string(), grid(true));
  Raster release;
  release.nx = 3, release.ny = 2, release.dx = release.dy = 7.0;
  release.x_west = 500003, release.y_north = 5199996, release.projection = wkt_of(32632);
  release.values = {1, 2, 3, 4, 5, 6};
  write_geotiff((dir / "release.tif").string(), release);
  const auto sc = parse(dir);
  // The volume is kept: sum of depth x 49 m^2 = 21 x 49 = 1029 m^3.
  double volume = 0.0;
  for (double d : sc.grid.release_depth) volume += d * 25.0;
  EXPECT_NEAR(volume, 1029.0, 1e-9);
  EXPECT_NE(sc.grid.release_resampling.find("area-weighted"), std::string::npos)
      << sc.grid.release_resampling;
  // Terrain cell (1, 0), x 500005-500010, y 5199995-5200000: release cell
  // (0, 0) (x 500003-500010, y 5199989-5199996) covers 5 x 1 m of it, 1 m
  // deep; the rest is beyond the release: 5 / 25 m.
  EXPECT_NEAR(sc.grid.release_depth[1], 5.0 / 25.0, 1e-12);
  // Cell (2, 1), x 500010-500015, y 5199990-5199995: release cells (1, 0)
  // (2 m deep, x 500010-500017, y 5199989-5199996) cover all of it.
  EXPECT_NEAR(sc.grid.release_depth[6 + 2], 2.0, 1e-12);
  // Cell (1, 1), x 500005-500010, y 5199990-5199995: inside release cell
  // (0, 0), 1 m deep over all of it.
  EXPECT_NEAR(sc.grid.release_depth[6 + 1], 1.0, 1e-12);
  // A release reaching beyond the terrain is refused with the volume beyond.
  release.x_west = 499990;  // 10 m west of the terrain
  write_geotiff((dir / "release.tif").string(), release);
  expect_refused(dir, kReleaseLine, "file", "release.tif", "lie beyond the terrain's extent");
}

TEST(RunoutRasters, TerrainNoDataCellsLieOutsideTheDomain) {
  // A clipped DEM: column 0 and row 3 have no elevation.
  const fs::path dir = folder();
  Raster terrain = grid(true), release = grid(false);
  terrain.nodata = -9999.0;
  for (std::size_t j = 0; j < 4; ++j) terrain.at(0, j) = -9999.0;
  for (std::size_t i = 0; i < 6; ++i) terrain.at(i, 3) = -9999.0;
  write_geotiff((dir / "terrain.tif").string(), terrain);
  // Material released where there is no terrain is refused, naming the cell.
  write_geotiff((dir / "release.tif").string(), release);
  expect_refused(dir, kReleaseLine, "file", "release.tif",
                 "cell (column 0, row 0) releases 1 m where the terrain");
  for (std::size_t j = 0; j < 4; ++j) release.at(0, j) = 0.0;
  for (std::size_t i = 0; i < 6; ++i) release.at(i, 3) = 0.0;
  write_geotiff((dir / "release.tif").string(), release);
  const auto sc = parse(dir);
  ASSERT_EQ(sc.grid.inside.size(), 24u);
  for (std::size_t j = 0; j < 4; ++j)
    for (std::size_t i = 0; i < 6; ++i)
      EXPECT_EQ(sc.grid.inside[j * 6 + i], i > 0 && j < 3 ? 1 : 0) << i << ", " << j;
  // The run keeps its volume and leaves the outside empty; the maps mark it
  // no-data (NaN).
  auto solver = runout::build_fv2d(sc);
  const double v0 = solver.volume();
  EXPECT_DOUBLE_EQ(v0, 15 * 25.0);  // 15 cells of 5 x 5 m, 1 m deep
  for (int k = 0; k < 50; ++k) solver.step(solver.stable_time_step());
  EXPECT_LT(std::abs(solver.volume() - v0) / v0, 1e-12);
  for (std::size_t i = 0; i < 6; ++i) EXPECT_EQ(solver.state().h[3 * 6 + i], 0.0);
  {
    runout::Fv2dOutputs out(dir, sc.grid, false, 0.0);
    runout::Fv2dMaxima maxima;
    maxima.reset(solver.state().h.size());
    maxima.observe(solver);
    out.write_results(solver, maxima);
  }
  const Raster deposit = read_raster((dir / "deposit.tif").string());
  EXPECT_TRUE(deposit.is_nodata(deposit.at(0, 0)));
  EXPECT_TRUE(deposit.is_nodata(deposit.at(4, 3)));
  EXPECT_FALSE(deposit.is_nodata(deposit.at(1, 0)));
  // The map says what its heights are: bed-normal, in metres.
  GDALDatasetH ds = GDALOpen((dir / "deposit.tif").c_str(), GA_ReadOnly);
  ASSERT_NE(ds, nullptr);
  GDALRasterBandH band = GDALGetRasterBand(ds, 1);
  EXPECT_STREQ(GDALGetDescription(band), "deposit height at the end, bed-normal");
  EXPECT_STREQ(GDALGetRasterUnitType(band), "m");
  GDALClose(ds);
  // A terrain with no data at all is refused.
  for (double& v : terrain.values) v = -9999.0;
  write_geotiff((dir / "terrain.tif").string(), terrain);
  expect_refused(dir, kTerrainLine, "file", "terrain.tif", "every cell is no-data");
}

}  // namespace
}  // namespace talus::io
