#include <fmt/format.h>

#include <cmath>

#include "talus/core/error.hpp"
#include "talus/mpm/scenario.hpp"

namespace talus::mpm {

double resolved_k0(const BodyParams& body, const MaterialParams& m) {
  if (body.k0 > 0.0) return body.k0;
  return m.model == MaterialModel::NewtonianFluid ? 1.0 : m.poisson_ratio / (1.0 - m.poisson_ratio);
}

template <int D>
Solver<D> build_mpm(const MpmScenario& sc) {
  using Vec = typename Space<D>::Vec;
  std::array<BoundaryKind, 2 * D> faces;
  for (int f = 0; f < 2 * D; ++f) faces[f] = sc.grid.faces[f];
  Grid<D> grid(Space<D>::from3(sc.grid.lo), Space<D>::from3(sc.grid.hi), sc.grid.cell_size, faces);
  std::vector<Material> materials;
  for (const auto& m : sc.materials) materials.push_back(make_material(m));
  SolverParams params = sc.solver;
  int per_cell = 0;
  for (const auto& b : sc.bodies) per_cell = std::max(per_cell, b.per_cell);
  if (per_cell > 0) params.gimp_half_width = 0.5 / per_cell;
  Solver<D> solver(std::move(grid), std::move(materials), params);

  const double h = sc.grid.cell_size;
  const Vec g = Space<D>::from3(sc.solver.gravity);
  const double g_mag = g.norm();
  const Vec up = g_mag > 0.0 ? (-g / g_mag).eval() : Vec::Unit(D - 1);
  for (std::size_t b = 0; b < sc.bodies.size(); ++b) {
    const BodyParams& body = sc.bodies[b];
    const MaterialParams& mat = sc.materials[body.material_index];
    const double dx = h / body.per_cell;
    std::array<int, D> count;
    Vec start;
    for (int d = 0; d < D; ++d) {
      if (body.min[d] < sc.grid.lo[d] - 1e-12 || body.max[d] > sc.grid.hi[d] + 1e-12)
        throw InputError(fmt::format("[[bodies]] #{}: the box lies outside the [grid]", b + 1));
      count[d] = std::max(1, static_cast<int>(std::round((body.max[d] - body.min[d]) / dx)));
      start[d] = body.min[d] + 0.5 * (body.max[d] - body.min[d]) / count[d];
    }
    Vec spacing;
    double volume = 1.0;
    for (int d = 0; d < D; ++d) {
      spacing[d] = (body.max[d] - body.min[d]) / count[d];
      volume *= spacing[d];
    }
    // Top of the body along "up": the corner furthest up.
    double top = -1e300;
    for (int corner = 0; corner < (1 << D); ++corner) {
      Vec c;
      for (int d = 0; d < D; ++d) c[d] = (corner >> d & 1) ? body.max[d] : body.min[d];
      top = std::max(top, up.dot(c));
    }
    const double k0 = resolved_k0(body, mat);
    std::array<int, 3> i{0, 0, 0};
    const int total = D == 2 ? count[0] * count[1] : count[0] * count[1] * count[2];
    for (int k = 0; k < total; ++k) {
      int rest = k;
      for (int d = 0; d < D; ++d) {
        i[d] = rest % count[d];
        rest /= count[d];
      }
      Vec x;
      for (int d = 0; d < D; ++d) x[d] = start[d] + i[d] * spacing[d];
      MaterialState s;
      s.cohesion = initial_cohesion(mat);
      if (body.geostatic && g_mag > 0.0) {
        const double vertical = -mat.density * g_mag * (top - up.dot(x));
        const Vec3 up3 = Space<D>::to3(up);
        s.stress = k0 * vertical * Mat3::Identity() + (1.0 - k0) * vertical * up3 * up3.transpose();
      }
      solver.particles.add(x, Space<D>::from3(body.velocity), mat.density * volume, volume,
                           body.material_index, s);
    }
  }
  return solver;
}

template Solver<2> build_mpm<2>(const MpmScenario&);
template Solver<3> build_mpm<3>(const MpmScenario&);

}  // namespace talus::mpm
