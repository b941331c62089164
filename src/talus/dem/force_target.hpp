#pragma once
// Where a chunk of the pair list adds its pair forces (dem/chunk_partition.hpp).
// Particles that only this chunk touches (the `own` range) get them directly in
// the particle arrays; the others go to the chunk's buffer, which starts at
// particle `shared_lo`, summed over the chunks in chunk order afterwards. With
// one thread everything is own.
#include "talus/core/space.hpp"

namespace talus::dem {

template <int D>
struct ForceTarget {
  using Vec = typename Space<D>::Vec;
  using Rot = typename Space<D>::Rot;
  Vec* f;
  Rot* t;
  int* contacts;
  Vec* f_shared;
  Rot* t_shared;
  int* contacts_shared;
  int own_lo, own_hi;  // inclusive; empty when own_hi < own_lo
  int shared_lo;       // the particle of f_shared[0]

  TALUS_HOT bool own(int i) const { return (i >= own_lo) & (i <= own_hi); }
  // Force fi on i (j gets -fi) and the torques ti, tj, in the order of the
  // one-thread loop.
  TALUS_HOT void add(int i, int j, const Vec& fi, const Rot& ti, const Rot& tj) const {
    const bool oi = own(i), oj = own(j);
    const int si = oi ? i : i - shared_lo, sj = oj ? j : j - shared_lo;
    (oi ? f : f_shared)[si] += fi;
    (oj ? f : f_shared)[sj] -= fi;
    (oi ? t : t_shared)[si] += ti;
    (oj ? t : t_shared)[sj] += tj;
    ++(oi ? contacts : contacts_shared)[si];
    ++(oj ? contacts : contacts_shared)[sj];
  }
};

}  // namespace talus::dem
