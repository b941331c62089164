#include "talus/runout/grid/fv2d_builder.hpp"

namespace talus::runout {

Fv2dParams fv2d_params(const RunoutScenario& sc) {
  Fv2dParams p;
  p.density = sc.params.density;
  p.gravity = sc.params.gravity;
  p.rheology = sc.params.rheology;
  p.pressure = sc.params.pressure;
  p.curvature = sc.params.centripetal;
  p.courant = sc.control.courant;
  p.order = sc.grid.order;
  p.dry_depth = sc.grid.dry_depth;
  p.boundary = sc.grid.boundary;
  return p;
}

Fv2dSolver build_fv2d(const RunoutScenario& sc) {
  std::vector<double> bed = sc.grid.elevation;
  for (std::size_t c = 0; c < bed.size() && c < sc.grid.obstacles.size(); ++c)
    bed[c] += sc.grid.obstacles[c];
  return Fv2dSolver(Terrain(sc.grid.shape, std::move(bed), sc.grid.inside), fv2d_params(sc),
                    sc.grid.release_depth);
}

}  // namespace talus::runout
