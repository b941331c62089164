#pragma once
// Checkpoints of an MPM run: everything a step reads that is not rebuilt from
// the scenario (time, step count, the material points with their constitutive
// state and cohesion, the APIC affine matrices, the positions of the rigid
// bodies' boundary particles, the membranes' nodes or points with York's
// tangents and stretches), so that a resumed run continues bit for bit
// like an uninterrupted one on the same number of threads. The grid is reset
// every step and is not stored.
#include <filesystem>

#include "talus/mpm/solver.hpp"

namespace talus::mpm {

template <int D>
void save_checkpoint(const Solver<D>& solver, const std::filesystem::path& path);

// Restores into a solver built from the same scenario (grid, materials,
// rigid-body weights and motions come from it). Throws InputError on a
// checkpoint that does not fit it.
template <int D>
void load_checkpoint(Solver<D>& solver, const std::filesystem::path& path);

}  // namespace talus::mpm
