#include "talus/runout/grid/path_grid.hpp"

#include <cmath>

#include "talus/core/error.hpp"
#include "talus/runout/builder.hpp"
#include "talus/runout/grid/path_terrain.hpp"

namespace talus::runout {

namespace {

// The release polygon in the path's plane and the barrier's start (NaN
// without one), as build_dan takes them.
std::vector<Vec2> release_polygon(const RunoutScenario& sc, double* barrier_s) {
  *barrier_s = std::nan("");
  std::vector<Vec2> polygon = sc.release.polygon;
  if (sc.path.kind == PathKind::Flume) {
    const auto flume = geometry::make_flume(sc.path.flume);
    *barrier_s = flume.arc_end_s();
    if (sc.release.kind == ReleaseKind::Flume)
      polygon = {flume.release[0], flume.release[1], flume.release[2]};
  }
  return polygon;
}

double barrier_start(const RunoutScenario& sc) {
  double s = 0.0;
  release_polygon(sc, &s);
  return s;
}

}  // namespace

void grid_from_path(RunoutScenario& sc) {
  auto& g = sc.grid;
  if (sc.path.kind != PathKind::Flume)
    throw InputError("a grid model on a path takes a path of type 'flume'");
  const RunoutPath path = build_path(sc.path);
  double barrier_s = 0.0;
  const auto polygon = release_polygon(sc, &barrier_s);
  const double x0 = path.point(path.s_begin()).x(), x1 = path.point(path.s_end()).x();
  const double row_width = sc.path.width / static_cast<double>(g.rows);
  // Whole columns inside the path's horizontal range (s_at_x needs it).
  const double x_end = x0 + std::floor((x1 - x0) / g.cell_size) * g.cell_size;
  const ExtrudedPath e = extrude_path(path, x0, x_end, g.cell_size, g.rows, row_width, polygon);
  g.shape = e.shape;
  g.elevation = e.elevation;
  g.release_depth = e.release;
  g.inside.clear();
  g.x_west = e.x_begin, g.y_north = row_width * static_cast<double>(g.rows);
  g.boundary = GridBoundary::Wall;
}

PathGridTracker::PathGridTracker(const RunoutScenario& sc)
    : path_(build_path(sc.path)),
      grid_(sc.grid),
      barrier_s_(barrier_start(sc)),
      tail_fraction_(sc.tail_fraction) {}

double PathGridTracker::front_s(const std::vector<double>& depth) const {
  std::size_t reached = 0;  // columns up to the front's downstream face
  for (std::size_t i = 0; i < grid_.shape.nx; ++i)
    if (depth[grid_.shape.index(i, 0)] > grid_.front_depth) reached = i + 1;
  const double x = grid_.x_west + static_cast<double>(reached) * grid_.shape.dx;
  return path_.s_at_x(x);
}

void PathGridTracker::observe_step(double time, const std::vector<double>& depth, double speed) {
  r_.max_speed = std::max(r_.max_speed, speed);
  for (double d : depth) r_.max_depth = std::max(r_.max_depth, d);
  const double front = front_s(depth);
  if (std::isnan(barrier_s_) || front < barrier_s_) return;
  if (std::isnan(r_.barrier_arrival_time)) r_.barrier_arrival_time = time;
  const double y = path_.point(front).y();
  if (std::isnan(r_.runup_max.elevation) || y > r_.runup_max.elevation)
    r_.runup_max = {y, front, front - barrier_s_, time};
}

void PathGridTracker::sample_front(double time, const std::vector<double>& depth) {
  const double s = front_s(depth);
  const Vec2 p = path_.point(s);
  r_.front.push_back({time, s, p.x(), p.y()});
}

const RunoutResults& PathGridTracker::finish(double time, const std::vector<double>& depth,
                                             bool at_rest) {
  // The deposit: one point per column of the first row, at its centre.
  r_.deposit.clear();
  for (std::size_t i = 0; i < grid_.shape.nx; ++i) {
    const double x = grid_.x_west + (static_cast<double>(i) + 0.5) * grid_.shape.dx;
    const double s = path_.s_at_x(x), a = path_.angle(s), h = depth[grid_.shape.index(i, 0)];
    const Vec2 bed = path_.point(s), top = bed + h * Vec2(-std::sin(a), std::cos(a));
    r_.deposit.push_back({s, bed.x(), bed.y(), h, top.x(), top.y()});
  }
  const double front = final_front_ = front_s(depth);
  if (!std::isnan(barrier_s_) && front >= barrier_s_)
    r_.runup_final = {path_.point(front).y(), front, front - barrier_s_, time};
  double deepest = 0.0;
  for (const auto& p : r_.deposit) deepest = std::max(deepest, p.depth);
  // The tail: the first column (from upstream) holding material, and the
  // first at least tail_fraction of the deepest (the main deposit).
  for (const auto& p : r_.deposit)
    if (p.depth > grid_.front_depth) {
      r_.tail_s_absolute = p.s;
      break;
    }
  for (const auto& p : r_.deposit)
    if (deepest > 0.0 && p.depth >= tail_fraction_ * deepest) {
      r_.tail_s = p.s;
      break;
    }
  if (at_rest && std::isnan(r_.rest_time)) r_.rest_time = time;
  return r_;
}

}  // namespace talus::runout
