#pragma once
// Where a grid solver's domain ends: the terrain's cells less its no-data
// ones. A face between a cell inside and the grid's edge or a cell outside is
// an edge face (a wall, or open: what crosses it leaves and is counted).
#include <cstddef>
#include <vector>

#include "talus/runout/grid/terrain.hpp"

namespace talus::runout {

struct EdgeFace {
  std::ptrdiff_t cell, face;  // the cell inside; the face's index among x- or y-faces
  bool normal_x;              // a face normal to x (index j (nx + 1) + i) or to y (j nx + i)
  double outward_length;      // face length, negative where +flux points inwards
};

struct DomainEdges {
  // Per cell: bit 1 set when both x-neighbours are in the domain, bit 2 both
  // y-neighbours (where a limited slope can be taken).
  std::vector<unsigned char> interior;
  std::vector<EdgeFace> faces;  // in row order: the same sums on any team
};

DomainEdges find_domain_edges(const Terrain& terrain);

}  // namespace talus::runout
