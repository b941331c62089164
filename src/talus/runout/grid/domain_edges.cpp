#include "talus/runout/grid/domain_edges.hpp"

namespace talus::runout {

DomainEdges find_domain_edges(const Terrain& terrain) {
  using Index = std::ptrdiff_t;
  const auto& g = terrain.shape();
  const auto& in = terrain.inside();
  const Index nx = static_cast<Index>(g.nx), ny = static_cast<Index>(g.ny);
  DomainEdges d;
  d.interior.assign(g.cells(), 0);
  for (Index j = 0; j < ny; ++j)
    for (Index i = 0; i < nx; ++i) {
      const Index c = j * nx + i;
      if (!in[c]) continue;
      const bool w = i > 0 && in[c - 1], e = i < nx - 1 && in[c + 1];
      const bool s = j > 0 && in[c - nx], n = j < ny - 1 && in[c + nx];
      d.interior[c] = static_cast<unsigned char>((w && e ? 1 : 0) | (s && n ? 2 : 0));
      const Index xf = j * (nx + 1) + i, yf = c;  // the cell's west and south faces
      if (!w) d.faces.push_back({c, xf, true, -g.dy});
      if (!e) d.faces.push_back({c, xf + 1, true, g.dy});
      if (!s) d.faces.push_back({c, yf, false, -g.dx});
      if (!n) d.faces.push_back({c, yf + nx, false, g.dx});
    }
  return d;
}

}  // namespace talus::runout
