#pragma once
// The granular beam's test rig (params.hpp BeamParams; Götz 2024 §5.2) on its
// membrane: the closing box mould of the preparation, the pinned supports and
// the load of the bending test. The builder sets it up with apply_beam;
// MembraneStep applies it each step; analysis/beam.hpp reads it.
#include <array>
#include <span>
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
  std::vector<int> loaded;    // share load_at(t) along -z (three-point)
  // Four-point: the rods' particles, pinned at bending_start and moved down
  // by rod_travel_at(t) from where they were then (rod_anchor); rod_force is
  // the force with which they push the beam down (N, > 0 pushing), from the
  // last force pass; rod_impulse its integral over the steps (N s), whose
  // differences give the mean force between two samples without the jitter
  // of single steps.
  std::vector<int> rods;
  std::vector<Vec3> rod_anchor;
  double rod_force = 0.0, rod_impulse = 0.0;
  std::vector<int> measured;  // their mean z is the deflection's
  // The flat faces' particles (-y, +y, -z, +z): the section's width and
  // height are the distances between opposite faces' mean positions.
  std::array<std::vector<int>, 4> faces;
  bool supported = false;
};

// Finds the beam's membrane and its particle sets (from the rest mesh) and
// gives it the rig. Throws InputError for a missing membrane or an empty set.
void apply_beam(const BeamParams& b, const DemScenario& sc, DemSystem<3>& s);

// The distance between the centroids of the supports at either end (0 when
// one end has none), for the particle positions x.
double support_span(const BeamRig& rig, std::span<const Vec3> x);

// Keeps the free particles inside the mould (before mould_end: a particle
// beyond a face is put back on it and loses its outward speed), then closes
// each face onto the outermost particle. Nothing from mould_end on.
void hold_in_mould(BeamRig& rig, Membrane& m, double t);
// Pins the supports (fixed, at rest) and the rods once t >= bending_start; once.
void pin_supports_if_due(BeamRig& rig, Membrane& m, double t);
// Puts the rods' particles where the rods are at time t (after pinning).
void move_rods(const BeamRig& rig, Membrane& m, double t);
// The force the rods exert on the beam along -z: what holds their particles
// on their path against the forces f on them and gravity g.
double rods_push(const BeamRig& rig, const Membrane& m, const Vec3& g);
// The factor exp(-damping dt) by which velocities fall in a step of dt at
// time t (1 before mould_end, from damping_end on or without damping).
double damping_factor(const BeamRig& rig, double t, double dt);
// Adds the load's share to the loaded particles' forces (three-point).
void add_load(const BeamRig& rig, Membrane& m, double t);

}  // namespace talus::dem::membrane
