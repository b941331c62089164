#include "talus/runout/grid/two_phase_viscous.hpp"

#include <algorithm>
#include <cstddef>

namespace talus::runout::two_phase_detail {

void viscous_fluxes(const Terrain& terrain, const std::vector<double>& hf,
                    const std::vector<double>& u, const std::vector<double>& v,
                    const std::vector<double>& nu, double dry, bool open, ViscousFluxes& out) {
  using Index = std::ptrdiff_t;
  const auto& g = terrain.shape();
  const Index nx = static_cast<Index>(g.nx), ny = static_cast<Index>(g.ny);
  const auto& dom = terrain.inside();
  const std::size_t nfx = (g.nx + 1) * g.ny, nfy = g.nx * (g.ny + 1);
  // Sized (and the faces on the grid's edges zeroed) once; every other value
  // is written below.
  if (out.x[0].size() != nfx || out.y[0].size() != nfy) {
    for (int m = 0; m < 2; ++m) out.x[m].assign(nfx, 0.0), out.y[m].assign(nfy, 0.0);
    out.du_dy.assign(g.cells(), 0.0), out.dv_dx.assign(g.cells(), 0.0);
  }
  auto wet = [&](Index c) { return dom[c] && hf[c] > dry; };
  // A central derivative over the wet neighbours (one-sided where one is dry).
  auto derivative = [&](const std::vector<double>& q, Index c, bool has_lo, Index lo, bool has_hi,
                        Index hi, double step) {
    const bool l = has_lo && wet(lo), h = has_hi && wet(hi);
    if (l && h) return 0.5 * (q[hi] - q[lo]) / step;
    if (h) return (q[hi] - q[c]) / step;
    if (l) return (q[c] - q[lo]) / step;
    return 0.0;
  };
#pragma omp parallel for schedule(static)
  for (Index j = 0; j < ny; ++j)
    for (Index i = 0; i < nx; ++i) {
      const Index c = j * nx + i;
      if (!wet(c)) {
        out.du_dy[c] = out.dv_dx[c] = 0.0;
        continue;
      }
      out.du_dy[c] = derivative(u, c, j > 0, c - nx, j < ny - 1, c + nx, g.dy);
      out.dv_dx[c] = derivative(v, c, i > 0, c - 1, i < nx - 1, c + 1, g.dx);
    }
  // A face on the domain's edge (the grid's, or next to no-data cells):
  // stress-free at a wall (free slip); at an open edge the flow continues
  // unchanged beyond it (the ghost is the cell), so only the cross
  // derivative along the edge remains.
  auto edge = [&](Index c, double& normal, double& shear, double along) {
    const double k = open && wet(c) ? nu[c] * hf[c] : 0.0;
    normal = 0.0, shear = k * along;
  };
#pragma omp parallel for schedule(static)
  for (Index j = 0; j < ny; ++j)
    for (Index i = 0; i <= nx; ++i) {  // x-faces between (i - 1, j) and (i, j)
      const Index l = j * nx + i - 1, r = l + 1, f = j * (nx + 1) + i;
      const bool has_l = i > 0 && dom[l], has_r = i < nx && dom[r];
      if (has_l != has_r) {
        const Index c = has_l ? l : r;
        edge(c, out.x[0][f], out.x[1][f], out.du_dy[c]);
        continue;
      }
      if (!has_l || !wet(l) || !wet(r)) {
        out.x[0][f] = out.x[1][f] = 0.0;
        continue;
      }
      const double k = 0.5 * (nu[l] + nu[r]) * std::min(hf[l], hf[r]);
      out.x[0][f] = k * 2.0 * (u[r] - u[l]) / g.dx;
      out.x[1][f] = k * (0.5 * (out.du_dy[l] + out.du_dy[r]) + (v[r] - v[l]) / g.dx);
    }
#pragma omp parallel for schedule(static)
  for (Index j = 0; j <= ny; ++j)
    for (Index i = 0; i < nx; ++i) {  // y-faces between (i, j - 1) and (i, j)
      const Index s = (j - 1) * nx + i, n = s + nx, f = j * nx + i;
      const bool has_s = j > 0 && dom[s], has_n = j < ny && dom[n];
      if (has_s != has_n) {
        const Index c = has_s ? s : n;
        edge(c, out.y[1][f], out.y[0][f], out.dv_dx[c]);
        continue;
      }
      if (!has_s || !wet(s) || !wet(n)) {
        out.y[0][f] = out.y[1][f] = 0.0;
        continue;
      }
      const double k = 0.5 * (nu[s] + nu[n]) * std::min(hf[s], hf[n]);
      out.y[0][f] = k * ((u[n] - u[s]) / g.dy + 0.5 * (out.dv_dx[s] + out.dv_dx[n]));
      out.y[1][f] = k * 2.0 * (v[n] - v[s]) / g.dy;
    }
}

}  // namespace talus::runout::two_phase_detail
