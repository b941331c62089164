// Raster files through GDAL: a GeoTIFF written and read back is the same grid
// (values, corner, cell size, no-data), an ESRI ASCII grid is read with its
// header, and a bad file is an InputError naming it.
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>

#include "talus/core/error.hpp"
#include "talus/io/raster.hpp"

namespace talus::io {
namespace {

namespace fs = std::filesystem;

fs::path temp_dir() {
  const fs::path d = fs::temp_directory_path() / ("talus_raster_" + std::to_string(::getpid()));
  fs::create_directories(d);
  return d;
}

TEST(Raster, GeoTiffRoundTrip) {
  Raster r;
  r.nx = 7, r.ny = 5, r.x_west = 600000.5, r.y_north = 5200000.25, r.dx = 2.5, r.dy = 2.0;
  r.nodata = -9999.0;
  for (std::size_t k = 0; k < r.nx * r.ny; ++k) r.values.push_back(0.1 * k - 1.0 / 3.0);
  r.values[3] = -9999.0;
  const fs::path file = temp_dir() / "round.tif";
  write_geotiff(file.string(), r);
  const Raster back = read_raster(file.string());
  EXPECT_TRUE(same_grid(r, back));
  EXPECT_EQ(back.x_west, r.x_west);
  EXPECT_EQ(back.y_north, r.y_north);
  ASSERT_TRUE(back.nodata.has_value());
  EXPECT_EQ(*back.nodata, -9999.0);
  ASSERT_EQ(back.values.size(), r.values.size());
  for (std::size_t k = 0; k < r.values.size(); ++k)
    EXPECT_EQ(back.values[k], r.values[k]);  // Float64: exact
  EXPECT_TRUE(back.is_nodata(back.at(3, 0)));
}

// A run killed while writing a GeoTIFF leaves a cut temporary file beside it;
// the resumed run writes the same file again and must succeed (GDAL's create
// tried to open the stale file to delete it and left that error behind:
// tests/app/test_resume_runout.sh failed "cannot write ... Unable to open
// ....tif.tmp to obtain file list").
TEST(Raster, GeoTiffOverAStaleTemporaryFile) {
  Raster r;
  r.nx = 3, r.ny = 2, r.dx = r.dy = 1.0;
  r.values = {1, 2, 3, 4, 5, 6};
  const fs::path file = temp_dir() / "stale.tif";
  std::ofstream(file.string() + ".tmp") << "II*\0 a cut GeoTIFF";
  EXPECT_NO_THROW(write_geotiff(file.string(), r));
  EXPECT_EQ(read_raster(file.string()).values, r.values);
  EXPECT_FALSE(fs::exists(file.string() + ".tmp"));
}

TEST(Raster, ReadsEsriAsciiGrid) {
  const fs::path file = temp_dir() / "grid.asc";
  std::ofstream(file) << "ncols 3\nnrows 2\nxllcorner 100\nyllcorner 200\ncellsize 10\n"
                         "NODATA_value -9999\n1 2 3\n4 -9999 6\n";
  const Raster r = read_raster(file.string());
  EXPECT_EQ(r.nx, 3u);
  EXPECT_EQ(r.ny, 2u);
  EXPECT_EQ(r.dx, 10.0);
  EXPECT_EQ(r.x_west, 100.0);
  EXPECT_EQ(r.y_north, 220.0);  // lower-left corner + 2 rows of 10 m
  EXPECT_EQ(r.at(0, 0), 1.0);   // first line of the file: the northern row
  EXPECT_EQ(r.at(2, 1), 6.0);
  EXPECT_TRUE(r.is_nodata(r.at(1, 1)));
}

TEST(Raster, NpyHasNumpyHeader) {
  Raster r;
  r.nx = 2, r.ny = 3, r.values = {1, 2, 3, 4, 5, 6};
  const fs::path file = temp_dir() / "a.npy";
  write_npy(file.string(), r);
  // NPY format 1.0: 10 bytes of preamble, the header padded to 64 bytes, data.
  const auto size = fs::file_size(file);
  EXPECT_EQ((size - 6 * sizeof(double)) % 64, 0u);
  std::ifstream in(file, std::ios::binary);
  std::string magic(6, ' ');
  in.read(magic.data(), 6);
  EXPECT_EQ(magic, "\x93NUMPY");
}

TEST(Raster, MissingFileIsInputErrorNamingIt) {
  try {
    read_raster("/nonexistent/terrain.tif");
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("/nonexistent/terrain.tif"), std::string::npos);
  }
}

}  // namespace
}  // namespace talus::io
