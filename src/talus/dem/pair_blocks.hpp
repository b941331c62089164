#pragma once
// What the vectorised pair loops (dem/hertz_pairs.cpp, dem/linear_pairs.cpp)
// share: their input, the block size, the choice of instruction set at run
// time and the flush of a block.
#include <algorithm>
#include <cstdint>

#include "talus/dem/force_target.hpp"
#include "talus/dem/neighbour_list.hpp"
#include "talus/dem/particles.hpp"

namespace talus::dem {

// The state a pair loop reads (and the shear history it updates).
template <int D, class Coeffs>
struct PairBlockInput {
  const Particles<D>* particles;
  NeighbourList<D>* neighbours;
  const Coeffs* coeffs;  // the law's coefficients, n_materials x n_materials, row major
  int n_materials;
  double dt;
};

namespace pair_blocks {

// Touching pairs per block: a multiple of the widest vector (8 doubles), small
// enough that the block stays in L1.
constexpr int kBlock = 32;

// `Body`, an always-inline loop over one block, compiled for AVX-512, AVX2 and
// SSE2; `chosen()` is the widest this CPU has. None of them enables FMA (and
// the build sets -ffp-contract=off), so all give the same bits.
template <class Block, void (*Body)(Block&, double)>
struct Kernel {
  using Fn = void (*)(Block&, double);
  struct Choice {
    Fn fn;
    const char* name;  // for reports
  };

  __attribute__((target("avx512f"))) static void avx512(Block& b, double dt) { Body(b, dt); }
  __attribute__((target("avx2"))) static void avx2(Block& b, double dt) { Body(b, dt); }
  static void sse2(Block& b, double dt) { Body(b, dt); }

  static const Choice& chosen() {
    static const Choice choice = [] {
      __builtin_cpu_init();
      if (__builtin_cpu_supports("avx512f")) return Choice{avx512, "avx512f"};
      if (__builtin_cpu_supports("avx2")) return Choice{avx2, "avx2"};
      return Choice{sse2, "sse2"};
    }();
    return choice;
  }
};

// Gathers the rest of a full block's state, computes it with `fn` and adds the
// results to the particles in pair order (the order of the one-thread loop, so
// the sums keep their bits); the new shear goes back to the list. With one
// material the loop set the coefficients of every lane once; with several each
// lane takes its pair's. `Block` has per lane l: gather(l, particles),
// set_coeffs(l, coeffs) and scatter(l, out, shear). Not declared inline, as
// the per-file flush it replaces, so the compiler weighs inlining it the same.
template <int D, class Coeffs, class Block>
void flush(Block& b, const PairBlockInput<D, Coeffs>& in, void (*fn)(Block&, double),
           const ForceTarget<D>& out) {
  const auto& p = *in.particles;
  for (int l = 0; l < b.n; ++l) b.gather(l, p);
  if (in.n_materials > 1)
    for (int l = 0; l < b.n; ++l)
      b.set_coeffs(l, in.coeffs[p.material[b.i[l]] * in.n_materials + p.material[b.j[l]]]);
  fn(b, in.dt);
  auto& shear = in.neighbours->pair_shear;
  for (int l = 0; l < b.n; ++l) b.scatter(l, out, shear);
  b.n = 0;
}

// The forces of the touching pairs among [k0, k1) of the list, block by block;
// returns how many touch. Whether a pair touches is close to random from one
// pair to the next, so the filter has no branch. It runs in two passes over
// chunks of the list: the first only tests the distance and notes the
// touching pairs' indices (a pair that does not touch loses its history); the
// second fills the block from those alone (`Block::put(l, i, j, k, d, d2, ri,
// rj, shear)`; the list's shear moves into the block, which writes the new one
// back). In the flume's flow 2.45 candidates come per contact, and one pass
// that filled a block slot for every candidate wrote most of them in vain.
// The second pass recomputes the same difference, so the bits are those of
// the scalar path (NaN counts as touching there too). The 3D Hertz loop keeps
// its one-pass filter: on the peer column (dense, most candidates touch) two
// passes were no faster (docs/performance.md).
template <int D, class Coeffs, class Block>
int64_t scatter_touching(Block& b, const PairBlockInput<D, Coeffs>& in, std::size_t k0,
                         std::size_t k1, void (*fn)(Block&, double), const ForceTarget<D>& out) {
  using Vec = typename Space<D>::Vec;
  const auto& p = *in.particles;
  const auto& pairs = in.neighbours->pairs;
  auto& shear = in.neighbours->pair_shear;
  constexpr std::size_t kChunk = 256;
  std::size_t hit[kChunk];
  int64_t touching = 0;
  // The count of the block lives in a register (`l`): b.n shares its type
  // with b.i and b.j, so the compiler would reload it after their stores.
  int l = 0;
  for (std::size_t c0 = k0; c0 < k1; c0 += kChunk) {
    const std::size_t c1 = std::min(k1, c0 + kChunk);
    std::size_t m = 0;
    for (std::size_t k = c0; k < c1; ++k) {
      const int i = pairs[k].i, j = pairs[k].j;
      const double d2 = (p.x[i] - p.x[j]).squaredNorm();
      const double rs = p.r[i] + p.r[j];
      const bool touches = !(d2 >= rs * rs);
      hit[m] = k;
      m += touches ? 1 : 0;
      shear[k] = touches ? shear[k] : zero_of<Vec>();
    }
    touching += static_cast<int64_t>(m);
    for (std::size_t q = 0; q < m; ++q) {
      const std::size_t k = hit[q];
      const int i = pairs[k].i, j = pairs[k].j;
      const Vec d = p.x[i] - p.x[j];
      b.put(l, i, j, k, d, d.squaredNorm(), p.r[i], p.r[j], shear[k]);
      shear[k] = zero_of<Vec>();
      if (++l == kBlock) {
        b.n = l;
        flush(b, in, fn, out);
        l = 0;
      }
    }
  }
  b.n = l;
  if (b.n > 0) flush(b, in, fn, out);
  return touching;
}

}  // namespace pair_blocks

}  // namespace talus::dem
