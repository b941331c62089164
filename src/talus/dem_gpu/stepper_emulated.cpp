// The emulated backend: the GPU stepper's code on the host, with Thrust's
// serial backend (THRUST_DEVICE_SYSTEM=CPP, set by CMake for this file).
#define TALUS_GPU_NS emulated_backend
#include "talus/dem_gpu/backend.hpp"
#include "talus/dem_gpu/make_stepper.hpp"

namespace talus::dem::gpu {

template <int D>
std::unique_ptr<StepperBase<D>> make_emulated_stepper(DemSystem<D>& s) {
  return emulated_backend::pick_stepper<D>(s);
}

template std::unique_ptr<StepperBase<2>> make_emulated_stepper<2>(DemSystem<2>&);
template std::unique_ptr<StepperBase<3>> make_emulated_stepper<3>(DemSystem<3>&);

}  // namespace talus::dem::gpu
