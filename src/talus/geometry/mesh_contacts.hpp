#pragma once
// A grain on a triangle mesh touches every triangle around the edge or vertex
// it sits on, each reporting the same (or, on a flat mesh near an edge, a
// slightly farther) closest point. Counted per triangle, a grain on a vertex
// shared by six triangles would feel six contacts: the mesh would be six
// times stiffer there than on a face. Only the true closest points of the
// surface count (the rule of Hu et al. 2013 as the membrane contacts use it):
// a contact at an edge or vertex of a triangle is dropped when another touched
// triangle of the same wall contains that point and is closer, or equally
// close and listed earlier. Contacts on different faces (a grain in a concave
// corner of the mesh) all stay.
#include <cmath>

#include "talus/geometry/primitive.hpp"

namespace talus::geometry {

// prims[k], wall[k], closest[k] and touching[k] describe the primitives one
// grain of radius r touches (touching[k] != 0); clears touching[k] for the
// duplicates described above. Only triangles are affected.
template <int D>
void drop_shared_features(const Primitive* const* prims, const int* wall, const Closest<D>* closest,
                          char* touching, int count, double r) {
  if constexpr (D == 3) {
    // Same point / same distance up to round-off: closest points of
    // neighbouring triangles differ by a few ulps of the coordinates (1e-16 of
    // the mesh size), far below 1e-9 r, while distinct contact points of one
    // grain lie a fair part of r apart. (The membrane contacts,
    // dem/membrane/contact.cpp, use their own topology-based rule.)
    const double tol = 1e-9 * r;
    for (int a = 0; a < count; ++a) {
      if (!touching[a] || prims[a]->kind != PrimitiveKind::Triangle) continue;
      for (int b = 0; b < count; ++b) {
        if (b == a || !touching[b] || wall[b] != wall[a] ||
            prims[b]->kind != PrimitiveKind::Triangle)
          continue;
        Closest<3> on;
        if (!closest_point<3>(*prims[b], closest[a].point, tol, on) || on.distance > tol) continue;
        const double da = closest[a].distance, db = closest[b].distance;
        if (db < da - tol || (std::abs(db - da) <= tol && b < a)) {
          touching[a] = 0;
          break;
        }
      }
    }
  } else {
    (void)prims, (void)wall, (void)closest, (void)touching, (void)count, (void)r;
  }
}

}  // namespace talus::geometry
