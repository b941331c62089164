#include "talus/analysis/coarse_grain.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <unordered_map>

#include "talus/core/error.hpp"

namespace talus::analysis {

namespace {

// Volume under the hemisphere sqrt(R^2 - x^2 - y^2) over the rectangle [0, a] x [0, b]
// (a, b >= 0, a^2 + b^2 <= R^2), given w = sqrt(R^2 - a^2 - b^2). Integrating over y in closed
// form, then over x by parts, gives
//   6 W = a (3R^2 - a^2) asin(b / sqrt(R^2 - a^2)) + b (3R^2 - b^2) asin(a / sqrt(R^2 - b^2))
//         - 2 R^3 atan(a b / (R w)) + 2 a b w.
// asin(b / sqrt(R^2 - a^2)) = atan2(b, w): an asin near 1 would turn a rounding error of
// 1e-16 in its argument into 1e-8 in the volume; atan2 of the two legs stays at round-off.
// For the same reason w is passed in, not recomputed from a difference of squares.
double column_volume(double R, double a, double b, double w) {
  const double R2 = R * R;
  return (a * (3 * R2 - a * a) * std::atan2(b, w) + b * (3 * R2 - b * b) * std::atan2(a, w) -
          2 * R2 * R * std::atan2(a * b, R * w) + 2 * a * b * w) /
         6.0;
}

// Ball volume in {x > a, y > b, z > c} for a, b, c >= 0. The slice at height z is the disc of
// radius rho (rho^2 = R^2 - z^2) beyond x = a and y = b: a quarter disc less the strips
// 0 < x < a and 0 < y < b plus the rectangle a b where both strips overlap (valid while
// a^2 + b^2 <= rho^2, i.e. z <= zm). The strip integrated over z is a difference of
// column_volume, the quarter disc a polynomial.
double orthant_positive(double R, double a, double b, double c) {
  const double R2 = R * R;
  const double zm2 = R2 - a * a - b * b;
  if (zm2 <= c * c) return 0.0;
  const double zm = std::sqrt(zm2);
  const double quarter = 0.25 * M_PI * (R2 * (zm - c) - (zm * zm * zm - c * c * c) / 3.0);
  // At z = zm the rest R^2 - a^2 - zm^2 is b^2 (and a^2 for the other strip) exactly.
  const double wa = std::sqrt(std::max(0.0, R2 - a * a - c * c));
  const double wb = std::sqrt(std::max(0.0, R2 - b * b - c * c));
  const double strips = column_volume(R, a, zm, b) - column_volume(R, a, c, wa) +
                        column_volume(R, b, zm, a) - column_volume(R, b, c, wb);
  return std::max(0.0, quarter - strips + a * b * (zm - c));
}

}  // namespace

double sphere_orthant_volume(double R, double a, double b, double c) {
  // A negative bound: {x > a} = everything minus the mirror image of {x > -a}, and everything
  // (in x) is twice {x > 0}.
  if (a < 0) return 2 * sphere_orthant_volume(R, 0, b, c) - sphere_orthant_volume(R, -a, b, c);
  if (b < 0) return 2 * sphere_orthant_volume(R, a, 0, c) - sphere_orthant_volume(R, a, -b, c);
  if (c < 0) return 2 * sphere_orthant_volume(R, a, b, 0) - sphere_orthant_volume(R, a, b, -c);
  return orthant_positive(R, a, b, c);
}

double sphere_box_overlap(const Vec3& centre, double R, const Vec3& lo, const Vec3& hi) {
  std::array<double, 2> x, y, z;
  for (int d = 0; d < 3; ++d) {
    const double l = std::clamp(lo[d] - centre[d], -R, R);
    const double h = std::clamp(hi[d] - centre[d], -R, R);
    if (h <= l) return 0.0;
    (d == 0 ? x : d == 1 ? y : z) = {l, h};
  }
  const double ball = 4.0 / 3.0 * M_PI * R * R * R;
  if (x[0] == -R && x[1] == R && y[0] == -R && y[1] == R && z[0] == -R && z[1] == R) return ball;
  // vol(lo < x < hi) = V(x > lo) - V(x > hi), in each coordinate.
  double sum = 0.0;
  for (int i = 0; i < 2; ++i)
    for (int j = 0; j < 2; ++j)
      for (int k = 0; k < 2; ++k) {
        const double sign = ((i + j + k) % 2 == 0) ? 1.0 : -1.0;
        sum += sign * sphere_orthant_volume(R, x[i], y[j], z[k]);
      }
  return std::clamp(sum, 0.0, ball);
}

Vec3 CellGrid::spacing() const {
  return Vec3((hi.x() - lo.x()) / cells[0], (hi.y() - lo.y()) / cells[1],
              (hi.z() - lo.z()) / cells[2]);
}
double CellGrid::cell_volume() const { return spacing().prod(); }
std::size_t CellGrid::size() const {
  return static_cast<std::size_t>(cells[0]) * cells[1] * cells[2];
}
std::size_t CellGrid::index(int i, int j, int k) const {
  return static_cast<std::size_t>(i) + cells[0] * (static_cast<std::size_t>(j) + cells[1] * k);
}
Vec3 CellGrid::cell_lo(int i, int j, int k) const {
  return lo + spacing().cwiseProduct(Vec3(i, j, k));
}
Vec3 CellGrid::cell_centre(int i, int j, int k) const {
  return lo + spacing().cwiseProduct(Vec3(i + 0.5, j + 0.5, k + 0.5));
}

std::vector<Vec3> CoarseField::velocity() const {
  std::vector<Vec3> v(mass_density.size(), Vec3::Zero());
  for (std::size_t a = 0; a < v.size(); ++a)
    if (mass_density[a] > 0) v[a] = momentum_density[a] / mass_density[a];
  return v;
}

CoarseGrainer::CoarseGrainer(const CellGrid& grid) {
  for (int d = 0; d < 3; ++d)
    if (grid.cells[d] < 1 || !(grid.hi[d] > grid.lo[d]))
      throw InputError(
          fmt::format("coarse-graining grid: need at least one cell and hi > lo in "
                      "every direction (direction {})",
                      d));
  field_.grid = grid;
  field_.solid_fraction.assign(grid.size(), 0.0);
  field_.mass_density.assign(grid.size(), 0.0);
  field_.momentum_density.assign(grid.size(), Vec3::Zero());
}

void CoarseGrainer::deposit(const Vec3& x, double r, double rho, const Vec3& v) {
  const CellGrid& g = field_.grid;
  const Vec3 h = g.spacing();
  std::array<int, 3> first, last;
  for (int d = 0; d < 3; ++d) {
    first[d] = std::max(0, static_cast<int>(std::floor((x[d] - r - g.lo[d]) / h[d])));
    last[d] = std::min(g.cells[d] - 1, static_cast<int>(std::floor((x[d] + r - g.lo[d]) / h[d])));
    if (last[d] < first[d]) return;  // wholly outside the grid
  }
  const double inv_cell = 1.0 / g.cell_volume();
  for (int k = first[2]; k <= last[2]; ++k)
    for (int j = first[1]; j <= last[1]; ++j)
      for (int i = first[0]; i <= last[0]; ++i) {
        const Vec3 lo = g.cell_lo(i, j, k);
        const double overlap = sphere_box_overlap(x, r, lo, lo + h);
        if (overlap <= 0) continue;
        const std::size_t a = g.index(i, j, k);
        const double fraction = overlap * inv_cell;  // V_{i∩a} / V_a
        field_.solid_fraction[a] += fraction;
        field_.mass_density[a] += rho * fraction;  // m_i V_{i∩a} / (V_i V_a)
        field_.momentum_density[a] += rho * fraction * v;
      }
}

int CoarseGrainer::add_interval(const ParticleSample& first, const ParticleSample& second) {
  for (const ParticleSample* s : {&first, &second})
    if (s->id.size() != s->position.size() || s->radius.size() != s->position.size() ||
        s->density.size() != s->position.size())
      throw InputError(
          fmt::format("coarse-graining: the sample at t = {} has arrays of "
                      "different lengths",
                      s->time));
  const double dt = second.time - first.time;
  if (!(dt > 0))
    throw InputError(fmt::format("coarse-graining: interval from t = {} to t = {} is empty",
                                 first.time, second.time));
  std::unordered_map<long long, std::size_t> later;
  later.reserve(second.id.size());
  for (std::size_t n = 0; n < second.id.size(); ++n) later.emplace(second.id[n], n);
  int matched = 0;
  for (std::size_t n = 0; n < first.id.size(); ++n) {
    const auto it = later.find(first.id[n]);
    if (it == later.end()) continue;
    const Vec3 v = (second.position[it->second] - first.position[n]) / dt;
    deposit(first.position[n], first.radius[n], first.density[n], v);
    ++matched;
  }
  ++field_.intervals;
  return matched;
}

CoarseField CoarseGrainer::mean() const {
  CoarseField m = field_;
  const double w = field_.intervals > 0 ? 1.0 / field_.intervals : 0.0;
  for (std::size_t a = 0; a < m.solid_fraction.size(); ++a) {
    m.solid_fraction[a] *= w;
    m.mass_density[a] *= w;
    m.momentum_density[a] *= w;
  }
  return m;
}

RadialField azimuthal_average(const CoarseField& mean, const Vec3& axis, int rings,
                              double ring_width) {
  if (rings < 1 || !(ring_width > 0))
    throw InputError("azimuthal average: need at least one ring of positive width");
  const CellGrid& g = mean.grid;
  RadialField out;
  out.rings = rings;
  out.layers = g.cells[2];
  out.ring_width = ring_width;
  const std::size_t n = static_cast<std::size_t>(rings) * out.layers;
  std::vector<double> mass(n, 0.0), p_r(n, 0.0), p_z(n, 0.0), phi(n, 0.0), count(n, 0.0);
  for (int k = 0; k < g.cells[2]; ++k)
    for (int j = 0; j < g.cells[1]; ++j)
      for (int i = 0; i < g.cells[0]; ++i) {
        const Vec3 c = g.cell_centre(i, j, k);
        const Vec3 radial(c.x() - axis.x(), c.y() - axis.y(), 0.0);
        const double r = radial.norm();
        const int ring = static_cast<int>(r / ring_width);
        if (ring >= rings) continue;
        const std::size_t a = g.index(i, j, k), b = ring + static_cast<std::size_t>(rings) * k;
        const Vec3 e_r = r > 0 ? Vec3(radial / r) : Vec3::Zero();
        mass[b] += mean.mass_density[a];
        p_r[b] += mean.momentum_density[a].dot(e_r);
        p_z[b] += mean.momentum_density[a].z();
        phi[b] += mean.solid_fraction[a];
        count[b] += 1.0;
      }
  out.r.resize(n), out.z.resize(n), out.solid_fraction.resize(n);
  out.v_r.assign(n, 0.0), out.v_z.assign(n, 0.0);
  for (int k = 0; k < out.layers; ++k)
    for (int ring = 0; ring < rings; ++ring) {
      const std::size_t b = ring + static_cast<std::size_t>(rings) * k;
      out.r[b] = (ring + 0.5) * ring_width;
      out.z[b] = g.cell_centre(0, 0, k).z();
      out.solid_fraction[b] = count[b] > 0 ? phi[b] / count[b] : 0.0;
      if (mass[b] > 0) out.v_r[b] = p_r[b] / mass[b], out.v_z[b] = p_z[b] / mass[b];
    }
  return out;
}

}  // namespace talus::analysis
