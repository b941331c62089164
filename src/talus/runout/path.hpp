#pragma once
// The path a 1D runout model travels along: a curve in the vertical (x, y)
// plane, x horizontal downstream, y up, parametrised by its arc length s, with
// a channel width. It is tabulated at a fixed spacing so that every lookup in
// the time loop is O(1); the curvature comes from the tangent angle of the
// table, which makes one code path for the flume (exact, smooth geometry) and
// for measured profiles (polylines, smoothed here because DAN needs a smooth
// path: Kuen 2011 §2.2.3).
#include <vector>

#include "talus/geometry/flume.hpp"

namespace talus::runout {

using Vec2 = Eigen::Vector2d;

class RunoutPath {
 public:
  // Samples at s = s_begin + k * spacing; angle is the tangent's angle from +x
  // (negative going downhill), width the channel width there.
  RunoutPath(double s_begin, double spacing, std::vector<Vec2> points, std::vector<double> angle,
             std::vector<double> width);

  double s_begin() const { return s0_; }
  double s_end() const { return s0_ + ds_ * static_cast<double>(points_.size() - 1); }
  double spacing() const { return ds_; }

  // Beyond either end the path continues straight along its end tangent with
  // the end width.
  Vec2 point(double s) const;
  double angle(double s) const;  // rad from +x, counter-clockwise
  // d(angle)/ds: positive where the path is concave (chute into a barrier),
  // which presses the flow onto the bed (centripetal term of DAN).
  double curvature(double s) const;
  double width(double s) const;
  // s where the path's horizontal coordinate is x; x(s) must increase along the
  // path (vertical blocks need it). Clamped beyond the ends by straight lines.
  double s_at_x(double x) const;

 private:
  struct Lookup {
    std::size_t k;
    double w;       // weight of sample k + 1
    double beyond;  // distance past the end (signed), 0 inside
  };
  Lookup locate(double s) const;

  double s0_, ds_;
  std::vector<Vec2> points_;
  std::vector<double> angle_, curvature_, width_;
};

// The flume of flume.md as a path: chute, arc and barrier, s = 0 at the gate
// foot as in geometry::FlumeGeometry. `width` is the channel width (1 gives
// results per metre of width, as the 2D DEM does).
RunoutPath path_from_flume(const geometry::FlumeGeometry& flume, double width,
                           double spacing = 1e-3);

// A measured profile: points (x, y) with x strictly increasing and a width at
// each. The polyline's tangent angle is averaged over a window of
// `smoothing_length` (m along the path; 0 keeps the kinks, each spread over one
// sample) and the curve is rebuilt from the smoothed angle, starting at the
// first point. s = 0 at the first point. Throws InputError for fewer than two
// points, x not increasing or a width <= 0 (messages name the point index).
RunoutPath path_from_profile(const std::vector<Vec2>& points, const std::vector<double>& widths,
                             double smoothing_length, double spacing = 1e-3);

}  // namespace talus::runout
