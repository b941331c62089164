#pragma once
// The particle-pair loop of PFC's linear spring-dashpot without pair rolling
// resistance in 2D (the flume's law; Kuen's rolling acts per particle, not
// per pair), in blocks of touching pairs, as dem/hertz_pairs.hpp does for
// Hertz in 3D: the pairs' state is gathered into small arrays, the kinematics
// and the law run as one loop over the block that the compiler vectorises
// (AVX-512, AVX2 or SSE2, chosen at run time), and the results are added to
// the particles in pair order. Every operation is the one of the scalar path
// (pair_force in stepper.cpp with LinearSpringDashpot::compute) in the same
// order, and the build disables FMA contraction, so both give the same bits.
#include <cstdint>

#include "talus/dem/contact/linear.hpp"
#include "talus/dem/force_target.hpp"
#include "talus/dem/pair_blocks.hpp"

namespace talus::dem {

using LinearPairsInput = PairBlockInput<2, LinearSpringDashpot::Coeffs>;

// Forces of pairs [k0, k1) added into `out` (pair order); returns the number
// of touching pairs. The shear force of each pair is updated, and reset where
// the pair does not touch.
int64_t linear_scatter_pairs(const LinearPairsInput& in, std::size_t k0, std::size_t k1,
                             const ForceTarget<2>& out);

// Which instruction set the block loop uses on this CPU ("avx512f", "avx2" or
// "sse2"), for reports.
const char* linear_pairs_isa();

}  // namespace talus::dem
