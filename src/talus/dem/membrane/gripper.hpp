#pragma once
// The granular gripper's set-up on a built system (params.hpp GripperParams;
// Götz 2024 §4.2): the membrane's free particles held at hold_stretch x its
// radius until `release` (then pre-tension), its stepped vacuum, and the
// object as a driven sphere. The builder calls it after making the membranes.
#include "talus/dem/params.hpp"
#include "talus/dem/system.hpp"

namespace talus::dem::membrane {

// Throws InputError when the membrane or the object's material is missing.
void apply_gripper(const GripperParams& g, const DemScenario& sc, DemSystem<3>& s);

}  // namespace talus::dem::membrane
