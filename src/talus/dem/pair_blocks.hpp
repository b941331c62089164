#pragma once
// What the vectorised pair loops (dem/hertz_pairs.cpp, dem/linear_pairs.cpp)
// share: their input, the block size and the choice of instruction set at
// run time.
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

}  // namespace pair_blocks

}  // namespace talus::dem
