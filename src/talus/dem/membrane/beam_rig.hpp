#pragma once
// The granular beam's test rig (params.hpp BeamParams; Götz 2024 §5.2) on its
// membrane: the closing box mould of the preparation, the pinned supports and
// the load of the bending test. The builder sets it up with apply_beam;
// MembraneStep applies it each step; analysis/beam.hpp reads it.
#include <array>
#include <vector>

#include "talus/core/space.hpp"
#include "talus/dem/params.hpp"

namespace talus::dem {
template <int D>
struct DemSystem;
}

namespace talus::dem::membrane {

struct Membrane;

struct BeamRig {
  BeamParams params;
  // The mould's faces: no free particle beyond lo/hi (per axis) before
  // mould_end. They start at the rest mesh's extent.
  Vec3 mould_lo = Vec3::Zero(), mould_hi = Vec3::Zero();
  std::vector<int> supports;  // pinned from bending_start on
  std::vector<int> loaded;    // share load_at(t) along -z
  std::vector<int> measured;  // their mean z is the deflection's
  // The flat faces' particles (-y, +y, -z, +z): the section's width and
  // height are the distances between opposite faces' mean positions.
  std::array<std::vector<int>, 4> faces;
  bool supported = false;
};

// Finds the beam's membrane and its particle sets (from the rest mesh) and
// gives it the rig. Throws InputError for a missing membrane or an empty set.
void apply_beam(const BeamParams& b, const DemScenario& sc, DemSystem<3>& s);

// Keeps the free particles inside the mould (before mould_end: a particle
// beyond a face is put back on it and loses its outward speed), then closes
// each face onto the outermost particle. Nothing from mould_end on.
void hold_in_mould(BeamRig& rig, Membrane& m, double t);
// Pins the supports (fixed, at rest) once t >= bending_start; once.
void pin_supports_if_due(BeamRig& rig, Membrane& m, double t);
// The factor exp(-damping dt) by which velocities fall in a step of dt at
// time t (1 before mould_end or without damping).
double damping_factor(const BeamRig& rig, double t, double dt);
// Adds the load's share to the loaded particles' forces.
void add_load(const BeamRig& rig, Membrane& m, double t);

}  // namespace talus::dem::membrane
