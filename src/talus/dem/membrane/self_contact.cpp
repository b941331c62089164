#include "talus/dem/membrane/self_contact.hpp"

#include <algorithm>

namespace talus::dem::membrane {

bool SelfExclusion::excluded(int vertex, int triangle) const {
  return std::binary_search(list.begin() + start[vertex], list.begin() + start[vertex + 1],
                            triangle);
}

SelfExclusion self_contact_exclusion(const Mesh& mesh) {
  const int nv = static_cast<int>(mesh.num_vertices());
  // Edge neighbours of each vertex, then the triangles around each of them.
  std::vector<std::vector<int>> ring(nv);
  for (const Edge& e : mesh.edges) {
    ring[e.a].push_back(e.b);
    ring[e.b].push_back(e.a);
  }
  SelfExclusion out;
  out.start.assign(nv + 1, 0);
  std::vector<int> tris;
  for (int v = 0; v < nv; ++v) {
    tris.clear();
    ring[v].push_back(v);
    for (int u : ring[v])
      for (int k = mesh.vertex_triangle_start[u]; k < mesh.vertex_triangle_start[u + 1]; ++k)
        tris.push_back(mesh.vertex_triangle_list[k]);
    std::sort(tris.begin(), tris.end());
    tris.erase(std::unique(tris.begin(), tris.end()), tris.end());
    out.list.insert(out.list.end(), tris.begin(), tris.end());
    out.start[v + 1] = static_cast<int>(out.list.size());
  }
  return out;
}

int add_self_contact_forces(Membrane& m, const TriangleGrid& grid, const SelfExclusion& exclusion,
                            double radius, const ContactLaw::Coeffs& coeffs, double dt,
                            ContactMemory& memory, SelfContactScratch& s) {
  int contacts = 0;
  const int nv = static_cast<int>(m.x.size());
  for (int i = 0; i < nv; ++i) {
    grid.query(m.x[i], radius, s.candidates, s.grid);
    s.kept.clear();
    for (int t : s.candidates)
      if (!exclusion.excluded(i, t)) s.kept.push_back(t);
    if (s.kept.empty()) continue;
    select_contacts(m.mesh, m.x, m.x[i], radius, s.kept, s.selected, s.touched);
    if (s.selected.empty()) continue;
    contacts += particle_triangle_forces(m.mesh, m.x, m.v, m.mass, m.f, i, radius, s.selected,
                                         coeffs, dt, memory);
  }
  return contacts;
}

}  // namespace talus::dem::membrane
