#pragma once
// Rasters on disk (GeoTIFF, ESRI ASCII grid and anything else GDAL reads) as a
// plain grid: values row by row from the north-west corner, the corner's map
// coordinates, the cell size and the no-data value. Reading and writing go
// through GDAL; nothing here knows what the values mean.
#include <cmath>
#include <optional>
#include <string>
#include <vector>

namespace talus::io {

struct Raster {
  std::size_t nx = 0, ny = 0;          // columns, rows
  double x_west = 0.0, y_north = 0.0;  // map coordinates of the outer corner
  double dx = 1.0, dy = 1.0;           // cell size (both > 0); rows run south
  std::optional<double> nodata;        // cells with this value have no data
  std::vector<double> values;          // ny * nx, row 0 is the northern one
  std::string projection;              // WKT; empty when unknown
  // Written to a GeoTIFF when set: the band's description (what the values
  // are, e.g. "deposit height, bed-normal") and its unit ("m").
  std::string description, unit;

  double& at(std::size_t i, std::size_t j) { return values[j * nx + i]; }
  double at(std::size_t i, std::size_t j) const { return values[j * nx + i]; }
  // A NaN no-data value marks the NaN cells.
  bool is_nodata(double v) const {
    return nodata && (v == *nodata || (std::isnan(v) && std::isnan(*nodata)));
  }
};

// The one band of a raster file. Throws InputError naming the file when GDAL
// cannot open it (a folder is said to be one), the raster is rotated, sheared
// or south-up (positive pixel height), or it has no band or more than one.
Raster read_raster(const std::string& path);

// Why a CRS (WKT) is not projected in metres: "its CRS 'WGS 84' is geographic
// ..."; "" when it is, or when the WKT is empty (unknown CRS).
std::string crs_not_metric(const std::string& wkt);
// "its CRS 'A' is not the terrain's 'B'" when both CRSs are known and differ,
// else "".
std::string crs_mismatch(const std::string& wkt, const std::string& terrain_wkt);

// GeoTIFF, one Float64 band (with the no-data value and projection if set).
// Throws RunError when the file cannot be written.
void write_geotiff(const std::string& path, const Raster& raster);

// The values as a NumPy .npy array (float64, shape (ny, nx), row 0 north), for
// plot scripts that have numpy but not GDAL's Python bindings.
void write_npy(const std::string& path, const Raster& raster);

// True when two rasters cover the same cells (size, corner and cell size to
// 1e-9 of a cell).
bool same_grid(const Raster& a, const Raster& b);

}  // namespace talus::io
