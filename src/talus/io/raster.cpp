#include "talus/io/raster.hpp"

#include <cpl_conv.h>
#include <cpl_error.h>
#include <fmt/format.h>
#include <gdal.h>
#include <ogr_srs_api.h>

#include <cmath>
#include <filesystem>
#include <memory>
#include <mutex>

#include "talus/core/error.hpp"
#include "talus/io/archive.hpp"

namespace talus::io {
namespace {

void register_gdal() {
  static std::once_flag once;
  std::call_once(once, [] {
    GDALAllRegister();
    CPLSetErrorHandler(CPLQuietErrorHandler);  // errors are reported as exceptions
  });
}

std::string last_gdal_error() {
  const char* msg = CPLGetLastErrorMsg();
  return msg && *msg ? msg : "unknown GDAL error";
}

// A parsed CRS, null when the WKT is empty or not understood.
using Srs = std::unique_ptr<void, void (*)(OGRSpatialReferenceH)>;
Srs parse_srs(const std::string& wkt) {
  Srs srs(nullptr, OSRDestroySpatialReference);
  if (wkt.empty()) return srs;
  srs.reset(OSRNewSpatialReference(nullptr));
  char* text = const_cast<char*>(wkt.c_str());
  if (OSRImportFromWkt(srs.get(), &text) != OGRERR_NONE) srs.reset();
  return srs;
}

std::string srs_name(const Srs& srs) {
  const char* name = OSRGetName(srs.get());
  return name && *name ? name : "unnamed";
}

}  // namespace

std::string crs_not_metric(const std::string& wkt) {
  register_gdal();
  const Srs srs = parse_srs(wkt);
  if (!srs) return "";
  if (OSRIsGeographic(srs.get()))
    return fmt::format(
        "its CRS '{}' is geographic (cells in degrees); expected a projected CRS "
        "in metres (reproject it, e.g. gdalwarp -t_srs EPSG:<UTM zone>)",
        srs_name(srs));
  char* unit = nullptr;
  const double metres = OSRGetLinearUnits(srs.get(), &unit);
  if (std::abs(metres - 1.0) > 1e-9)
    return fmt::format("its CRS '{}' measures in {} ({} m); expected a projected CRS in metres",
                       srs_name(srs), unit ? unit : "unknown units", metres);
  return "";
}

std::string crs_mismatch(const std::string& a, const std::string& b) {
  register_gdal();
  const Srs sa = parse_srs(a), sb = parse_srs(b);
  if (!sa || !sb || OSRIsSame(sa.get(), sb.get())) return "";
  return fmt::format("its CRS '{}' is not the terrain's '{}'", srs_name(sa), srs_name(sb));
}

Raster read_raster(const std::string& path) {
  register_gdal();
  CPLErrorReset();
  GDALDatasetH ds = GDALOpen(path.c_str(), GA_ReadOnly);
  if (!ds) {
    std::error_code ec;
    if (std::filesystem::is_directory(path, ec))
      throw InputError(fmt::format("{}: is a folder, not a raster file", path));
    throw InputError(fmt::format("{}: cannot read the raster ({})", path, last_gdal_error()));
  }
  struct Closer {
    GDALDatasetH ds;
    ~Closer() { GDALClose(ds); }
  } closer{ds};
  const int bands = GDALGetRasterCount(ds);
  if (bands < 1) throw InputError(fmt::format("{}: the raster has no band", path));
  if (bands > 1)
    throw InputError(fmt::format(
        "{}: the raster has {} bands; expected one (extract it, e.g. gdal_translate -b 1)", path,
        bands));
  double gt[6];
  if (GDALGetGeoTransform(ds, gt) != CE_None) {
    // No georeference: unit cells with the corner at the origin.
    gt[0] = 0, gt[1] = 1, gt[2] = 0, gt[3] = 0, gt[4] = 0, gt[5] = -1;
  }
  if (gt[2] != 0.0 || gt[4] != 0.0)
    throw InputError(fmt::format("{}: rotated or sheared rasters are not supported", path));
  if (!(gt[1] > 0.0) || gt[5] == 0.0)
    throw InputError(fmt::format("{}: the cell size must be positive", path));
  // Positive: rows run north from the first. Flipping would mirror a raster
  // whose geotransform has the wrong sign, so such files are refused.
  if (gt[5] > 0.0)
    throw InputError(fmt::format(
        "{}: a south-up raster (pixel height {} > 0); expected north-up rows (negative pixel "
        "height; e.g. gdalwarp rewrites it north-up)",
        path, gt[5]));
  Raster r;
  r.nx = static_cast<std::size_t>(GDALGetRasterXSize(ds));
  r.ny = static_cast<std::size_t>(GDALGetRasterYSize(ds));
  r.dx = gt[1], r.dy = std::abs(gt[5]);
  r.x_west = gt[0];
  r.y_north = gt[3];
  if (const char* wkt = GDALGetProjectionRef(ds)) r.projection = wkt;
  GDALRasterBandH band = GDALGetRasterBand(ds, 1);
  int has_nodata = 0;
  const double nodata = GDALGetRasterNoDataValue(band, &has_nodata);
  if (has_nodata) r.nodata = nodata;
  r.values.resize(r.nx * r.ny);
  if (GDALRasterIO(band, GF_Read, 0, 0, static_cast<int>(r.nx), static_cast<int>(r.ny),
                   r.values.data(), static_cast<int>(r.nx), static_cast<int>(r.ny), GDT_Float64, 0,
                   0) != CE_None)
    throw InputError(
        fmt::format("{}: cannot read the raster's values ({})", path, last_gdal_error()));
  return r;
}

// Both writers produce the whole file under a temporary name and rename it
// into place: a full disk leaves the old file or none, never a cut one, and
// the error names the file.
void write_geotiff(const std::string& path, const Raster& r) {
  register_gdal();
  if (r.values.size() != r.nx * r.ny || r.nx == 0 || r.ny == 0)
    throw RunError(fmt::format("{}: raster of {} values for {} x {} cells", path, r.values.size(),
                               r.nx, r.ny));
  GDALDriverH driver = GDALGetDriverByName("GTiff");
  if (!driver) throw RunError("GDAL has no GeoTIFF driver");
  const std::string temp = path + ".tmp";
  auto fail = [&] {
    const std::string why = last_gdal_error();
    std::error_code ignored;
    std::filesystem::remove(temp, ignored);
    throw RunError(fmt::format("cannot write '{}': {}", path, why));
  };
  // A run killed while writing leaves its temporary file; GDAL's create
  // would try to open it as a dataset to delete it and leave that failure as
  // the last error, so a resumed run's write would be taken as failed.
  std::error_code stale;
  std::filesystem::remove(temp, stale);
  CPLErrorReset();
  char* options[] = {const_cast<char*>("COMPRESS=DEFLATE"), nullptr};
  GDALDatasetH ds = GDALCreate(driver, temp.c_str(), static_cast<int>(r.nx), static_cast<int>(r.ny),
                               1, GDT_Float64, options);
  if (!ds) fail();
  double gt[6] = {r.x_west, r.dx, 0.0, r.y_north, 0.0, -r.dy};
  GDALSetGeoTransform(ds, gt);
  if (!r.projection.empty()) GDALSetProjection(ds, r.projection.c_str());
  GDALRasterBandH band = GDALGetRasterBand(ds, 1);
  if (r.nodata) GDALSetRasterNoDataValue(band, *r.nodata);
  if (!r.description.empty()) GDALSetDescription(band, r.description.c_str());
  if (!r.unit.empty()) GDALSetRasterUnitType(band, r.unit.c_str());
  const CPLErr err =
      GDALRasterIO(band, GF_Write, 0, 0, static_cast<int>(r.nx), static_cast<int>(r.ny),
                   const_cast<double*>(r.values.data()), static_cast<int>(r.nx),
                   static_cast<int>(r.ny), GDT_Float64, 0, 0);
  // The data reach the file when it is closed; a write that fails there
  // leaves its error behind.
  GDALClose(ds);
  if (err != CE_None || CPLGetLastErrorType() >= CE_Failure) fail();
  rename_into_place(temp, path);
}

void write_npy(const std::string& path, const Raster& r) {
  std::string header =
      fmt::format("{{'descr': '<f8', 'fortran_order': False, 'shape': ({}, {}), }}", r.ny, r.nx);
  // Magic (6) + version (2) + length (2) + header + '\n', padded to 64 bytes.
  const std::size_t total = 10 + header.size() + 1;
  header.append((64 - total % 64) % 64, ' ');
  header.push_back('\n');
  const auto len = static_cast<unsigned short>(header.size());
  const char preamble[10] = {'\x93',
                             'N',
                             'U',
                             'M',
                             'P',
                             'Y',
                             '\x01',
                             '\x00',
                             static_cast<char>(len & 0xff),
                             static_cast<char>(len >> 8)};
  const std::string_view pieces[] = {
      std::string_view(preamble, sizeof preamble), header,
      std::string_view(reinterpret_cast<const char*>(r.values.data()),
                       r.values.size() * sizeof(double))};
  write_file_atomically(path, pieces);
}

bool same_grid(const Raster& a, const Raster& b) {
  const double tol = 1e-9 * std::min(a.dx, a.dy);
  return a.nx == b.nx && a.ny == b.ny && std::abs(a.dx - b.dx) <= tol &&
         std::abs(a.dy - b.dy) <= tol && std::abs(a.x_west - b.x_west) <= tol * 1e3 &&
         std::abs(a.y_north - b.y_north) <= tol * 1e3;
}

}  // namespace talus::io
