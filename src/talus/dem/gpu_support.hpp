#pragma once
// What the GPU backend (src/talus/dem_gpu/) runs. A scenario that uses
// anything else is refused with this list before anything runs, never
// quietly run on the CPU.
#include <string>
#include <vector>

#include "talus/dem/params.hpp"

namespace talus::dem {

// One line per feature of `scenario` the GPU backend lacks; empty when it runs.
std::vector<std::string> gpu_missing_features(const DemScenario& scenario);

// The lines joined into one message (for InputError), naming the scenario.
std::string gpu_refusal(const DemScenario& scenario, const std::vector<std::string>& missing);

}  // namespace talus::dem
