#pragma once
// The GPU backend's per-particle and per-pair work, as Thrust functors: nvcc
// runs them as CUDA kernels, g++ (the emulated backend) as loops on the host.
// The contact laws, the kick, the pair kinematics and the walls' closest
// points are the CPU stepper's own (TALUS_HOT / TALUS_HD make them device
// functions under nvcc), so both backends integrate the same equations.
#include <cstdint>

#include "talus/dem/contact/kinematics.hpp"
#include "talus/dem/kick.hpp"
#include "talus/dem/pair_kinematics.hpp"
#include "talus/dem/wall_contact.hpp"
#include "talus/geometry/primitive.hpp"

namespace talus::dem::gpu_detail {

// Particle arrays in device memory, with the field names of dem::Particles,
// so kick_one and pair_kinematics take it as they take the host arrays.
template <int D>
struct ParticleView {
  using Vec = typename Space<D>::Vec;
  using Rot = typename Space<D>::Rot;
  Vec *x, *v, *f, *x_ref;
  Rot *w, *t;
  double *r, *m, *inv_m, *inv_I;
  int *material, *contacts, *wall_contacts;
};

// Sums that several threads add into: hardware atomics on the GPU; the
// emulated backend runs one thread.
TALUS_HD inline void add_to(double* a, double v) {
#ifdef __CUDA_ARCH__
  atomicAdd(a, v);
#else
  *a += v;
#endif
}
TALUS_HD inline void add_to(int* a, int v) {
#ifdef __CUDA_ARCH__
  atomicAdd(a, v);
#else
  *a += v;
#endif
}
template <class V>
TALUS_HD inline void add_to(V* a, const V& b) {
  for (int d = 0; d < V::RowsAtCompileTime; ++d) add_to(&(*a)[d], b[d]);
}

// First half kick and drift of a step; flags a rebuild once a particle has
// moved half the skin since the last build (a NaN position counts as far), then
// clears the force sums for the step's contacts.
template <int D>
struct KickDrift {
  ParticleView<D> p;
  Kick<D> half;
  double dt, half_skin2;
  int* rebuild;
  TALUS_HD void operator()(int i) const {
    ParticleView<D> q = p;
    kick_one<D>(q, i, half);
    q.x[i] += dt * q.v[i];
    const double d2 = (q.x[i] - q.x_ref[i]).squaredNorm();
    if (!(d2 <= half_skin2)) *rebuild = 1;
    q.f[i] = zero_of<typename Space<D>::Vec>();
    q.t[i] = Space<D>::rot_zero();
    q.contacts[i] = 0;
  }
};

// One candidate pair k (i < j in the current order): its force, added to both
// particles, and its history; a pair apart has its history reset (as on the CPU).
template <int D, class Model>
struct PairForces {
  ParticleView<D> p;
  const int *pair_i, *pair_j;
  typename Space<D>::Vec* shear;
  typename Space<D>::Rot* roll;
  const typename Model::Coeffs* coeffs;
  int n_materials;
  double dt;
  TALUS_HD void operator()(int k) const {
    const int i = pair_i[k], j = pair_j[k];
    const typename Space<D>::Vec d = p.x[i] - p.x[j];
    const double d2 = d.squaredNorm();
    const double rs = p.r[i] + p.r[j];
    if (d2 >= rs * rs) {
      shear[k] = zero_of<typename Space<D>::Vec>();
      if constexpr (Model::has_rolling) roll[k] = Space<D>::rot_zero();
      return;
    }
    const PairKinematics<D> pk = pair_kinematics<D, Model::needs_inertia>(p, i, j, d, d2);
    ContactHistory<D> h{shear[k], roll[k]};
    ContactForce<D> cf;
    Model::template compute<D>(coeffs[p.material[i] * n_materials + p.material[j]], pk.kin, h, dt,
                               cf);
    shear[k] = h.shear;
    if constexpr (Model::has_rolling) roll[k] = h.roll;
    const PairResult<D> res = pair_result<D>(pk, cf);
    add_to(&p.f[i], res.f);
    add_to(&p.f[j], typename Space<D>::Vec(-res.f));
    add_to(&p.t[i], res.ti);
    add_to(&p.t[j], res.tj);
    add_to(&p.contacts[i], 1);
    add_to(&p.contacts[j], 1);
  }
};

// The same forces with one thread per particle i over its row of pairs
// (j > i): i's sums stay in registers, only j's go through atomics. Which of
// the two loops is faster is measured (docs/gpu.md); TALUS_GPU_PAIR_LOOP picks.
template <int D, class Model>
struct RowForces {
  PairForces<D, Model> pair;
  const int* row_start;
  TALUS_HD void operator()(int i) const {
    using Vec = typename Space<D>::Vec;
    using Rot = typename Space<D>::Rot;
    const ParticleView<D>& p = pair.p;
    Vec fi = zero_of<Vec>();
    Rot ti = Space<D>::rot_zero();
    int ci = 0;
    for (int k = row_start[i]; k < row_start[i + 1]; ++k) {
      const int j = pair.pair_j[k];
      const Vec d = p.x[i] - p.x[j];
      const double d2 = d.squaredNorm();
      const double rs = p.r[i] + p.r[j];
      if (d2 >= rs * rs) {
        pair.shear[k] = zero_of<Vec>();
        if constexpr (Model::has_rolling) pair.roll[k] = Space<D>::rot_zero();
        continue;
      }
      const PairKinematics<D> pk = pair_kinematics<D, Model::needs_inertia>(p, i, j, d, d2);
      ContactHistory<D> h{pair.shear[k], pair.roll[k]};
      ContactForce<D> cf;
      Model::template compute<D>(pair.coeffs[p.material[i] * pair.n_materials + p.material[j]],
                                 pk.kin, h, pair.dt, cf);
      pair.shear[k] = h.shear;
      if constexpr (Model::has_rolling) pair.roll[k] = h.roll;
      const PairResult<D> res = pair_result<D>(pk, cf);
      fi += res.f;
      ti += res.ti;
      ++ci;
      add_to(&p.f[j], Vec(-res.f));
      add_to(&p.t[j], res.tj);
      add_to(&p.contacts[j], 1);
    }
    if (ci == 0) return;
    add_to(&p.f[i], fi);
    add_to(&p.t[i], ti);
    add_to(&p.contacts[i], ci);
  }
};

// The fields of a particle that change every step, packed for one copy back.
template <int D>
struct Moving {
  typename Space<D>::Vec x, v, f;
  typename Space<D>::Rot w, t;
  int contacts, wall_contacts;
};
template <int D>
struct PackMoving {
  ParticleView<D> p;
  Moving<D>* out;
  TALUS_HD void operator()(int i) const {
    out[i] = {p.x[i], p.v[i], p.f[i], p.w[i], p.t[i], p.contacts[i], p.wall_contacts[i]};
  }
};

// What a step needs of each wall: material, whether it is present, its pivot
// (torques are about it) and its velocity field v = v0 + omega x (x - pivot).
struct WallState {
  Vec3 pivot, v0, omega;
  int material, active, moving;
};

// Particle i against every wall primitive (the backend takes only walls whose
// primitives never share an edge, so each touching one is a contact of its
// own), then the step's second half kick. Forces on the walls go into
// wall_sum (force, torque per wall).
template <int D, class Model>
struct WallForces {
  ParticleView<D> p;
  const geometry::Primitive* prims;
  const int* prim_wall;
  int n_prims;
  const WallState* walls;
  ContactHistory<D>* history;  // n_particles x n_prims
  const typename Model::Coeffs* coeffs;
  int n_materials;
  double dt;
  Vec3* wall_sum;
  Kick<D> half;
  bool kick;
  TALUS_HD void operator()(int i) const {
    using Vec = typename Space<D>::Vec;
    ParticleView<D> q = p;
    q.wall_contacts[i] = 0;
    for (int k = 0; k < n_prims; ++k) {
      ContactHistory<D>& h = history[static_cast<int64_t>(i) * n_prims + k];
      const int w = prim_wall[k];
      geometry::Closest<D> c;
      if (!walls[w].active || !geometry::closest_point<D>(prims[k], q.x[i], q.r[i], c) ||
          !(c.distance < q.r[i])) {
        h = ContactHistory<D>{};
        continue;
      }
      Vec v_wall;
      if (walls[w].moving) {
        const Vec3 at = Space<D>::to3(c.point);
        v_wall = Space<D>::from3(Vec3(walls[w].v0 + walls[w].omega.cross(at - walls[w].pivot)));
      }
      const WallTouch<D> touch = wall_touch<D>(q, i, c, walls[w].moving ? &v_wall : nullptr);
      ContactForce<D> cf;
      Model::template compute<D>(coeffs[q.material[i] * n_materials + walls[w].material], touch.kin,
                                 h, dt, cf);
      const Vec f = apply_wall_force<D>(q, i, touch, cf);
      const Vec3 f3 = Space<D>::to3(f);
      add_to(&wall_sum[2 * w], Vec3(-f3));
      add_to(&wall_sum[2 * w + 1], Vec3(-(Space<D>::to3(c.point) - walls[w].pivot).cross(f3)));
    }
    if (kick) kick_one<D>(q, i, half);
  }
};

// Each wall's sums of the step become its force and torque; a closed step
// also adds them to the impulse, the force extremes and the work (geometry::Wall).
// `wall` holds kWallFields vectors per wall: force, torque, impulse, force_max,
// force_min, and (work, 0, 0).
inline constexpr int kWallFields = 6;
struct CloseWalls {
  Vec3 *sum, *wall;
  const WallState* state;
  double dt;
  bool close_step;
  TALUS_HD void operator()(int w) const {
    Vec3* out = wall + kWallFields * w;
    out[0] = sum[2 * w];
    out[1] = sum[2 * w + 1];
    sum[2 * w] = Vec3(0, 0, 0);
    sum[2 * w + 1] = Vec3(0, 0, 0);
    if (!close_step) return;
    out[2] += out[0] * dt;
    out[3] = out[3].cwiseMax(out[0]);
    out[4] = out[4].cwiseMin(out[0]);
    const WallState& m = state[w];
    if (m.moving) out[5].x() -= (out[0].dot(m.v0) + out[1].dot(m.omega)) * dt;
  }
};

// ---- neighbour search: cells of size >= max diameter + skin, numbered along
// a Morton curve, so that particles sorted by cell key sit near their
// neighbours in memory.

TALUS_HD inline uint64_t spread_bits3(uint64_t v) {  // 21 bits -> every third bit
  v &= 0x1fffff;
  v = (v | v << 32) & 0x1f00000000ffffull;
  v = (v | v << 16) & 0x1f0000ff0000ffull;
  v = (v | v << 8) & 0x100f00f00f00f00full;
  v = (v | v << 4) & 0x10c30c30c30c30c3ull;
  v = (v | v << 2) & 0x1249249249249249ull;
  return v;
}
TALUS_HD inline uint64_t spread_bits2(uint64_t v) {  // 32 bits -> every second bit
  v &= 0xffffffffull;
  v = (v | v << 16) & 0x0000ffff0000ffffull;
  v = (v | v << 8) & 0x00ff00ff00ff00ffull;
  v = (v | v << 4) & 0x0f0f0f0f0f0f0f0full;
  v = (v | v << 2) & 0x3333333333333333ull;
  v = (v | v << 1) & 0x5555555555555555ull;
  return v;
}

// A key no cell has: particles that left the domain sort to the end.
inline constexpr uint64_t kRemoved = ~0ull;

template <int D>
struct CellGrid {
  Vec3 lo;
  double inv_cell;
  int max_coord;  // coordinates are clamped to [0, max_coord]: cells merge, none is lost
  TALUS_HD int coord(double x, int d) const {
    const double c = (x - lo[d]) * inv_cell;
    return c <= 0.0 ? 0 : (c >= max_coord ? max_coord : static_cast<int>(c));
  }
  TALUS_HD uint64_t key(int cx, int cy, int cz) const {
    if constexpr (D == 3) return spread_bits3(cx) | spread_bits3(cy) << 1 | spread_bits3(cz) << 2;
    return spread_bits2(cx) | spread_bits2(cy) << 1;
  }
};

template <int D>
struct CellKeys {
  const typename Space<D>::Vec* x;
  CellGrid<D> grid;
  Vec3 domain_lo, domain_hi;
  bool has_domain;
  uint64_t* keys;
  int* order;
  TALUS_HD void operator()(int i) const {
    order[i] = i;
    if (has_domain)
      for (int d = 0; d < D; ++d)
        if (!(x[i][d] >= domain_lo[d] && x[i][d] <= domain_hi[d])) {
          keys[i] = kRemoved;
          return;
        }
    keys[i] = grid.key(grid.coord(x[i][0], 0), grid.coord(x[i][1], 1),
                       D == 3 ? grid.coord(x[i][D - 1], 2) : 0);
  }
};

TALUS_HD inline int first_not_below(const uint64_t* a, int n, uint64_t key) {
  int lo = 0, hi = n;
  while (lo < hi) {
    const int mid = lo + (hi - lo) / 2;
    if (a[mid] < key)
      lo = mid + 1;
    else
      hi = mid;
  }
  return lo;
}

// Candidate pairs (i, j > i) closer than r_i + r_j + skin, found in the 3^D
// cells around i: counted (out_j == nullptr) or written from row_start[i],
// each with the history its pair had in the previous list (old_*, indexed by
// the particles' previous order; `previous[k]` is new particle k's old index).
template <int D>
struct FindPairs {
  using Vec = typename Space<D>::Vec;
  using Rot = typename Space<D>::Rot;
  const Vec* x;
  const double* r;
  const uint64_t* keys;
  int n;
  CellGrid<D> grid;
  double skin;
  int* count;
  const int* row_start;
  int *out_i, *out_j;
  Vec* out_shear;
  Rot* out_roll;
  const int* previous;
  const int *old_row, *old_j;
  const Vec* old_shear;
  const Rot* old_roll;
  bool carry;
  TALUS_HD void operator()(int i) const {
    const int c[3] = {grid.coord(x[i][0], 0), grid.coord(x[i][1], 1),
                      D == 3 ? grid.coord(x[i][D - 1], 2) : 0};
    int found = 0;
    const int zr = D == 3 ? 1 : 0;
    for (int dz = -zr; dz <= zr; ++dz)
      for (int dy = -1; dy <= 1; ++dy)
        for (int dx = -1; dx <= 1; ++dx) {
          const int cx = c[0] + dx, cy = c[1] + dy, cz = c[2] + dz;
          if (cx < 0 || cy < 0 || cz < 0 || cx > grid.max_coord || cy > grid.max_coord ||
              cz > grid.max_coord)
            continue;
          const uint64_t key = grid.key(cx, cy, cz);
          for (int j = first_not_below(keys, n, key); j < n && keys[j] == key; ++j) {
            if (j <= i) continue;
            const double reach = r[i] + r[j] + skin;
            if ((x[i] - x[j]).squaredNorm() >= reach * reach) continue;
            if (out_j) write(i, j, row_start[i] + found);
            ++found;
          }
        }
    if (!out_j) count[i] = found;
  }

  TALUS_HD void write(int i, int j, int slot) const {
    out_i[slot] = i;
    out_j[slot] = j;
    Vec s = zero_of<Vec>();
    Rot w = Space<D>::rot_zero();
    if (carry) {
      const int a = previous[i], b = previous[j];
      const int lo = a < b ? a : b, hi = a < b ? b : a;
      for (int q = old_row[lo]; q < old_row[lo + 1]; ++q)
        if (old_j[q] == hi) {
          // The old pair's history is that of particle lo against hi.
          s = a == lo ? old_shear[q] : Vec(-old_shear[q]);
          w = a == lo ? old_roll[q] : Rot(-old_roll[q]);
          break;
        }
    }
    out_shear[slot] = s;
    out_roll[slot] = w;
  }
};

// Wall histories follow their particles into the new order.
template <int D>
struct GatherWallHistory {
  const ContactHistory<D>* from;
  ContactHistory<D>* to;
  const int* previous;
  int n_prims;
  TALUS_HD void operator()(int i) const {
    for (int k = 0; k < n_prims; ++k)
      to[static_cast<int64_t>(i) * n_prims + k] =
          from[static_cast<int64_t>(previous[i]) * n_prims + k];
  }
};

}  // namespace talus::dem::gpu_detail
