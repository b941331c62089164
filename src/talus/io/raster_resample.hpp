#pragma once
// A raster carried onto another grid of the same CRS by area-weighted
// averaging: each target cell takes the mean of the source over its area,
// source cells weighted by the area they share with it, and 0 where no source
// cell lies. For a quantity per unit area (a release depth) the integral is
// kept exactly over the part of the source inside the target grid.
//
// Written here rather than taken from GDAL: gdalwarp's "average" divides by
// the area the source covers, so a target cell cut by the edge of the source
// raster gets the mean of its covered part and the volume is not kept;
// "sum" needs GDAL 3.8. Both grids are north-up and axis-aligned (read_raster
// refuses others), so the overlap is a product of two 1D overlaps.
#include "talus/io/raster.hpp"

namespace talus::io {

// `grid` gives the target's size, corner and cell size (its values are not
// read). Source no-data cells count as 0. Returns nx * ny values of the
// target grid.
std::vector<double> resample_area_weighted(const Raster& source, const Raster& grid);

// The integral of the values over the raster's area (sum of value x cell
// area), no-data cells counted as 0.
double raster_integral(const Raster& r);

}  // namespace talus::io
