#pragma once
// The explicit MPM step (Sulsky et al. 1994; mpm.md "Algorithm"):
//   particle -> grid (lumped mass, momentum, internal and gravity forces),
//   grid update with local damping and the face constraints,
//   grid -> particle (FLIP/PIC blend), then the stress update either with the
//   grid velocities of this step (USL) or after re-mapping the new particle
//   velocities to the grid (MUSL, Sulsky's modified update, the default).
// The step is instantiated per shape function and chosen by a switch outside
// the particle loops. The particle-to-grid loops run on OpenMP threads, each
// into its own node arrays that are then summed in thread order, so results
// are the same run to run for a given number of threads.
#include <cstdint>
#include <optional>
#include <vector>

#include "talus/mpm/field_contact.hpp"
#include "talus/mpm/grid.hpp"
#include "talus/mpm/materials.hpp"
#include "talus/mpm/membrane.hpp"
#include "talus/mpm/particles.hpp"
#include "talus/mpm/rigid.hpp"
#include "talus/mpm/water.hpp"

namespace talus::mpm {

enum class Scheme { Usl, Musl };
// Grid-to-particle velocity transfer: FLIP/PIC blend (flip), or APIC.
enum class Transfer { FlipPic, Apic };

struct SolverParams {
  ShapeKind shape = ShapeKind::Gimp;
  Scheme scheme = Scheme::Musl;
  double flip = 0.99;  // FLIP share of the velocity update (1 = FLIP, 0 = PIC)
  Transfer transfer = Transfer::FlipPic;
  // Jassim (2011): the volumetric strain increment averaged over each cell
  // (against volumetric locking, mpm/smoothing.hpp).
  bool volumetric_smoothing = false;
  double local_damping = 0.0;    // Cundall's local damping coefficient, [0, 1)
  double cfl = 0.3;              // dt = cfl h / (c + |v|max)
  double fixed_time_step = 0.0;  // > 0: use this instead of the CFL rule
  Vec3 gravity = Vec3::Zero();
  double gimp_half_width = 0.25;  // particle half-width over h (GIMP), <= 1/2
  // 2D plan view of a mass sliding on a bed (depth-averaged, as van den Bout's
  // model): Coulomb friction mu g_n per unit mass at every node, against the
  // node's trial velocity and never reversing it. 0 = no bed.
  double basal_friction = 0.0;
  double bed_normal_gravity = 0.0;  // m/s^2, g cos(slope)
  WaterParams water;
};

template <int D>
class Solver {
 public:
  using Vec = typename Space<D>::Vec;

  Solver(Grid<D> grid, std::vector<Material> materials, SolverParams params);

  Grid<D> grid;
  Particles<D> particles;
  // Boundary particles with prescribed motion, in contact with the material.
  std::vector<RigidBody<D>> rigid_bodies;
  // Geotextile membranes on the same grid (membrane.hpp, membrane_grid.hpp).
  std::vector<Membrane<D>> membranes;
  std::vector<Material> materials;
  // Per material: the length over which the dilation that drives the cohesion
  // loss is averaged (nonlocal.hpp); 0 or absent = local.
  std::vector<double> cohesion_length;
  SolverParams params;
  double time = 0.0;
  std::int64_t steps = 0;
  double last_dt = 0.0;

  // The CFL step C h / max(c + |v|) over the particles (or the fixed one).
  double time_step() const;
  // The CFL rule's step with Courant number `cfl` whatever the parameters say:
  // cfl = 1 is the stability limit a fixed step is checked against.
  double cfl_time_step(double cfl) const;
  // One step of length dt. Throws RunError when a particle leaves the grid or
  // a velocity stops being finite.
  void step(double dt);
  // One step of time_step().
  double advance();
  // The particles' transfer to the grid is cut into `chunks` pieces (0: one
  // per thread of the parallel region), summed in piece order: results depend
  // on the pieces, not on how many threads compute them. Set it to the thread
  // count asked for, and a run can go on with fewer threads in the same bits.
  void set_chunks(int chunks) { chunks_ = chunks; }

  Vec gravity() const { return Space<D>::from3(params.gravity); }

 private:
  template <class Shape>
  void step_with(double dt);
  // Mass and momentum (with forces: and forces; with a membrane field: and
  // the soil's mass-weighted offsets) of the particles on the nodes.
  template <class Shape>
  void to_grid(bool forces);
  // The membranes on the grid, or on their own field (cleared first).
  template <class Shape>
  void membranes_to_grids(bool forces);
  // The walls (rigid bodies, clamps, faces) on the grid, or with a membrane
  // field on both fields together, then the contact between them.
  template <class Shape>
  void constrain_and_contact(double dt, double mass_floor);
  // Step 2 on one field: velocities with local damping and bed friction.
  void update_nodes(Grid<D>& field, double dt, double mass_floor);
  Grid<D>& grid_of(std::size_t membrane);
  // GIMP half-width of a membrane's nodes: 0 (the linear hat) in the
  // membranes' own field. With GIMP's width a sheet on a floor reaches the
  // row of nodes a cell inside the soil above it, and the block of
  // tests/mpm/test_field_contact.cpp slid 11 % faster than Coulomb allows
  // (2.0061 against 1.8129 m/s^2; 1.8430 with the hat, measured).
  double half_width_of(std::size_t membrane) const;
  template <class Shape>
  void rigid_to_grid(double dt);
  // The material velocity at the nodes shared with a rigid body, corrected.
  // with_friction = false: no penetration only (the bodies' friction taken
  // as 0, stick bodies as friction bodies).
  void rigid_contact(Grid<D>& field, double mass_floor, bool with_friction = true);
  void update_stresses(double dt);

  std::vector<std::vector<int>> by_material_;
  struct NodeBuffer {
    std::vector<double> mass;
    std::vector<Vec> momentum, force, offset;
  };
  // The membranes with a soil friction move in one velocity field of their
  // own; the walls act on the soil's and theirs together (field_contact.hpp).
  struct MembraneField {
    Grid<D> membranes, combined;
    MembraneNodes<D> on_nodes;
    std::vector<Vec> soil_offset;  // sum N_i m_p (x_p - x_i)
  };
  std::optional<MembraneField> field_;
  std::vector<NodeBuffer> buffers_;                  // one per chunk
  int chunks_ = 0;                                   // set_chunks
  std::vector<RigidNodes<D>> rigid_nodes_;           // one per rigid body
  std::vector<double> smoothing_;                    // per-cell sums (volumetric smoothing)
  std::vector<double> dilation_, nonlocal_scratch_;  // non-local cohesion loss
};

}  // namespace talus::mpm
