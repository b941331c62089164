#pragma once
// The built-in experiments, each defined in its own file beside this one.
#include "talus/run/experiment.hpp"

namespace talus::run {

ExperimentKind flume_experiment();
ExperimentKind dam_break_experiment();
ExperimentKind triaxial_experiment();
ExperimentKind hollow_sphere_experiment();
ExperimentKind gripper_experiment();
ExperimentKind beam_experiment();

}  // namespace talus::run
