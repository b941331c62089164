#pragma once
// Validated parameters of a DEM run: what the scenario parser (io) produces and
// the builder (dem/builder) consumes. Plain data, SI units, angles in radians.
// Vectors are always 3D here; 2D runs use x and y and ignore z.
#include <limits>
#include <optional>
#include <string>
#include <vector>

#include "talus/core/space.hpp"
#include "talus/geometry/flume_params.hpp"
#include "talus/geometry/wall_params.hpp"

namespace talus::dem {

using geometry::kNever;
// Wall and flume descriptions belong to the geometry layer, which builds them.
using geometry::FlumeParams;
using geometry::WallKind;
using geometry::WallMotionParams;
using geometry::WallParams;

struct MaterialParams {
  std::string name;
  double density = 0.0;           // kg/m^3
  double youngs_modulus = 0.0;    // Pa (Hertz laws)
  double poisson_ratio = 0.3;     // -
  double restitution = 0.5;       // - (hertz_mindlin)
  double friction = 0.5;          // Coulomb coefficient mu (tan of the friction angle)
  double rolling_friction = 0.0;  // mu_r (epsd)
  double normal_stiffness = 0.0;  // N/m (linear)
  double shear_stiffness = 0.0;   // N/m (linear)
  double damping_ratio = 0.0;     // critical damping ratio beta (linear)
  double dissipation = 0.0;       // A in s (viscoelastic_hertz)
};

enum class RollingModel { None, Epsd, Kuen };
// How two materials combine a coefficient (friction, rolling friction).
enum class PairRule { Max, Min, Harmonic, Mean };

// A coefficient given for one pair of materials overrides the rule.
struct PairOverride {
  std::string material_a, material_b;
  std::optional<double> friction, rolling_friction, restitution;
};

struct ContactParams {
  std::string model = "hertz_mindlin";  // a name from ContactLaws (contact/laws.hpp)
  RollingModel rolling = RollingModel::None;
  PairRule friction_rule = PairRule::Max;
  std::vector<PairOverride> pairs;
  bool lock_rotation = false;       // Kuen's Model 1: translation only
  double local_damping = 0.0;       // PFC local damping alpha (default off)
  bool dashpot_may_pull = true;     // linear: whether the normal dashpot may pull
  double tangential_damping = 0.3;  // viscoelastic_hertz gamma_t
  // Kuen rolling resistance
  double kuen_wall_depth = 0.15e-3;   // u_rr [m]
  double kuen_particle_factor = 0.5;  // mu_Br per step
  double kuen_reference_step = 0.0;   // s: mu_Br holds at this step; 0 = at every step (Kuen)
  // EPSD (type C) rolling resistance
  double epsd_stiffness_factor = 2.25;  // k_r = factor * mu_r^2 * R_eff^2 * k_n (Ai et al.)
  double epsd_damping_ratio = 0.3;      // eta_r of the critical rotational damping
};

// One particle given explicitly (verification cases, small tests).
struct ParticleSpec {
  Vec3 position = Vec3::Zero(), velocity = Vec3::Zero(), angular_velocity = Vec3::Zero();
  double radius = 0.0;
  std::string material;
};

enum class SourceKind { List, Lattice, RandomFill, Grow, File };

struct SettleParams {
  bool enabled = false;
  double ke_ratio = 1e-5;  // stop when KE < ratio * m_total * g * L (L = mean diameter)
  double max_time = 5.0;   // s of simulated settling at most
};

struct ParticleSourceParams {
  SourceKind kind = SourceKind::List;
  std::string material;
  std::vector<ParticleSpec> particles;  // List
  // Lattice: simple cubic/square lattice of sites filling [box_min, box_max).
  // jitter = "peer" applies the deterministic jitter of the peer benchmark.
  Vec3 box_min = Vec3::Zero(), box_max = Vec3::Zero();
  double spacing = 0.0;
  double radius = 0.0;          // monodisperse lattice radius
  std::string jitter = "none";  // none | peer
  // RandomFill / Grow: region is a box or a polygon (2D, counter-clockwise),
  // or (3D, cylinder_radius > 0) the vertical cylinder of that radius whose
  // bounding box is box_min..box_max, or (3D, shell_outer_radius > 0) the
  // spherical shell shell_inner_radius < |x - c| < shell_outer_radius about
  // the centre c of the box (the hollow sphere's grains between two membranes),
  // or (3D, edge_radius > 0) the box with rounded edges (inside a rounded-box
  // membrane).
  std::vector<Vec3> polygon;
  double cylinder_radius = 0.0;
  double shell_inner_radius = 0.0, shell_outer_radius = 0.0;
  double edge_radius = 0.0;
  double radius_min = 0.0, radius_max = 0.0;
  double porosity = 0.0;          // RandomFill target porosity
  double packing_fraction = 0.0;  // Grow target solid fraction
  double shrink = 0.0;            // relative radius shrink after filling (Kuen: 0.03)
  std::optional<int> count;       // number of particles; default from porosity
  SettleParams settle;
  std::string file;        // File: CSV x,y,z,r
  bool generated = false;  // the [flume.release] or [dam_break.release] fill
};

struct OutputParams {
  double snapshot_interval = 0.0;    // s, 0 = only first and last
  double series_interval = 0.0;      // s, 0 = every 100 steps
  double checkpoint_interval = 0.0;  // s, 0 = none
  bool write_snapshots = true;
};

// Where the steps run: the CPU stepper (dem/stepper) or the GPU backend
// (dem_gpu/, CUDA builds only; dem/gpu_support.hpp lists what it runs).
enum class Backend { Cpu, Gpu };

struct RunParams {
  int dimension = 3;
  Backend backend = Backend::Cpu;
  double duration = 0.0;       // s
  double time_step = 0.0;      // s; 0 = automatic (safety * critical)
  double safety_factor = 0.8;  // fraction of the critical step (PFC default)
  Vec3 gravity = Vec3(0, 0, -9.81);
  Vec3 domain_min = Vec3::Zero(), domain_max = Vec3::Zero();  // particles leaving are removed
  double skin = 0.0;  // neighbour-list skin, m; 0 = 0.1 * max diameter
  unsigned seed = 1;
  // Stop when the kinetic energy exceeds this factor times the energy available
  // at the start (kinetic plus potential above the floor); 0 disables the check.
  double ke_blowup_factor = 10.0;
  // Where time_step was set ("file:line: [run] 'time_step'"), for messages.
  std::string time_step_source;
};

// The dam-break test used to calibrate the grain friction (spec: flume.md
// "Dam-break calibration"; Hungr 2008, Kuen Table 7): a column of sand on a
// floor between a back wall at x = 0 and a gate at x = width, the gate removed
// at t = 0. The thesis does not give the geometry; width x height is an input
// (0.4 x 0.2 m gives the 0.080 m^2 bulk area its disk count implies).
// The slope left behind is measured as angles gamma_1..gamma_n of segments of
// `segment_length` along the horizontal, gamma_1 at the toe.
struct DamBreakParams {
  double width = 0.4, height = 0.2;  // m
  double floor_length = 1.5;         // m from the back wall
  std::string wall_material;
  double gate_open = 0.0;       // s
  double segment_length = 0.1;  // m
  int segments = 5;             // gamma_1 (toe) .. gamma_segments
  double profile_bin = 0.01;    // m of x per bin of the surface profile
  double toe_thickness = 0.0;   // m; the toe is the last x this thick (0: 3 mean diameters)
};

// A membrane of DEM membrane particles on a triangle mesh (spec/membranes-and-jamming.md,
// Götz 2024 ch. 3; dem/membrane/). 3D runs only.
enum class MembraneMeshKind { FlatSheet, Cylinder, GeodesicSphere, GeodesicHemisphere, Box, Stl };
// Which membrane particles are pinned: none; every particle on a boundary edge
// ("edge": a sheet's rim, a hemisphere's equator, an open cylinder's two end
// rings); the boundary ring at the bottom or top of a cylinder (the cap's
// outer ring of a capped one); both rings; every particle ("all": a rigid
// body, e.g. the hollow sphere's object, whose supports' reaction is measured).
enum class MembraneFixed { None, Edge, BottomRing, TopRing, BothRings, All };

struct MembraneSpec {
  std::string name;
  MembraneMeshKind mesh = MembraneMeshKind::FlatSheet;
  // flat_sheet: lower-left corner `origin`, size [lx, ly] in its plane z = origin.z.
  // cylinder: axis along z through `origin` (the bottom centre), radius, height, caps.
  // geodesic_sphere / geodesic_hemisphere: centre `origin`, radius, frequency.
  // box: centre `origin`, size [size_x, size_y, size_z], edge_radius, spacing.
  // stl: file, scale, offset.
  Vec3 origin = Vec3::Zero();
  double size_x = 0.0, size_y = 0.0, size_z = 0.0;
  double edge_radius = 0.0;  // m, box: radius of the rounded edges and corners
  double radius = 0.0, height = 0.0;
  bool caps = false;
  double spacing = 0.0;  // m, target edge length (flat_sheet, cylinder, box)
  int frequency = 0;     // geodesic meshes
  std::string file;
  double scale = 1.0;
  Vec3 offset = Vec3::Zero();
  // Material (Götz 2024 Table 2 names).
  double youngs_modulus = 0.0;     // E_m, Pa
  double thickness = 0.0;          // d, m
  double density = 0.0;            // rho_m, kg/m^3
  double spring_damping = 0.0;     // gamma_sp, -
  double bending_stiffness = 0.0;  // k_el, N m
  double bending_damping = 0.0;    // k_diss, N m s
  double pressure = 0.0;           // p, Pa, force A p n per triangle (n outwards): < 0 squeezes
  // The pressure is 0 before pressure_ramp_start and reaches `pressure` at
  // pressure_ramp_end, linearly in between (both 0: applied from t = 0).
  double pressure_ramp_start = 0.0, pressure_ramp_end = 0.0;
  // geodesic_sphere: the particles start at stretch x radius from the centre,
  // the springs' rest lengths are those of `radius` (the hollow sphere's outer
  // membrane held at 1.25 R while the grains are placed, then let go).
  double stretch = 1.0;
  // geodesic_sphere: > 0 puts a rigid frictionless sphere of this radius at
  // the centre that the particles cannot enter (the hollow sphere's object
  // under its membrane): it pushes on them, never pulls, so the membrane can
  // lift off it.
  double core_radius = 0.0;
  MembraneFixed fixed = MembraneFixed::None;
  // Cylinders: walls whose translation the pinned bottom / top ring follows
  // (the triaxial plates); empty = the ring stays where it is.
  std::string bottom_ring_wall, top_ring_wall;
  std::string material;  // [[materials]] entry for grain-membrane contacts
  // Contacts of the membrane's particles with its own triangles
  // (dem/membrane/self_contact.hpp), with the material against itself.
  bool self_contact = false;
};

// The triaxial test (spec/membranes-and-jamming.md, Götz 2024 §3.3.1): which
// plates and membrane the analysis reads. The plates are plane walls with a
// servo (stress-controlled phase up to the top plate's servo_stop, where the
// gap is h0) and then a prescribed velocity; the confining pressure is the
// membrane's -pressure, the plate area its pi R^2.
struct TriaxialParams {
  std::string bottom_plate, top_plate, membrane;
};

// The hollow sphere (spec/membranes-and-jamming.md, Götz 2024 §4.3): the
// object is a rigid geodesic sphere (a membrane with fixed = "all") inside a
// shell of grains closed by the membrane `shell`; the analysis reads the
// normal force of the object's supports (hollow_sphere.hpp).
struct HollowSphereParams {
  std::string object, shell;
  // Poisson ratio of the continuum comparison (eq. 33); the grains' by default.
  double poisson_ratio = 0.0;
};

// The granular gripper (spec/membranes-and-jamming.md, Götz 2024 §4.2): a
// geodesic hemisphere `membrane` (opening up, rim fixed) is held with its free
// particles at hold_stretch x its radius while the grains fall in; at
// `release` they are let go and every rest length is cut by `pretension`.
// The object, a rigid sphere (DrivenSphere) of object_radius, waits at
// object_center until push_start, then rises at push_speed until its top is
// `depth` above the hemisphere's lowest point (centre.z - radius); after
// `relax` the vacuum (the membrane's pressure -vacuum) rises in vacuum_steps
// equal steps of vacuum_step_time each (a linear rise over the first half of
// each step, then held); after `hold` more the object moves down at
// pull_speed until the end of the run. The io reader checks the keys and
// derives the phase times below.
struct GripperParams {
  std::string membrane, object_material;
  double hold_stretch = 1.25, release = 0.0, pretension = 0.125;
  double object_radius = 0.0;
  Vec3 object_center = Vec3::Zero();
  double push_start = 0.0, push_speed = 0.0, depth = 0.0, relax = 0.0;
  double vacuum = 0.0;  // Pa, > 0
  int vacuum_steps = 1;
  double vacuum_step_time = 0.0, hold = 0.0, pull_speed = 0.0;
  // Derived: end of the push, start and end of the vacuum, start of the pull.
  double push_end = 0.0, vacuum_start = 0.0, vacuum_end = 0.0, pull_start = 0.0;
};

// The granular beam in 3-point bending (spec/membranes-and-jamming.md, Götz
// 2024 §5.2) on a closed box `membrane` whose long axis is x and whose vacuum
// is its own pressure ramp. Until mould_end a box mould holds the membrane:
// each face closes in with the membrane (it sits on the outermost particle
// and never moves back out), so the beam keeps its box shape while the vacuum
// compacts it. At bending_start the supports are pinned: the bottom-face
// particles (lowest z of the rest mesh) within support_length of either end
// of the box. Then the load: step 0 holds F = 0, steps 1..n raise F by
// load_step each up to max_load = n load_step, steps n+1..2n lower it back to
// 0; each step lasts step_time, its change ramped in linearly over load_ramp.
// The force acts along -z, shared equally by the top-face particles within
// load_length/2 of the beam's centre (x); the deflection is the mean z of the
// bottom-face particles within measure_length/2 of it, averaged over the last
// half of each step. beam_poisson_ratio is the beam's ν_b of the Timoshenko
// fit (analysis/beam.hpp), which the source leaves open. damping (1/s) slows
// every grain and membrane particle by dv/dt = -damping v from mould_end on,
// so that the beam comes to rest within a step: its own contact damping lets
// the bending mode (~20 Hz at full size) ring for many steps. At rest it
// exerts no force, so the deflection it settles to is the undamped one.
// damping_end stops it (the four-point test damps only the settling, since
// its rods never let the beam rest).
//
// test = FourPoint (source §5.3) drives the bending by displacement instead:
// from bending_start two rods, the top-face particles within load_length/2 of
// x = centre -+ span/6 (span: between the supports' centroids at rest), move
// down together, their speed rising linearly to rod_speed over rod_ramp, until
// they have travelled rod_travel, the midspan deflection that max_strain
// means by ε = 108 h Δz / (23 L²) for the rest length L and height h; then they
// hold. bending_friction, when given, becomes the friction of the grains'
// materials at bending_start (the source's μ_p; the materials' own friction is
// μ_init of the vacuum).
enum class BeamTest { ThreePoint, FourPoint };

struct BeamParams {
  BeamTest test = BeamTest::ThreePoint;
  std::string membrane;
  double mould_end = 0.0, bending_start = 0.0;
  double support_length = 0.0, load_length = 0.0, measure_length = 0.0;
  double max_load = 0.0, load_step = 0.0, step_time = 0.0, load_ramp = 0.0;
  double beam_poisson_ratio = 0.0;
  double damping = 0.0;
  double damping_end = kNever;  // the damping acts from mould_end until this
  double rod_speed = 0.0, rod_ramp = 0.0, max_strain = 0.0;
  // The Gaussian's width (in strain) that smooths σ(ε) before Y_b is sought
  // (analysis/beam_four_point.hpp); the source does not give its own.
  double yield_smoothing = 0.0;
  double rod_travel = 0.0;  // derived (four-point)
  std::optional<double> bending_friction;
  int load_steps = 0;  // derived: n = max_load / load_step
  // The load that step k (0 .. 2n) holds once ramped in.
  double step_load(int k) const { return load_step * (k <= load_steps ? k : 2 * load_steps - k); }
  // Total load at time t (N, along -z; 0 before the first step and after the last).
  double load_at(double t) const;
  // Which load step t falls in (0 .. 2 n), -1 before bending_start, 2n + 1 after.
  int step_at(double t) const;
  // How far the rods have moved down at time t (four-point).
  double rod_travel_at(double t) const;
  double end() const;
};

struct DemScenario {
  std::string name;
  std::string description;
  RunParams run;
  ContactParams contact;
  std::vector<MaterialParams> materials;
  std::vector<WallParams> walls;
  std::vector<ParticleSourceParams> sources;
  std::vector<MembraneSpec> membranes;
  OutputParams output;
  std::optional<FlumeParams> flume;
  std::optional<DamBreakParams> dam_break;
  std::optional<TriaxialParams> triaxial;
  std::optional<HollowSphereParams> hollow_sphere;
  std::optional<GripperParams> gripper;
  std::optional<BeamParams> beam;
};

}  // namespace talus::dem
