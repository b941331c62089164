#pragma once
// Checkpoints hold the complete state of a DEM run: particles, forces, contact
// history and the neighbour list itself, so a resumed run continues bit for bit
// like an uninterrupted one.
#include <filesystem>

#include "talus/dem/system.hpp"

namespace talus::dem {

template <int D>
void save_checkpoint(const DemSystem<D>& system, const std::filesystem::path& path);

// Restores into a system built from the same scenario (walls, materials and
// contact settings come from the scenario). Throws InputError on a checkpoint
// that does not fit it.
template <int D>
void load_checkpoint(DemSystem<D>& system, const std::filesystem::path& path);

}  // namespace talus::dem
