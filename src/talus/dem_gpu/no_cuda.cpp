// Built in place of stepper_cuda.cu where CMake found no nvcc.
#include "talus/core/error.hpp"
#include "talus/dem_gpu/backend.hpp"

namespace talus::dem::gpu {

Device device() {
  return {false, "this talus was built without the CUDA backend (CMake found no nvcc)"};
}

template <int D>
std::unique_ptr<StepperBase<D>> make_stepper(DemSystem<D>&) {
  throw InputError("--backend gpu: " + device().description);
}

template std::unique_ptr<StepperBase<2>> make_stepper<2>(DemSystem<2>&);
template std::unique_ptr<StepperBase<3>> make_stepper<3>(DemSystem<3>&);

}  // namespace talus::dem::gpu
