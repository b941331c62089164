// The CUDA backend: the stepper's functors run as kernels on the GPU.
#define TALUS_GPU_NS cuda_backend
#include <cuda_runtime.h>

#include <string>

#include "talus/dem_gpu/backend.hpp"
#include "talus/dem_gpu/make_stepper.hpp"

namespace talus::dem::gpu {

Device device() {
  int count = 0;
  const cudaError_t err = cudaGetDeviceCount(&count);
  if (err != cudaSuccess || count == 0)
    return {false, std::string("no usable CUDA GPU: ") +
                       (err != cudaSuccess ? cudaGetErrorString(err) : "none found")};
  cudaDeviceProp prop{};
  cudaGetDeviceProperties(&prop, 0);
  return {true, std::string(prop.name) + ", compute capability " + std::to_string(prop.major) +
                    "." + std::to_string(prop.minor) + ", " +
                    std::to_string(prop.multiProcessorCount) + " multiprocessors, " +
                    std::to_string(prop.totalGlobalMem >> 30) + " GiB"};
}

template <int D>
std::unique_ptr<StepperBase<D>> make_stepper(DemSystem<D>& s) {
  const Device d = device();
  if (!d.usable) throw InputError("--backend gpu: " + d.description);
  return cuda_backend::pick_stepper<D>(s);
}

template std::unique_ptr<StepperBase<2>> make_stepper<2>(DemSystem<2>&);
template std::unique_ptr<StepperBase<3>> make_stepper<3>(DemSystem<3>&);

}  // namespace talus::dem::gpu
