#include <fmt/format.h>

#include <Eigen/Geometry>
#include <cmath>

#include "talus/core/error.hpp"
#include "talus/core/memory_limit.hpp"
#include "talus/mpm/flume.hpp"
#include "talus/mpm/scenario.hpp"

namespace talus::mpm {

namespace {

// Centres of n^D equal sub-boxes of [lo, hi] with n = round(extent / dx) per axis.
template <int D>
std::vector<typename Space<D>::Vec> fill_box(const typename Space<D>::Vec& lo,
                                             const typename Space<D>::Vec& hi, double dx,
                                             double& volume) {
  using Vec = typename Space<D>::Vec;
  std::array<int, D> count;
  Vec spacing;
  volume = 1.0;
  int total = 1;
  for (int d = 0; d < D; ++d) {
    count[d] = std::max(1, static_cast<int>(std::round((hi[d] - lo[d]) / dx)));
    spacing[d] = (hi[d] - lo[d]) / count[d];
    volume *= spacing[d];
    total *= count[d];
  }
  std::vector<Vec> points;
  points.reserve(total);
  for (int k = 0; k < total; ++k) {
    int rest = k;
    Vec x;
    for (int d = 0; d < D; ++d) {
      x[d] = lo[d] + (rest % count[d] + 0.5) * spacing[d];
      rest /= count[d];
    }
    points.push_back(x);
  }
  return points;
}

// The flume's bed and release points (2D only; the parser refuses 3D).
template <int D>
void add_flume(Solver<D>& solver, const MpmScenario& sc) {
  if constexpr (D == 2) {
    const MpmFlumeParams& f = *sc.flume;
    const auto g = geometry::make_flume(f.shape);
    const double h = sc.grid.cell_size;
    const int per_cell = f.release_material_index >= 0 ? f.release_per_cell : 2;
    solver.rigid_bodies.push_back(
        flume_bed(g, h / per_cell, f.wall_layers, std::tan(f.wall_friction)));
    for (const Vec2& y : solver.rigid_bodies.back().x)
      if (y.x() < sc.grid.lo.x() || y.x() > sc.grid.hi.x() || y.y() < sc.grid.lo.y() ||
          y.y() > sc.grid.hi.y())
        throw InputError(fmt::format(
            "[flume]: the bed (and {} rows of boundary particles below it) leaves the [grid]; it "
            "spans x in [{:.3f}, {:.3f}] m, y in [{:.3f}, {:.3f}] m",
            f.wall_layers, g.chute_start.x(), g.barrier_end.x(), g.arc_centre.y() - g.radius,
            std::max(g.chute_start.y(), g.barrier_end.y())));
    if (f.release_material_index < 0) return;
    const MaterialParams& mat = sc.materials[f.release_material_index];
    const double dx = h / f.release_per_cell;
    const Vec2 origin(sc.grid.lo.x(), sc.grid.lo.y());
    MaterialState state;
    state.cohesion = initial_cohesion(mat);
    for (const Vec2& x : fill_triangle(g.release[0], g.release[1], g.release[2], dx, origin))
      solver.particles.add(x, Vec2::Zero(), mat.density * dx * dx, dx * dx,
                           f.release_material_index, state);
  }
}

}  // namespace

template <int D>
RigidBody<D> build_rigid_body(const RigidBodyParams& p, double cell_size) {
  using Vec = typename Space<D>::Vec;
  RigidBody<D> body;
  double volume = 0.0;
  body.x =
      fill_box<D>(Space<D>::from3(p.min), Space<D>::from3(p.max), cell_size / p.per_cell, volume);
  body.weight.assign(body.x.size(), volume);
  // A single layer of particles is as near the one face as the opposite one:
  // its normals would cancel and the contact would have no direction.
  for (int d = 0; d < D; ++d)
    if (std::round((p.max[d] - p.min[d]) * p.per_cell / cell_size) < 2.0)
      throw InputError(fmt::format(
          "[[rigid_bodies]]: the box from ({}, {}, {}) to ({}, {}, {}) is one particle thick, so "
          "its contact normals are undefined; make it at least two particle spacings ({} m) "
          "thick",
          p.min.x(), p.min.y(), p.min.z(), p.max.x(), p.max.y(), p.max.z(),
          2.0 * cell_size / p.per_cell));
  // Outward normal of the nearest face; the mean of the nearest ones at ties
  // (edges, corners).
  const Vec lo = Space<D>::from3(p.min), hi = Space<D>::from3(p.max);
  for (const Vec& y : body.x) {
    double nearest = 1e300;
    for (int d = 0; d < D; ++d) nearest = std::min({nearest, y[d] - lo[d], hi[d] - y[d]});
    Vec n = Vec::Zero();
    for (int d = 0; d < D; ++d) {
      if (y[d] - lo[d] <= nearest * (1.0 + 1e-9)) n[d] -= 1.0;
      if (hi[d] - y[d] <= nearest * (1.0 + 1e-9)) n[d] += 1.0;
    }
    body.normal.push_back(n.normalized());
  }
  body.motion = p.motion;
  body.hinge = Space<D>::from3(p.motion.hinge);
  body.contact = p.contact;
  body.friction = p.friction;
  const auto q = rigid_rotation<D>(p);
  for (Vec& y : body.x) y = body.hinge + q * (y - body.hinge);
  for (Vec& n : body.normal) n = q * n;
  body.angle = p.angle;
  return body;
}

double resolved_k0(const BodyParams& body, const MaterialParams& m) {
  if (body.k0 >= 0.0) return body.k0;
  return m.model == NewtonianFluid::name ? 1.0 : m.poisson_ratio / (1.0 - m.poisson_ratio);
}

// The grid nodes and body points a scenario asks for, checked against the
// memory there is before anything is allocated (core/memory_limit.hpp).
template <int D>
void check_memory_need(const MpmScenario& sc) {
  const double h = sc.grid.cell_size;
  double nodes = 1.0;
  for (int d = 0; d < D; ++d) nodes *= std::ceil((sc.grid.hi[d] - sc.grid.lo[d]) / h) + 1.0;
  double points = 0.0;
  for (const auto& b : sc.bodies) {
    double n = 1.0;
    for (int d = 0; d < D; ++d) n *= std::max(1.0, (b.max[d] - b.min[d]) * b.per_cell / h);
    points += n;
  }
  // Per node: the mass and four vector fields of grid.hpp, twice for the
  // solver's scratch; per point: position, velocity, two D x D gradients,
  // stress and state (particles.hpp).
  const double node_bytes = 16.0 * (1 + 4 * D), point_bytes = 8.0 * (4 * D + 2 * D * D + 16);
  check_memory(nodes * node_bytes + points * point_bytes,
               fmt::format("[grid] cell_size = {:.3g} m: {:.3g} grid nodes and {:.3g} material "
                           "points",
                           h, nodes, points));
}

template <int D>
Solver<D> build_mpm(const MpmScenario& sc) {
  using Vec = typename Space<D>::Vec;
  check_memory_need<D>(sc);
  std::array<BoundaryKind, 2 * D> faces;
  std::array<double, 2 * D> friction;
  for (int f = 0; f < 2 * D; ++f) {
    faces[f] = sc.grid.faces[f];
    friction[f] = sc.grid.friction[f];
  }
  Grid<D> grid(Space<D>::from3(sc.grid.lo), Space<D>::from3(sc.grid.hi), sc.grid.cell_size, faces,
               friction);
  std::vector<Material> materials;
  for (MaterialParams m : sc.materials) {
    m.critical_volume_strain = critical_volume_strain(m, sc.grid.cell_size);
    materials.push_back(make_material(m));
  }
  SolverParams params = sc.solver;
  int per_cell = 0;
  for (const auto& b : sc.bodies) per_cell = std::max(per_cell, b.per_cell);
  if (sc.flume && sc.flume->release_material_index >= 0)
    per_cell = std::max(per_cell, sc.flume->release_per_cell);
  if (per_cell > 0) params.gimp_half_width = 0.5 / per_cell;
  Solver<D> solver(std::move(grid), std::move(materials), params);
  for (const auto& m : sc.materials) solver.cohesion_length.push_back(m.nonlocal_length);

  const double h = sc.grid.cell_size;
  const Vec g = Space<D>::from3(sc.solver.gravity);
  const double g_mag = g.norm();
  const Vec up = g_mag > 0.0 ? (-g / g_mag).eval() : Vec::Unit(D - 1);
  for (std::size_t b = 0; b < sc.bodies.size(); ++b) {
    const BodyParams& body = sc.bodies[b];
    const MaterialParams& mat = sc.materials[body.material_index];
    const double dx = h / body.per_cell;
    std::array<int, D> count;
    Vec start;
    for (int d = 0; d < D; ++d) {
      if (body.min[d] < sc.grid.lo[d] - 1e-12 || body.max[d] > sc.grid.hi[d] + 1e-12)
        throw InputError(fmt::format("[[bodies]] #{}: the box lies outside the [grid]", b + 1));
      count[d] = std::max(1, static_cast<int>(std::round((body.max[d] - body.min[d]) / dx)));
      start[d] = body.min[d] + 0.5 * (body.max[d] - body.min[d]) / count[d];
    }
    Vec spacing;
    double volume = 1.0;
    for (int d = 0; d < D; ++d) {
      spacing[d] = (body.max[d] - body.min[d]) / count[d];
      volume *= spacing[d];
    }
    // Top of the body along "up": the corner furthest up.
    double top = -1e300;
    for (int corner = 0; corner < (1 << D); ++corner) {
      Vec c;
      for (int d = 0; d < D; ++d) c[d] = (corner >> d & 1) ? body.max[d] : body.min[d];
      top = std::max(top, up.dot(c));
    }
    const double k0 = resolved_k0(body, mat);
    std::array<int, 3> i{0, 0, 0};
    const int total = D == 2 ? count[0] * count[1] : count[0] * count[1] * count[2];
    for (int k = 0; k < total; ++k) {
      int rest = k;
      for (int d = 0; d < D; ++d) {
        i[d] = rest % count[d];
        rest /= count[d];
      }
      Vec x;
      for (int d = 0; d < D; ++d) x[d] = start[d] + i[d] * spacing[d];
      MaterialState s;
      s.cohesion = initial_cohesion(mat);
      if (body.geostatic && g_mag > 0.0) {
        double vertical = -mat.density * g_mag * (top - up.dot(x));
        // The skeleton carries the weight less the water's buoyancy below
        // the level (mpm/water.hpp): (rho - rho_w) g under water.
        if (const auto& w = sc.solver.water; w.present())
          vertical += w.density * g_mag * std::max(0.0, std::min(top, w.level) - up.dot(x));
        const Vec3 up3 = Space<D>::to3(up);
        s.stress = k0 * vertical * Mat3::Identity() + (1.0 - k0) * vertical * up3 * up3.transpose();
      }
      solver.particles.add(x, Space<D>::from3(body.velocity), mat.density * volume, volume,
                           body.material_index, s);
    }
  }
  for (std::size_t b = 0; b < sc.rigid_bodies.size(); ++b) {
    solver.rigid_bodies.push_back(build_rigid_body<D>(sc.rigid_bodies[b], h));
    for (const Vec& y : solver.rigid_bodies.back().x)
      for (int d = 0; d < D; ++d)
        if (y[d] < sc.grid.lo[d] - 1e-12 || y[d] > sc.grid.hi[d] + 1e-12)
          throw InputError(fmt::format(
              "[[rigid_bodies]] #{}: boundary particles lie outside the [grid]", b + 1));
  }
  for (const auto& m : sc.membranes) {
    solver.membranes.push_back(build_membrane<D>(m, h));
    solver.membranes.back().soil_friction = m.soil_friction;
  }
  if (sc.flume) add_flume<D>(solver, sc);
  return solver;
}

template RigidBody<2> build_rigid_body<2>(const RigidBodyParams&, double);
template RigidBody<3> build_rigid_body<3>(const RigidBodyParams&, double);
template Solver<2> build_mpm<2>(const MpmScenario&);
template Solver<3> build_mpm<3>(const MpmScenario&);

}  // namespace talus::mpm
