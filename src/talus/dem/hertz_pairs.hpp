#pragma once
// The particle-pair loop of the Hertz-Mindlin law without rolling resistance
// in 3D (the peer benchmark's law), in blocks of touching pairs: their state
// is gathered into small arrays, the kinematics and the law run as one loop
// over the block that the compiler vectorises (AVX-512 or AVX2 where the CPU
// has them, chosen at run time), and the results are added to the particles
// in pair order. Every operation is the one of the scalar path (pair_force in
// stepper.cpp with HertzMindlin::compute) in the same order, and the build
// disables FMA contraction, so both paths give the same bits.
#include <cstdint>

#include "talus/dem/contact/hertz_mindlin.hpp"
#include "talus/dem/force_target.hpp"
#include "talus/dem/pair_blocks.hpp"

namespace talus::dem {

using HertzPairsInput = PairBlockInput<3, HertzMindlin::Coeffs>;

// Forces of pairs [k0, k1) added into `out` (pair order); returns the number
// of touching pairs. The shear history of each pair is updated, and reset
// where the pair does not touch.
int64_t hertz_scatter_pairs(const HertzPairsInput& in, std::size_t k0, std::size_t k1,
                            const ForceTarget<3>& out);

// Which instruction set the block loop uses on this CPU ("avx512f", "avx2" or
// "sse2"), for reports.
const char* hertz_pairs_isa();

}  // namespace talus::dem
