#pragma once
// The resolved parameters of an MPM run, as read from a scenario file by
// io/scenario_mpm.cpp (angles in radians, defaults filled in).
#include <Eigen/Geometry>
#include <array>
#include <optional>
#include <string>
#include <vector>

#include "talus/geometry/flume.hpp"
#include "talus/mpm/grid.hpp"
#include "talus/mpm/materials.hpp"
#include "talus/mpm/membrane.hpp"
#include "talus/mpm/rigid.hpp"
#include "talus/mpm/solver.hpp"

namespace talus::mpm {

struct GridParams {
  Vec3 lo = Vec3::Zero(), hi = Vec3::Zero();
  double cell_size = 0.0;
  // xmin, xmax, ymin, ymax, zmin, zmax (the z pair unused in 2D)
  std::array<BoundaryKind, 6> faces{};
  std::array<double, 6> friction{};  // Coulomb mu of the BoundaryKind::Friction faces
};

// A box of material filled with per_cell^D points per cell.
struct BodyParams {
  std::string material;
  int material_index = 0;
  Vec3 min = Vec3::Zero(), max = Vec3::Zero();
  int per_cell = 2;
  Vec3 velocity = Vec3::Zero();
  // Geostatic initial stress: vertical stress rho g depth below the box top,
  // horizontal k0 times it (k0 < 0, not given: nu / (1 - nu), the elastic
  // value of gravity loading between rollers).
  bool geostatic = false;
  double k0 = -1.0;
};

// A rigid body of boundary particles (per_cell^D per cell) filling a box that
// is then turned by `angle` about `axis` through the hinge, with a prescribed
// motion. A box is the only shape, so inclined plates (a chute, a tilted run-out)
// are turned boxes.
struct RigidBodyParams {
  Vec3 min = Vec3::Zero(), max = Vec3::Zero();
  int per_cell = 2;
  double angle = 0.0;         // rad, initial rotation about motion.hinge
  Vec3 axis = Vec3::UnitZ();  // unit rotation axis (2D: always z)
  RigidMotion motion;
  RigidContact contact = RigidContact::Friction;
  double friction = 0.0;
};

// The Mancarella & Hungr flume (2D): its bed as a rigid friction wall of
// boundary particles and, with a release material, the release triangle
// behind the gate filled with points (mpm/flume.hpp). The analysis keys are
// those of the DEM's [flume] (front quantile, deposit profile bins, tail).
struct MpmFlumeParams {
  geometry::FlumeShape shape;
  double wall_friction = 0.0;    // basal friction angle, rad
  int wall_layers = 3;           // rows of boundary particles below the bed
  std::string release_material;  // empty: no release (points from [[bodies]] only)
  int release_material_index = -1;
  int release_per_cell = 2;
  geometry::FlumeMeasures measures;  // tail_thickness 0: three point spacings of the release
};

struct MpmOutputParams {
  double series_interval = 0.0;      // s; 0 = 200 rows over the run
  double snapshot_interval = 0.0;    // s; 0 = first and last only
  double checkpoint_interval = 0.0;  // s; 0 = no checkpoints
  bool snapshots = true;
};

struct MpmScenario {
  std::string name, description;
  int dimension = 2;
  double duration = 0.0;
  double ke_blowup_factor = 10.0;  // mpm/health.hpp
  SolverParams solver;
  GridParams grid;
  std::vector<MaterialParams> materials;
  std::vector<BodyParams> bodies;
  std::vector<RigidBodyParams> rigid_bodies;
  std::vector<MembraneParams> membranes;
  std::optional<MpmFlumeParams> flume;
  MpmOutputParams output;
};

// The solver with its grid, materials and points. Throws InputError when a
// body lies outside the grid or the GIMP particle would be wider than a cell.
template <int D>
Solver<D> build_mpm(const MpmScenario& sc);

// The boundary particles of a rigid body on a grid of the given cell size.
template <int D>
RigidBody<D> build_rigid_body(const RigidBodyParams& p, double cell_size);

// The initial rotation of a rigid body's box (about the hinge).
template <int D>
Eigen::Matrix<double, D, D> rigid_rotation(const RigidBodyParams& p) {
  if constexpr (D == 2)
    return Eigen::Rotation2Dd(p.angle).toRotationMatrix();
  else
    return Eigen::AngleAxisd(p.angle, p.axis).toRotationMatrix();
}

// K0 used for a body's geostatic stress.
double resolved_k0(const BodyParams& body, const MaterialParams& material);

}  // namespace talus::mpm
