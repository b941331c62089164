#pragma once
// The stepper's contact model picked once from the scenario, as
// dem::make_stepper does for the CPU; included by each backend's source.
#include <memory>

#include "talus/core/error.hpp"
#include "talus/dem/contact/laws.hpp"
#include "talus/dem/contact/rolling.hpp"
#include "talus/dem_gpu/stepper_impl.hpp"

namespace talus::dem::TALUS_GPU_NS {

template <int D, class Law>
std::unique_ptr<StepperBase<D>> with_law(DemSystem<D>& s) {
  if (s.contact.rolling == RollingModel::Epsd)
    return std::make_unique<GpuStepper<D, ComposedContact<Law, EpsdRolling>>>(s);
  if (s.contact.rolling != RollingModel::None)
    throw InputError("the GPU backend has rolling resistance none and epsd");
  return std::make_unique<GpuStepper<D, ComposedContact<Law, NoRolling>>>(s);
}

template <int D>
std::unique_ptr<StepperBase<D>> pick_stepper(DemSystem<D>& s) {
  if (!s.membranes.empty()) throw InputError("the GPU backend has no membranes");
  for (const auto& w : s.walls) {
    if (w.has_servo())
      throw InputError("the GPU backend has no stress-controlled walls ('" + w.name + "')");
    for (const auto& p : w.reference)
      if (p.kind == geometry::PrimitiveKind::Triangle)
        throw InputError("the GPU backend has no triangle walls ('" + w.name + "')");
  }
  if (s.contact.model == HertzMindlin::name) return with_law<D, HertzMindlin>(s);
  if (s.contact.model == LinearSpringDashpot::name) return with_law<D, LinearSpringDashpot>(s);
  throw InputError("the GPU backend has the contact models hertz_mindlin and linear, not " +
                   s.contact.model);
}

}  // namespace talus::dem::TALUS_GPU_NS
