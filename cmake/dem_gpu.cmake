# The GPU backend of DEM (src/talus/dem_gpu/, docs/gpu.md), a layer beside the
# methods: it sees core, geometry, io and dem. Two builds of one stepper:
#  - CUDA kernels (stepper_cuda.cu) when CMake finds nvcc (check_language),
#    for Hopper (sm_90: H100, H200) unless CMAKE_CUDA_ARCHITECTURES says
#    otherwise; without nvcc, no_cuda.cpp says so at run time;
#  - the emulated backend (stepper_emulated.cpp): the same functors on the
#    host through Thrust's serial backend, wherever the CUDA toolkit's Thrust
#    headers are, so that machines without a GPU test the GPU code's logic.
# The sanitizer build leaves CUDA out (ASan and the CUDA runtime do not mix)
# and keeps the emulated backend.
include(CheckLanguage)
option(TALUS_NO_CUDA "Do not build the CUDA backend even where nvcc is found" OFF)
if(NOT TALUS_SANITIZE AND NOT TALUS_NO_CUDA)
  check_language(CUDA)
endif()
set(TALUS_CUDA OFF)
if(CMAKE_CUDA_COMPILER AND NOT TALUS_SANITIZE AND NOT TALUS_NO_CUDA)
  if(NOT DEFINED CMAKE_CUDA_ARCHITECTURES)
    set(CMAKE_CUDA_ARCHITECTURES 90)
  endif()
  enable_language(CUDA)
  # C++20 as the rest of talus: nvcc 12+ has it, CMake 3.25 does not know the flag.
  if(NOT CMAKE_CUDA20_STANDARD_COMPILE_OPTION)
    set(CMAKE_CUDA20_STANDARD_COMPILE_OPTION "-std=c++20")
    set(CMAKE_CUDA20_EXTENSION_COMPILE_OPTION "-std=c++20")
    list(APPEND CMAKE_CUDA_COMPILE_FEATURES cuda_std_20)
  endif()
  set(CMAKE_CUDA_STANDARD 20)
  set(TALUS_CUDA ON)
endif()
get_filename_component(_cuda_bin "${CMAKE_CUDA_COMPILER}" DIRECTORY)
find_path(TALUS_THRUST_INCLUDE_DIR thrust/device_vector.h
  HINTS ${_cuda_bin}/../include/cccl /usr/local/cuda/include/cccl /usr/include)
message(STATUS "talus GPU backend: CUDA ${TALUS_CUDA}, Thrust headers ${TALUS_THRUST_INCLUDE_DIR}")

set(_dir ${TALUS_LAYER_ROOT}/dem_gpu/talus)
file(MAKE_DIRECTORY ${_dir})
foreach(seen core geometry io dem dem_gpu)
  if(NOT EXISTS ${_dir}/${seen})
    file(CREATE_LINK ${CMAKE_SOURCE_DIR}/src/talus/${seen} ${_dir}/${seen} SYMBOLIC)
  endif()
endforeach()
set(_src ${CMAKE_SOURCE_DIR}/src/talus/dem_gpu)
if(TALUS_CUDA)
  set(_backend ${_src}/stepper_cuda.cu)
else()
  set(_backend ${_src}/no_cuda.cpp)
endif()
if(TALUS_THRUST_INCLUDE_DIR)
  set(_emulated ${_src}/stepper_emulated.cpp)
else()
  set(_emulated ${_src}/no_emulation.cpp)
endif()
add_library(talus_dem_gpu STATIC ${_backend} ${_emulated})
target_include_directories(talus_dem_gpu PRIVATE ${TALUS_LAYER_ROOT}/dem_gpu)
target_link_libraries(talus_dem_gpu PUBLIC talus_core talus_dem)
if(TALUS_THRUST_INCLUDE_DIR)
  get_filename_component(_cuda_include ${TALUS_THRUST_INCLUDE_DIR} DIRECTORY)
  set_source_files_properties(${_src}/stepper_emulated.cpp PROPERTIES
    COMPILE_DEFINITIONS THRUST_DEVICE_SYSTEM=THRUST_DEVICE_SYSTEM_CPP)
  target_include_directories(talus_dem_gpu SYSTEM PRIVATE ${TALUS_THRUST_INCLUDE_DIR} ${_cuda_include})
  if(TALUS_SANITIZE)
    # Thrust's device_reference reads a value by binding a reference to a null
    # system tag (thrust/detail/reference.h, convert_to_value_type), which
    # UBSan's null check reports on every read of one element. ASan still
    # traps real null dereferences in this file.
    set_source_files_properties(${_src}/stepper_emulated.cpp PROPERTIES
      COMPILE_OPTIONS -fno-sanitize=null)
  endif()
endif()
if(TALUS_CUDA)
  # Eigen's fixed-size vectors in device code: constexpr std functions are
  # allowed there, and Eigen's defaulted host-device members warn (20012).
  target_compile_options(talus_dem_gpu PRIVATE
    $<$<COMPILE_LANGUAGE:CUDA>:--expt-relaxed-constexpr -diag-suppress=20012,20011,20014 -Xcompiler=-fno-math-errno>)
  set_target_properties(talus_dem_gpu PROPERTIES CUDA_RUNTIME_LIBRARY Static)
  target_compile_definitions(talus_dem_gpu PUBLIC TALUS_HAS_CUDA=1)
endif()
