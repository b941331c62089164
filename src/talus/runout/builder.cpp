#include "talus/runout/builder.hpp"

#include <cmath>

#include "talus/core/error.hpp"
#include "talus/runout/release.hpp"

namespace talus::runout {

RunoutPath build_path(const PathSpec& spec) {
  if (spec.kind == PathKind::Flume) {
    return path_from_flume(geometry::make_flume(spec.flume), spec.width, spec.spacing);
  }
  return path_from_profile(spec.profile_points, spec.profile_widths, spec.smoothing_length,
                           spec.spacing);
}

DanSetup build_dan(const RunoutScenario& sc) {
  RunoutPath path = build_path(sc.path);
  double barrier_s = std::nan("");
  std::vector<Vec2> polygon = sc.release.polygon;
  if (sc.path.kind == PathKind::Flume) {
    const auto flume = geometry::make_flume(sc.path.flume);
    barrier_s = flume.arc_end_s();
    if (sc.release.kind == ReleaseKind::Flume)
      polygon = {flume.release[0], flume.release[1], flume.release[2]};
  } else if (sc.path.barrier_start) {
    barrier_s = *sc.path.barrier_start;
  }
  DanBlocks blocks = blocks_from_polygon(path, polygon, sc.release.blocks);
  return {DanModel(std::move(path), sc.params, std::move(blocks)), barrier_s};
}

}  // namespace talus::runout
