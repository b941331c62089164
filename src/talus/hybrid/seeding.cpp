#include "talus/hybrid/seeding.hpp"

#include <fmt/format.h>

#include <cmath>

#include "talus/core/error.hpp"
#include "talus/hybrid/r2_sequence.hpp"

namespace talus::hybrid {

Seeded seed_particles(const runout::GridShape& shape, const std::vector<double>& depth,
                      double particle_volume, double density, double u0, double v0) {
  if (depth.size() != shape.cells())
    throw InputError(
        fmt::format("hybrid: {} depths for a grid of {} cells", depth.size(), shape.cells()));
  if (!(particle_volume > 0.0) || !(density > 0.0))
    throw InputError("hybrid: the particle volume and the density must be > 0");
  Seeded out;
  Particles& p = out.particles;
  const double area = shape.cell_area();
  long fullest = 0;
  for (std::size_t j = 0; j < shape.ny; ++j)
    for (std::size_t i = 0; i < shape.nx; ++i) {
      const double d = depth[shape.index(i, j)];
      if (!std::isfinite(d) || d < 0.0)
        throw InputError(fmt::format("hybrid: depth {} in cell ({}, {})", d, i, j));
      const long count = std::lround(d * area / particle_volume);
      fullest = std::max(fullest, count);
      for (long n = 1; n <= count; ++n) {
        const auto [fx, fy] = r2_point(n);
        p.x.push_back((static_cast<double>(i) + fx) * shape.dx);
        p.y.push_back((static_cast<double>(j) + fy) * shape.dy);
      }
    }
  if (fullest == 0)
    throw InputError("hybrid: no cell is deep enough for one particle of the given volume");
  const std::size_t n = p.x.size();
  p.resize(n);
  for (std::size_t k = 0; k < n; ++k) {
    p.u[k] = u0;
    p.v[k] = v0;
    p.mass[k] = density * particle_volume;
  }
  out.spacing = std::sqrt(area / static_cast<double>(fullest));
  return out;
}

}  // namespace talus::hybrid
