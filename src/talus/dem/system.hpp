#pragma once
// The state of a DEM run: particles, walls, contact history, clock. Everything
// a checkpoint must hold lives here; the stepper only adds caches.
#include <cstdint>
#include <string>
#include <vector>

#include "talus/dem/chunk_cut.hpp"
#include "talus/dem/membrane/body.hpp"
#include "talus/dem/membrane/driven_sphere.hpp"
#include "talus/dem/neighbour_list.hpp"
#include "talus/dem/params.hpp"
#include "talus/dem/particles.hpp"
#include "talus/geometry/wall.hpp"

namespace talus::dem {

template <int D>
struct DemSystem {
  using Vec = typename Space<D>::Vec;

  Particles<D> particles;
  std::vector<geometry::Wall> walls;
  std::vector<MaterialParams> materials;
  ContactParams contact;
  std::vector<membrane::MembraneBody> membranes;  // 3D only
  // Rigid spheres on prescribed paths that touch the membranes (the gripper's
  // object); 3D runs with membranes only.
  std::vector<membrane::DrivenSphere> objects;

  Vec gravity = Vec::Zero();
  double dt = 0.0;
  double time = 0.0;
  int64_t step = 0;
  Vec3 domain_min = Vec3::Zero(), domain_max = Vec3::Zero();  // empty box = no removal
  double skin = 0.0;
  int threads = 1;
  int64_t removed = 0;  // particles that left the domain
  // Their kinetic energy (1/2 m v^2) when they were removed: the energy check
  // still counts it, so a blow-up that throws every particle out is caught.
  double removed_kinetic_energy = 0.0;
  bool settling = false;  // the builder settles the packing: walls stay as at t = 0
  // How the builder chose the step, kept for diagnostics and the summary; in
  // the checkpoint, as a resume does not place the particles again.
  double critical_time_step = 0.0;
  double reference_speed = 0.0;  // impact speed the Hertz critical step assumes
  double settle_time = 0.0;      // simulated seconds spent settling before t = 0

  // Flattened current wall primitives and the wall each belongs to.
  std::vector<geometry::Primitive> primitives;
  std::vector<int> primitive_wall;
  NeighbourList<D> neighbours;
  // Displacement and rotation angle of each wall at the last neighbour build:
  // the list is rebuilt once a wall has moved half the skin since then.
  std::vector<Vec3> wall_displacement_at_build;
  std::vector<double> wall_angle_at_build;
  ChunkCut chunk_cut;  // how the threads share the step (dem/chunk_cut.hpp)

  // Filled by every step.
  int64_t pair_contacts = 0;
  int64_t wall_contacts = 0;

  bool has_domain() const { return (domain_max - domain_min).template head<D>().minCoeff() > 0.0; }
  int material_index(const std::string& name) const;
};

// Energies and other global measures.
template <int D>
double kinetic_energy(const Particles<D>& p);
template <int D>
double rotational_energy(const Particles<D>& p);
// Potential energy in gravity g relative to the origin: -sum m g.x
template <int D>
double potential_energy(const Particles<D>& p, const typename Space<D>::Vec& g);

// Front: the largest x of a particle centre (the peers' definition); top: the
// highest centre along the last axis (y in 2D, z in 3D). 0 without particles.
template <int D>
double front_x(const Particles<D>& p);
template <int D>
double top(const Particles<D>& p);

}  // namespace talus::dem
