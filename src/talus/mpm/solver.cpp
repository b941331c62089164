#include "talus/mpm/solver.hpp"

#include <fmt/format.h>
#include <omp.h>

#include <algorithm>
#include <cmath>

#include "talus/core/error.hpp"
#include "talus/mpm/apic.hpp"
#include "talus/mpm/field_contact.hpp"
#include "talus/mpm/membrane_grid.hpp"
#include "talus/mpm/nonlocal.hpp"
#include "talus/mpm/smoothing.hpp"

namespace talus::mpm {

namespace {

[[noreturn]] void left_grid(double time, std::size_t p) {
  throw RunError(fmt::format(
      "t = {:.6g} s: material point {} left the grid or has a non-finite position; enlarge "
      "[grid] or close its faces with \"roller\"/\"fixed\" boundaries",
      time, p));
}

}  // namespace

template <int D>
Solver<D>::Solver(Grid<D> g, std::vector<Material> m, SolverParams p)
    : grid(std::move(g)), materials(std::move(m)), params(p) {}

template <int D>
double Solver<D>::time_step() const {
  if (params.fixed_time_step > 0.0) return params.fixed_time_step;
  return cfl_time_step(params.cfl);
}

template <int D>
double Solver<D>::cfl_time_step(double cfl) const {
  double speed = 0.0;
  for (std::size_t i = 0; i < particles.size(); ++i) {
    const double c = wave_speed(materials[particles.material[i]]);
    speed = std::max(speed, c + particles.v[i].norm());
  }
  speed = std::max(speed, membrane_max_speed(membranes));
  // A rigid body moves material at its own speed, carried by the same waves.
  double rigid_speed = 0.0;
  for (const auto& r : rigid_bodies) rigid_speed = std::max(rigid_speed, r.max_speed(time));
  speed += rigid_speed;
  double dt = speed > 0.0 ? cfl * grid.h / speed : cfl * grid.h;
  // Explicit viscosity is stable for dt < rho h^2 / (2 D eta).
  for (const auto& m : materials)
    if (const auto* fluid = std::get_if<NewtonianFluid>(&m); fluid && fluid->viscosity > 0.0)
      dt = std::min(dt, cfl * fluid->density * grid.h * grid.h / (D * fluid->viscosity));
  return dt;
}

template <int D>
double Solver<D>::advance() {
  const double dt = time_step();
  step(dt);
  return dt;
}

template <int D>
void Solver<D>::step(double dt) {
  if (by_material_.size() != materials.size() || [&] {
        std::size_t n = 0;
        for (const auto& list : by_material_) n += list.size();
        return n != particles.size();
      }()) {
    by_material_.assign(materials.size(), {});
    for (std::size_t i = 0; i < particles.size(); ++i)
      by_material_[particles.material[i]].push_back(static_cast<int>(i));
  }
  // The membranes' own field, on the grid's nodes and faces.
  const bool any = std::any_of(membranes.begin(), membranes.end(),
                               [](const Membrane<D>& m) { return m.own_field(); });
  if (any && !field_) field_ = MembraneField{grid, grid, {}, {}};
  if (!any) field_.reset();
  with_shape(params.shape, [&](auto shape) { step_with<decltype(shape)>(dt); });
  time += dt;
  last_dt = dt;
  ++steps;
}

namespace {

// The items [first, last) of n that OpenMP's static schedule gives thread c of
// `parts` (the first n % parts threads one more).
std::pair<std::int64_t, std::int64_t> static_block(std::int64_t n, int parts, int c) {
  std::int64_t q = n / parts, first = n % parts;
  if (c < first) {
    ++q;
    first = 0;
  }
  first += q * c;
  return {first, first + q};
}

}  // namespace

// Mass and momentum (and, with forces, internal and gravity forces) of the
// particles on the nodes.
template <int D>
template <class Shape>
void Solver<D>::to_grid(bool forces) {
  const auto n = static_cast<std::int64_t>(particles.size());
  const std::int64_t nodes = grid.nodes();
  const int chunks = chunks_ > 0 ? chunks_ : omp_get_max_threads();
  buffers_.resize(chunks);
  const Vec g = gravity();
  const double l = params.gimp_half_width;
  const bool apic = params.transfer == Transfer::Apic;
  const bool offsets = forces && field_;
  // Submerged points: added mass on their inertia, buoyancy on their weight.
  const WaterParams& water = params.water;
  const double added_density = water.added_mass_coefficient * water.density;
  if (offsets) field_->soil_offset.resize(nodes);
  bool outside = false;
  std::int64_t bad = 0;
#pragma omp parallel
  {
    Stencil<D, Shape> st;
    // Chunk c holds the particles OpenMP's static schedule would give thread c
    // of `chunks`: with one chunk per thread, the bits of a per-thread split.
    const int team = omp_get_num_threads();
    for (int c = omp_get_thread_num(); c < chunks; c += team) {
      NodeBuffer& buf = buffers_[c];
      buf.mass.assign(nodes, 0.0);
      buf.momentum.assign(nodes, Vec::Zero());
      if (forces) buf.force.assign(nodes, Vec::Zero());
      if (offsets) buf.offset.assign(nodes, Vec::Zero());
      const auto [first, last] = static_block(n, chunks, c);
      for (std::int64_t p = first; p < last; ++p) {
        if (!st.compute(grid, particles.x[p], l)) {
#pragma omp critical
          {
            outside = true;
            bad = p;
          }
          continue;
        }
        const double vol = particles.volume[p];
        const bool wet = particles.x[p][D - 1] < water.level;
        const double m = particles.mass[p];
        const double mi = wet ? m + added_density * vol : m;  // inertia
        const Vec mv = mi * particles.v[p];
        const auto sigma = particles.state[p].stress.template topLeftCorner<D, D>().eval();
        const auto mc = apic ? (mi * apic_velocity_gradient<D>(st, particles.affine[p])).eval()
                             : Eigen::Matrix<double, D, D>::Zero().eval();
        const Vec buoyancy = (-water.density * vol) * g;
        for (int k = 0; k < st.count; ++k) {
          const auto a = st.node[k];
          buf.mass[a] += st.w[k] * mi;
          buf.momentum[a] += st.w[k] * (apic ? (mv + mc * st.dx[k]).eval() : mv);
          if (forces) buf.force[a] += st.w[k] * m * g - vol * (sigma * st.grad[k]);
          if (forces && wet) buf.force[a] += st.w[k] * buoyancy;
          if (offsets) buf.offset[a] -= (st.w[k] * mi) * st.dx[k];  // over grid.mass
        }
      }
    }
#pragma omp barrier
    // Sum in chunk order: the same result for this chunk count on any team.
#pragma omp for schedule(static)
    for (std::int64_t a = 0; a < nodes; ++a) {
      double m = 0.0;
      Vec mv = Vec::Zero(), f = Vec::Zero();
      for (int t = 0; t < chunks; ++t) {
        m += buffers_[t].mass[a];
        mv += buffers_[t].momentum[a];
        if (forces) f += buffers_[t].force[a];
      }
      grid.mass[a] = m;
      grid.momentum[a] = mv;
      if (forces) grid.force[a] = f;
      if (offsets) {
        Vec o = Vec::Zero();
        for (int t = 0; t < chunks; ++t) o += buffers_[t].offset[a];
        field_->soil_offset[a] = o;
      }
    }
  }
  if (outside) left_grid(time, bad);
}

template <int D>
Grid<D>& Solver<D>::grid_of(std::size_t membrane) {
  return membranes[membrane].own_field() ? field_->membranes : grid;
}

template <int D>
double Solver<D>::half_width_of(std::size_t membrane) const {
  return membranes[membrane].own_field() ? 0.0 : params.gimp_half_width;
}

template <int D>
template <class Shape>
void Solver<D>::membranes_to_grids(bool forces) {
  if (field_) {
    field_->membranes.clear();
    if (forces) field_->on_nodes.reset(grid.nodes());
  }
  for (std::size_t i = 0; i < membranes.size(); ++i) {
    const bool own = membranes[i].own_field() && forces;
    membrane_to_grid<D, Shape>(membranes[i], grid_of(i), gravity(), half_width_of(i), forces, time,
                               own ? &field_->on_nodes : nullptr);
  }
  if (field_) {
    Grid<D>& g = field_->membranes;
    g.fold(g.mass, g.momentum, forces ? &g.force : nullptr);
  }
}

template <int D>
template <class Shape>
void Solver<D>::constrain_and_contact(double dt, double mass_floor) {
  const std::int64_t nodes = grid.nodes();
  Grid<D>& walls = field_ ? field_->combined : grid;
  if (field_) {
    // The two fields as one body: mass, and the centre-of-mass velocities.
    const Grid<D>& m = field_->membranes;
#pragma omp parallel for schedule(static)
    for (std::int64_t a = 0; a < nodes; ++a) {
      const double total = grid.mass[a] + m.mass[a];
      walls.mass[a] = total;
      const bool empty = total <= mass_floor;
      walls.velocity[a] =
          empty ? Vec::Zero().eval()
                : ((grid.mass[a] * grid.velocity[a] + m.mass[a] * m.velocity[a]) / total).eval();
      walls.velocity_old[a] =
          empty ? Vec::Zero().eval()
                : ((grid.mass[a] * grid.velocity_old[a] + m.mass[a] * m.velocity_old[a]) / total)
                      .eval();
    }
  }
  if (!rigid_bodies.empty()) {
    rigid_to_grid<Shape>(dt);
    rigid_contact(walls, mass_floor);
  }
  const double l = params.gimp_half_width;
  for (const auto& m : membranes) clamp_membrane_nodes<D, Shape>(m, walls, walls.velocity, l);
  // The updated velocities first: they decide which nodes of a friction face
  // touch it, and those take the roller's constraint in velocity_old too.
  const double flip = params.transfer == Transfer::Apic ? 0.0 : params.flip;
  walls.constrain_velocity(walls.velocity, &walls.velocity_old, flip);
  walls.constrain(walls.velocity_old);
  if (!field_) return;
  MembraneField& f = *field_;
  split_contact<D>(walls, grid, f.membranes, f.soil_offset, f.on_nodes, flip, mass_floor);
  walls.constrain(grid.velocity_old);
  // The soil where it touches the membranes either took v_c (approaching) or
  // moves away from them, so of a friction face only the roller and fixed
  // faces apply to it: a friction face holds only what presses on it, and
  // soil leaving the sheet is not pressing. (The tests' block slides at the
  // same rate either way: 1.8430 here, 1.8448 m/s^2 held both ways,
  // measured.) The membranes take the momentum the soil leaves behind, which
  // may push them toward a wall: stopped there, without friction (the walls'
  // friction acted on v_c).
  walls.constrain(grid.velocity, false);
  if (!rigid_bodies.empty()) rigid_contact(f.membranes, mass_floor, false);
  f.membranes.constrain_velocity(f.membranes.velocity, nullptr, 0.0, false);
  f.membranes.constrain(f.membranes.velocity_old);
  for (std::size_t i = 0; i < membranes.size(); ++i)
    clamp_membrane_nodes<D, Shape>(membranes[i], grid_of(i), grid_of(i).velocity, l);
}

template <int D>
template <class Shape>
void Solver<D>::step_with(double dt) {
  const auto n = static_cast<std::int64_t>(particles.size());
  const std::int64_t nodes = grid.nodes();
  double mass_floor = 0.0;
  for (double m : particles.mass) mass_floor = std::max(mass_floor, m);
  mass_floor = 1e-12 * std::max(mass_floor, membrane_max_mass(membranes));

  // 1. particles -> grid
  to_grid<Shape>(true);
  membranes_to_grids<Shape>(true);
  grid.fold(grid.mass, grid.momentum, &grid.force);

  // 2. grid momentum update with Cundall's local damping, then the walls and
  // the contact between the soil and the membranes in their own field
  update_nodes(grid, dt, mass_floor);
  if (field_) update_nodes(field_->membranes, dt, mass_floor);
  if (params.water.present())
    for (std::size_t i = 0; i < membranes.size(); ++i)
      membrane_drag<D, Shape>(membranes[i], grid_of(i), params.water, dt, half_width_of(i),
                              mass_floor);
  constrain_and_contact<Shape>(dt, mass_floor);

  // 3. grid -> particles: velocities (and for USL positions and gradients)
  const double flip = params.flip, l = params.gimp_half_width;
  const bool usl = params.scheme == Scheme::Usl;
  const bool apic = params.transfer == Transfer::Apic;
#pragma omp parallel for schedule(static)
  for (std::int64_t p = 0; p < n; ++p) {
    Stencil<D, Shape> st;
    st.compute(grid, particles.x[p], l);  // checked in to_grid
    Vec dv = Vec::Zero(), v_pic = Vec::Zero();
    typename Eigen::Matrix<double, D, D> grad_v = Eigen::Matrix<double, D, D>::Zero();
    for (int k = 0; k < st.count; ++k) {
      const Vec& vn = grid.velocity[st.node[k]];
      dv += st.w[k] * (vn - grid.velocity_old[st.node[k]]);
      v_pic += st.w[k] * vn;
      if (usl) grad_v += vn * st.grad[k].transpose();
    }
    if (apic) {
      particles.v[p] = v_pic;
      particles.affine[p] = apic_affine<D>(st, grid.velocity);
    } else {
      particles.v[p] = flip * (particles.v[p] + dv) + (1.0 - flip) * v_pic;
    }
    if (usl) {
      particles.velocity_gradient[p] = embed(grad_v);
      particles.x[p] += dt * v_pic;
    }
  }
  for (std::size_t i = 0; i < membranes.size(); ++i) {
    membrane_velocities<D, Shape>(membranes[i], grid_of(i), flip, half_width_of(i));
    if (usl) membrane_move<D, Shape>(membranes[i], grid_of(i), dt, half_width_of(i));
  }

  if (!usl) {
    // 4. MUSL: the new particle momenta back to the grid, then the gradient
    to_grid<Shape>(false);
    membranes_to_grids<Shape>(false);
    grid.fold(grid.mass, grid.momentum, nullptr);
    auto remapped = [&](Grid<D>& field) {
#pragma omp parallel for schedule(static)
      for (std::int64_t a = 0; a < nodes; ++a)
        field.velocity_old[a] =
            field.mass[a] > mass_floor ? (field.momentum[a] / field.mass[a]).eval() : Vec::Zero();
    };
    remapped(grid);
    if (field_) remapped(field_->membranes);
    for (std::size_t i = 0; i < membranes.size(); ++i)
      clamp_membrane_nodes<D, Shape>(membranes[i], grid_of(i), grid_of(i).velocity_old, l);
    // The walls' contacts of this step (the combined field's, with a membrane field).
    const Grid<D>& walls = field_ ? field_->combined : grid;
    walls.constrain(grid.velocity_old);
    if (field_) walls.constrain(field_->membranes.velocity_old);
#pragma omp parallel for schedule(static)
    for (std::int64_t p = 0; p < n; ++p) {
      Stencil<D, Shape> st;
      st.compute(grid, particles.x[p], l);
      Vec v_move = Vec::Zero();
      typename Eigen::Matrix<double, D, D> grad_v = Eigen::Matrix<double, D, D>::Zero();
      for (int k = 0; k < st.count; ++k) {
        v_move += st.w[k] * grid.velocity[st.node[k]];
        grad_v += grid.velocity_old[st.node[k]] * st.grad[k].transpose();
      }
      particles.velocity_gradient[p] = embed(grad_v);
      particles.x[p] += dt * v_move;
    }
    for (std::size_t i = 0; i < membranes.size(); ++i)
      membrane_move<D, Shape>(membranes[i], grid_of(i), dt, half_width_of(i));
  }

  // 5. volumes and stresses; the rigid bodies move on exactly
  update_stresses(dt);
  for (auto& r : rigid_bodies) r.advance(time, dt);
  for (std::int64_t p = 0; p < n; ++p)
    if (!particles.v[p].allFinite() || !particles.x[p].allFinite()) left_grid(time + dt, p);
}

// Weights, prescribed momenta and surface normals of the boundary particles
// on the nodes (serial: boundary particles are few and cheap).
template <int D>
template <class Shape>
void Solver<D>::rigid_to_grid(double dt) {
  rigid_nodes_.resize(rigid_bodies.size());
  const double l = params.gimp_half_width;
  for (std::size_t b = 0; b < rigid_bodies.size(); ++b) {
    const RigidBody<D>& body = rigid_bodies[b];
    RigidNodes<D>& nodes = rigid_nodes_[b];
    nodes.reset(grid.nodes());
    Stencil<D, Shape> st;
    for (std::size_t p = 0; p < body.x.size(); ++p) {
      if (!st.compute(grid, body.x[p], l))
        throw RunError(fmt::format(
            "t = {:.6g} s: boundary particle {} of rigid body {} left the grid; enlarge [grid]",
            time, p, b + 1));
      const Vec v = body.velocity_at(body.x[p], time, dt);
      const double w = body.weight[p];
      for (int k = 0; k < st.count; ++k) {
        if (st.w[k] <= 0.0) continue;
        const auto a = st.node[k];
        if (nodes.weight[a] == 0.0) nodes.touched.push_back(a);
        nodes.weight[a] += w * st.w[k];
        nodes.momentum[a] += w * st.w[k] * v;
        nodes.normal[a] += w * st.w[k] * body.normal[p];
      }
    }
  }
}

template <int D>
void Solver<D>::update_nodes(Grid<D>& field, double dt, double mass_floor) {
  const std::int64_t nodes = field.nodes();
  const double alpha = params.local_damping;
  // Velocity a node's bed friction can take away in this step.
  const double bed_dv = params.basal_friction * params.bed_normal_gravity * dt;
#pragma omp parallel for schedule(static)
  for (std::int64_t a = 0; a < nodes; ++a) {
    const double m = field.mass[a];
    if (m <= mass_floor) {
      field.velocity_old[a].setZero();
      field.velocity[a].setZero();
      continue;
    }
    const Vec v = field.momentum[a] / m;
    Vec f = field.force[a];
    if (alpha > 0.0)
      for (int d = 0; d < D; ++d)
        f[d] -= alpha * std::abs(f[d]) * (v[d] > 0 ? 1 : v[d] < 0 ? -1 : 0);
    field.velocity_old[a] = v;
    Vec trial = v + dt / m * f;
    if (bed_dv > 0.0) {
      // Friction opposes the trial sliding velocity; a node it would reverse sticks.
      const double speed = trial.norm();
      trial = speed <= bed_dv ? Vec::Zero().eval() : (trial * (1.0 - bed_dv / speed)).eval();
    }
    field.velocity[a] = trial;
  }
}

template <int D>
void Solver<D>::rigid_contact(Grid<D>& field, double mass_floor, bool with_friction) {
  for (std::size_t b = 0; b < rigid_bodies.size(); ++b) {
    RigidBody<D>& body = rigid_bodies[b];
    const RigidNodes<D>& nodes = rigid_nodes_[b];
    double work = 0.0;
    for (const auto a : nodes.touched) {
      if (field.mass[a] <= mass_floor) continue;
      const Vec vr = nodes.momentum[a] / nodes.weight[a];
      const double g = nodes.normal[a].norm();
      const Vec before = field.velocity[a];
      // Stick, or no normal (opposite faces cancel): the rigid velocity.
      if (with_friction && (body.contact == RigidContact::Stick || g == 0.0))
        field.velocity[a] = vr;
      else if (g > 0.0)
        field.velocity[a] = friction_contact<Vec>(before, vr, -nodes.normal[a] / g,
                                                  with_friction ? body.friction : 0.0);
      work += field.mass[a] * (field.velocity[a] - before).dot(vr);
    }
    body.work += work;
  }
}

template <int D>
void Solver<D>::update_stresses(double dt) {
  if (params.volumetric_smoothing) smooth_volumetric_strain(grid, particles, smoothing_);
  for (std::size_t m = 0; m < materials.size(); ++m) {
    const std::vector<int>& list = by_material_[m];
    const auto count = static_cast<std::int64_t>(list.size());
    const double ell = m < cohesion_length.size() ? cohesion_length[m] : 0.0;
    if (ell > 0.0) {
      // The dilation dV/V0 of this step (compaction restores no bonds), averaged.
      dilation_.resize(list.size());
#pragma omp parallel for schedule(static)
      for (std::int64_t k = 0; k < count; ++k) {
        const int p = list[k];
        dilation_[k] = std::max(0.0, particles.volume[p] * particles.velocity_gradient[p].trace() *
                                         dt / particles.volume0[p]);
      }
      nonlocal_average(particles, list, ell, dilation_, nonlocal_scratch_);
    }
    std::visit(
        [&](const auto& model) {
#pragma omp parallel for schedule(static)
          for (std::int64_t k = 0; k < count; ++k) {
            const int p = list[k];
            const Mat3& lp = particles.velocity_gradient[p];
            const double v_old = particles.volume[p];
            particles.volume[p] = v_old * (1.0 + lp.trace() * dt);
            const double dv_over_v0 =
                ell > 0.0 ? dilation_[k] : (particles.volume[p] - v_old) / particles.volume0[p];
            model.update(particles.state[p], lp, dt, dv_over_v0);
          }
        },
        materials[m]);
  }
}

template class Solver<2>;
template class Solver<3>;

}  // namespace talus::mpm
