#pragma once
// Where the threads' chunks of a DEM step start (dem/chunk_partition.hpp).
// Part of the run's state, not a cache: the cut fixes the order in which the
// forces on a particle that several chunks touch are summed, and it is made
// from the contacts counted at a neighbour build, which a resumed run no
// longer has. So it goes into the checkpoint, and a resume reuses it.
#include <cstdint>
#include <vector>

namespace talus::dem {

struct ChunkCut {
  int64_t build = -1;           // the neighbour-list build it was made at
  int64_t particles = -1;       // the particle count it was made for
  std::vector<int32_t> starts;  // first particle of each chunk
};

}  // namespace talus::dem
