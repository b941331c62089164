#pragma once
// The initial blocks of a DAN run: n boundary blocks spaced evenly along the
// path over the released mass, and the volume of each mass block between them.
#include <functional>
#include <vector>

#include "talus/runout/dan.hpp"

namespace talus::runout {

// A released area in the path's vertical plane (x, y), cut into vertical
// slices between the boundary blocks (DAN's vertical blocks): V_j = width *
// (area of the polygon between x(S_j) and x(S_{j+1})). The blocks span the
// polygon's horizontal extent. Throws InputError for n < 2, fewer than three
// vertices or a polygon of zero area.
DanBlocks blocks_from_polygon(const RunoutPath& path, const std::vector<Vec2>& polygon,
                              std::size_t n);

// A depth profile normal to the path between s_tail and s_front:
// V_j = integral of depth(s) * width(s) ds over the block (Simpson's rule on 8
// sub-intervals, exact for polynomials of degree 3 in s). velocity(s) sets the
// initial velocities (zero when empty).
DanBlocks blocks_from_depth(const RunoutPath& path, double s_tail, double s_front, std::size_t n,
                            const std::function<double(double)>& depth,
                            const std::function<double(double)>& velocity = {});

// Area of the part of the polygon with x0 <= x <= x1.
double polygon_area_between(const std::vector<Vec2>& polygon, double x0, double x1);

}  // namespace talus::runout
