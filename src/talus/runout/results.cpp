#include "talus/runout/results.hpp"

#include <algorithm>
#include <cmath>

namespace talus::runout {

RunoutTracker::RunoutTracker(double barrier_start_s, double tail_fraction)
    : barrier_s_(barrier_start_s), tail_fraction_(tail_fraction) {}

std::vector<ProfilePoint> surface_profile(const DanModel& model) {
  std::vector<ProfilePoint> out(model.size());
  for (std::size_t i = 0; i < model.size(); ++i) {
    const double s = model.blocks().s[i];
    const Vec2 bed = model.path().point(s);
    const double a = model.path().angle(s), depth = model.boundary_depth(i);
    const Vec2 normal(-std::sin(a), std::cos(a));
    const Vec2 top = bed + depth * normal;
    out[i] = {s, bed.x(), bed.y(), depth, top.x(), top.y()};
  }
  return out;
}

void RunoutTracker::observe_step(const DanModel& model) {
  const double t = model.blocks().time;
  const double front = model.blocks().s.back();
  r_.max_speed = std::max(r_.max_speed, model.max_speed());
  for (std::size_t j = 0; j + 1 < model.size(); ++j)
    r_.max_depth = std::max(r_.max_depth, model.block_depth(j));
  if (std::isnan(barrier_s_) || front < barrier_s_) return;
  if (std::isnan(r_.barrier_arrival_time)) r_.barrier_arrival_time = t;
  const double y = model.path().point(front).y();
  if (std::isnan(r_.runup_max.elevation) || y > r_.runup_max.elevation)
    r_.runup_max = {y, front, front - barrier_s_, t};
}

void RunoutTracker::sample_front(const DanModel& model) {
  const double s = model.blocks().s.back();
  const Vec2 p = model.path().point(s);
  r_.front.push_back({model.blocks().time, s, p.x(), p.y()});
}

const RunoutResults& RunoutTracker::finish(const DanModel& model) {
  r_.deposit = surface_profile(model);
  const double front = model.blocks().s.back();
  if (!std::isnan(barrier_s_) && front >= barrier_s_)
    r_.runup_final = {model.path().point(front).y(), front, front - barrier_s_,
                      model.blocks().time};
  double deepest = 0.0;
  for (const auto& p : r_.deposit) deepest = std::max(deepest, p.depth);
  r_.tail_s_absolute = r_.deposit.front().s;
  for (const auto& p : r_.deposit) {
    if (p.depth >= tail_fraction_ * deepest) {
      r_.tail_s = p.s;
      break;
    }
  }
  if (model.at_rest() && std::isnan(r_.rest_time)) r_.rest_time = model.blocks().time;
  return r_;
}

}  // namespace talus::runout
