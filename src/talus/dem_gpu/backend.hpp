#pragma once
// The GPU backend for DEM (--backend gpu): a StepperBase that keeps the run's
// state in GPU memory. Built when CMake finds nvcc (TALUS_CUDA); without it,
// and on machines without a GPU, device() says why and make_stepper throws.
// The emulated stepper is the same code compiled for the host (Thrust's
// serial backend): the tests compare it with the CPU stepper everywhere.
#include <memory>
#include <string>

#include "talus/dem/stepper.hpp"

namespace talus::dem::gpu {

struct Device {
  bool usable = false;
  // "NVIDIA H100 80GB HBM3, compute capability 9.0, 132 multiprocessors, 79 GiB",
  // or why there is none to use.
  std::string description;
};
Device device();

// The stepper for a system whose scenario gpu_missing_features (dem/gpu_support.hpp)
// accepted. Throws InputError when no GPU is usable.
template <int D>
std::unique_ptr<StepperBase<D>> make_stepper(DemSystem<D>& system);

// The same stepper run on the host; absent (throws) where talus was built
// without the CUDA toolkit's Thrust headers.
template <int D>
std::unique_ptr<StepperBase<D>> make_emulated_stepper(DemSystem<D>& system);

}  // namespace talus::dem::gpu
