#pragma once
// Which GPU backend test_dem_gpu runs: TALUS_TEST_BACKEND=emulated (the GPU
// stepper's code on the host, every machine) or =gpu (CUDA; the whole binary
// is skipped with a message where no GPU is usable: main.cpp).
#include <cstdlib>
#include <memory>
#include <string>

#include "talus/dem/system.hpp"
#include "talus/dem_gpu/backend.hpp"

namespace talus::dem::test {

inline bool on_device() {
  const char* b = std::getenv("TALUS_TEST_BACKEND");
  return b && std::string(b) == "gpu";
}

template <int D>
std::unique_ptr<StepperBase<D>> backend_stepper(DemSystem<D>& s) {
  return on_device() ? gpu::make_stepper<D>(s) : gpu::make_emulated_stepper<D>(s);
}

}  // namespace talus::dem::test
