// Built in place of stepper_emulated.cpp where CMake found no Thrust headers.
#include "talus/core/error.hpp"
#include "talus/dem_gpu/backend.hpp"

namespace talus::dem::gpu {

template <int D>
std::unique_ptr<StepperBase<D>> make_emulated_stepper(DemSystem<D>&) {
  throw InputError("the emulated GPU backend needs the CUDA toolkit's Thrust headers");
}

template std::unique_ptr<StepperBase<2>> make_emulated_stepper<2>(DemSystem<2>&);
template std::unique_ptr<StepperBase<3>> make_emulated_stepper<3>(DemSystem<3>&);

}  // namespace talus::dem::gpu
