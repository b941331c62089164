#pragma once
// What the vectorised pair loops (dem/hertz_pairs.cpp, dem/linear_pairs.cpp)
// share: their input, the block size, the choice of instruction set at run
// time and the flush of a block.
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

}  // namespace pair_blocks

}  // namespace talus::dem
