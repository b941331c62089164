#pragma once
// Where a thread adds the pair forces of its chunk of the pair list. Particles
// that only this thread's chunk touches (the `own` range) get them directly in
// the particle arrays; the others go to the thread's buffer, summed over the
// threads in thread order afterwards. With one thread everything is own.
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

  TALUS_HOT bool own(int i) const { return (i >= own_lo) & (i <= own_hi); }
  // Force fi on i (j gets -fi) and the torques ti, tj, in the order of the
  // one-thread loop.
  TALUS_HOT void add(int i, int j, const Vec& fi, const Rot& ti, const Rot& tj) const {
    const bool oi = own(i), oj = own(j);
    (oi ? f : f_shared)[i] += fi;
    (oj ? f : f_shared)[j] -= fi;
    (oi ? t : t_shared)[i] += ti;
    (oj ? t : t_shared)[j] += tj;
    ++(oi ? contacts : contacts_shared)[i];
    ++(oj ? contacts : contacts_shared)[j];
  }
};

}  // namespace talus::dem
