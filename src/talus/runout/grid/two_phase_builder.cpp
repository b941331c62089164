#include "talus/runout/grid/two_phase_builder.hpp"

namespace talus::runout {

TwoPhaseParams two_phase_params(const RunoutScenario& sc) {
  TwoPhaseParams p = sc.two_phase.params;
  p.drag.gravity = sc.params.gravity;
  p.courant = sc.control.courant;
  p.order = sc.grid.order;
  p.dry_depth = sc.grid.dry_depth;
  p.boundary = sc.grid.boundary;
  return p;
}

TwoPhaseSolver build_two_phase(const RunoutScenario& sc) {
  std::vector<double> bed = sc.grid.elevation;
  for (std::size_t c = 0; c < bed.size() && c < sc.grid.obstacles.size(); ++c)
    bed[c] += sc.grid.obstacles[c];
  const auto& depth = sc.grid.release_depth;
  const auto& map = sc.two_phase.solid_fraction_map;
  std::vector<double> solid(depth.size()), fluid(depth.size());
  for (std::size_t c = 0; c < depth.size(); ++c) {
    const double alpha = map.empty() ? sc.two_phase.solid_fraction : map[c];
    solid[c] = alpha * depth[c], fluid[c] = depth[c] - solid[c];
  }
  return TwoPhaseSolver(Terrain(sc.grid.shape, std::move(bed), sc.grid.inside),
                        two_phase_params(sc), std::move(solid), std::move(fluid));
}

}  // namespace talus::runout
