#include "talus/dem/stepper.hpp"

#include <omp.h>

#include <algorithm>
#include <cmath>
#include <exception>
#include <limits>
#include <stdexcept>
#include <string>
#include <type_traits>

#include "talus/core/team_segments.hpp"
#include "talus/dem/chunk_partition.hpp"
#include "talus/dem/contact/laws.hpp"
#include "talus/dem/contact/rolling.hpp"
#include "talus/dem/force_target.hpp"
#include "talus/dem/hertz_pairs.hpp"
#include "talus/dem/kick.hpp"
#include "talus/dem/kuen_rolling.hpp"
#include "talus/dem/linear_pairs.hpp"
#include "talus/dem/membrane/membrane_step.hpp"
#include "talus/dem/pair_kinematics.hpp"
#include "talus/dem/wall_contact.hpp"
#include "talus/dem/wall_motion.hpp"
#include "talus/geometry/mesh_contacts.hpp"

namespace talus::dem {

namespace {

template <int D, class Model>
class Stepper final : public StepperBase<D> {
 public:
  using Vec = typename Space<D>::Vec;
  using Rot = typename Space<D>::Rot;

  explicit Stepper(DemSystem<D>& s) : s_(s) {
    const int m = static_cast<int>(s.materials.size());
    n_materials_ = m;
    coeffs_ = coefficient_table<Model>(s.contact, s.materials);
    friction_.resize(m * m);
    for (int a = 0; a < m; ++a)
      for (int b = 0; b < m; ++b)
        friction_[a * m + b] =
            pair_coefficients(s.contact, s.materials[a], s.materials[b]).friction;
    if constexpr (kHertzBlocks || kLinearBlocks)
      for (const auto& c : coeffs_) coeffs_law_.push_back(c.law);
    kuen_ = KuenRolling(s.contact, s.gravity.norm());
    if constexpr (D == 3)
      if (!s.membranes.empty()) membranes_ = std::make_unique<membrane::MembraneStep>(s);
  }

  void prime() override {
    update_walls(true);
    rebuild();
#pragma omp parallel num_threads(s_.threads)
    {
#pragma omp single
      {
        team_ = omp_get_num_threads();
        prepare_step(team_);
        if constexpr (D == 3)
          if (membranes_) membranes_->compute_forces(s_);
      }
      compute_forces(nullptr);
    }
    close_forces();
  }

  void resume() override { update_walls(true); }

  void rebuild() override {
    remove_escaped();
    s_.neighbours.build(s_.particles, s_.primitives, s_.skin);
    s_.wall_displacement_at_build.clear();
    s_.wall_angle_at_build.clear();
    for (const auto& w : s_.walls) {
      s_.wall_displacement_at_build.push_back(w.displacement(wall_time()));
      s_.wall_angle_at_build.push_back(w.rotation_angle(wall_time()));
    }
  }

  // All threads run the whole step loop in one parallel region; each takes
  // chunks of the particles and pairs in turn (dem/chunk_partition.hpp), the
  // serial parts run on one thread. A step ends without a barrier: its bookkeeping (wall forces,
  // impulses, contact counts, the step counter) is done by the next step's serial part, or here
  // after the last step.
  // With several threads the steps run in segments, each with the whole team
  // or one thread alone, whichever is faster now (core/adaptive_team.hpp): the
  // chunks make the results the same either way.
  void advance(int64_t steps) override {
    error_ = nullptr;
    for (int64_t done = 0; done < steps && !error_;) {
      const int64_t segment = segments_.begin(steps - done);
      sleeps_.store(0, std::memory_order_relaxed);
      run_segment(segments_.team(), segment);
      segments_.end(segment,
                    AdaptiveTeam::sleepy(sleeps_.load(std::memory_order_relaxed), segment));
      done += segment;
    }
    if (step_open_) close_step();
    // Exceptions may not cross the parallel region: they are carried out here.
    if (error_) std::rethrow_exception(error_);
  }

  double critical_time_step(double v_ref) const override {
    const auto& p = s_.particles;
    // The lightest and the smallest particle of each material bound the step.
    double best = 1e300;
    std::vector<double> m_min(n_materials_, 1e300), r_min(n_materials_, 1e300);
    for (std::size_t i = 0; i < p.size(); ++i) {
      m_min[p.material[i]] = std::min(m_min[p.material[i]], p.m[i]);
      r_min[p.material[i]] = std::min(r_min[p.material[i]], p.r[i]);
    }
    std::vector<bool> wall_material(n_materials_, false);
    for (const auto& w : s_.walls) wall_material[w.material] = true;
    for (int a = 0; a < n_materials_; ++a) {
      if (m_min[a] >= 1e300) continue;
      for (int b = 0; b < n_materials_; ++b) {
        const auto& c = coeffs_[a * n_materials_ + b];
        if (m_min[b] < 1e300) {  // particle pair
          const double me = m_min[a] * m_min[b] / (m_min[a] + m_min[b]);
          const double re = r_min[a] * r_min[b] / (r_min[a] + r_min[b]);
          best = std::min(best, Model::critical_time_step(c, me, re, v_ref));
        }
        if (wall_material[b])
          best = std::min(best, Model::critical_time_step(c, m_min[a], r_min[a], v_ref));
      }
    }
    if constexpr (D == 3)
      if (membranes_) best = std::min(best, membranes_->contact_time_step(s_, m_min, r_min, v_ref));
    // A particle in a dense packing has about 2D contacts (4 disks, 6 spheres)
    // and oscillates sqrt(2D) times faster than on one contact; with PFC's
    // damping this is what limits stability (a damped 2D packing does not come
    // to rest at the single-contact estimate: test_verification_packing.cpp).
    // Grain-membrane contacts take the same factor (a grain on a membrane among
    // others has several contacts at once); the membranes' internal bound does not.
    best /= std::sqrt(2.0 * D);
    if constexpr (D == 3)
      if (membranes_) best = std::min(best, membranes_->internal_time_step(s_));
    return best;
  }

  std::vector<PairContactForce> pair_contact_forces() const override {
    const auto& p = s_.particles;
    const auto& nl = s_.neighbours;
    std::vector<PairContactForce> out;
    PairKinematics<D> pk;
    ContactForce<D> cf;
    for (std::size_t k = 0; k < nl.pairs.size(); ++k) {
      ContactHistory<D> h{nl.pair_shear[k], nl.pair_roll[k]};  // a copy: left as it was
      if (!evaluate_pair(k, h, 0.0, pk, cf)) continue;
      const int i = nl.pairs[k].i, j = nl.pairs[k].j;
      out.push_back(
          {i, j, cf.fn, cf.ft.norm(), friction_[p.material[i] * n_materials_ + p.material[j]]});
    }
    return out;
  }

 private:
  void run_segment(int team, int64_t steps) {
#pragma omp parallel num_threads(team) if (team > 1)
    {
#pragma omp single
      {
        team_ = omp_get_num_threads();
        barrier_.reset(team_);
        moved_.assign(team_, 0.0);
      }
      for (int64_t k = 0; k < steps && !error_; ++k) one_step(k == 0);
    }
  }

  // One velocity-Verlet step; called by every thread of the team. `first`:
  // the first step of this parallel region, whose particles are all complete.
  void one_step(bool first) {
    auto& p = s_.particles;
    const double dt = s_.dt;
    const Kick half = kick_params(0.5 * dt);
    double moved = 0.0;
    // First half kick and drift in one pass over the particles, chunk by
    // chunk once the last step has finished the chunk (on any thread).
    auto drift = [&](int i0, int i1) {
      for (int i = i0; i < i1; ++i) {
        kick_one<D>(p, i, half);
        p.x[i] += dt * p.v[i];
        const double d2 = (p.x[i] - s_.neighbours.reference_positions()[i]).squaredNorm();
        // A NaN position counts as infinitely far: the rebuild then stops the run.
        moved = std::isnan(d2) ? std::numeric_limits<double>::infinity() : std::max(moved, d2);
      }
    };
    const int n = static_cast<int>(p.size()), tid = omp_get_thread_num();
    if (!chunked() || first) {
      // Equal shares: the particles may have changed since the last cut.
      drift(static_cast<int>(static_cast<int64_t>(n) * tid / team_),
            static_cast<int>(static_cast<int64_t>(n) * (tid + 1) / team_));
    } else {
      for (int c = partition_.drift_claims.take(tid); c >= 0;
           c = partition_.drift_claims.take(tid)) {
        if (partition_.wait_for_finished(c, force_pass_)) note_sleep();
        drift(partition_.chunk(c).p0, partition_.chunk(c).p1);
      }
    }
    moved_[tid] = moved;
    // The last thread to arrive closes the step and decides on a rebuild.
    if (barrier_.arrive_and_wait([&] { serial_part(); })) note_sleep();
    // A rebuild and the membranes run OpenMP tasks: the whole team joins
    // them in an OpenMP `single` (all threads read the same flag here).
    if (team_tasks_) {
#pragma omp single
      tasked_part();
    }
    if (error_) return;
    compute_forces(&half);
  }

  // The serial part of a step (any one thread, no OpenMP construct): the last
  // step's bookkeeping, the time, servo walls, and whether to rebuild.
  void serial_part() {
    // An exception may not leave the barrier (the others would wait for ever):
    // it is carried out of the parallel region like the rebuild's.
    try {
      serial_bookkeeping();
    } catch (...) {
      error_ = std::current_exception();
      team_tasks_ = false;
    }
  }

  void serial_bookkeeping() {
    const double dt = s_.dt;
    if (step_open_) close_step();
    double moved = 0.0;
    for (double m : moved_) moved = m <= moved ? moved : m;  // NaN-free: infinity marks NaN
    s_.time = static_cast<double>(s_.step + 1) * dt;
    // Stress-controlled walls (geometry/wall.hpp) move on the forces just closed.
    if (!s_.settling)
      for (auto& w : s_.walls) w.advance_servo(s_.time - dt, dt);
    const bool walls_changed = update_walls(false);
    const double wall_moved = wall_motion_since_build();
    const double half_skin = 0.5 * s_.skin;
    rebuild_now_ = walls_changed || !(moved <= half_skin * half_skin) || wall_moved > half_skin;
    bool membranes = false;
    if constexpr (D == 3) membranes = membranes_ != nullptr;
    team_tasks_ = rebuild_now_ || membranes;
    if (!team_tasks_) open_step();
  }

  // The rest of the serial part, where a rebuild or the membranes need it.
  void tasked_part() {
    try {
      if (rebuild_now_) rebuild();
    } catch (...) {
      error_ = std::current_exception();
    }
    if (error_) return;
    open_step();
    // Membranes (serial, dem/membrane/membrane_step.hpp): their whole step,
    // and their contact forces on the grains, which finish_particles adds.
    if constexpr (D == 3)
      if (membranes_) membranes_->step(s_);
  }

  bool chunked() const { return s_.threads > 1; }
  // A thread had to sleep waiting for another (core/team_sync.hpp).
  void note_sleep() { sleeps_.fetch_add(1, std::memory_order_relaxed); }

  void open_step() {
    prepare_step(team_);
    step_open_ = true;
  }

  // The step's serial set-up, once the particles have drifted.
  void prepare_step(int team) {
    ++force_pass_;
    // The chunks follow the thread count asked for, not the team of the
    // moment: a step gives the same bits with one thread or the whole team.
    if (chunked())
      partition_.prepare(s_.threads * kChunksPerThread, s_.particles, s_.neighbours, s_.chunk_cut);
    partition_.force_claims.reset(team, partition_.size());
    // The next step's drift goes by the chunks just prepared (after a resume
    // the first step's serial part is the first to prepare any).
    partition_.drift_claims.reset(team, partition_.size());
    prepare_wall_accumulators(chunked() ? partition_.size() : 1);
    pair_touching_ = 0;
    wall_touching_ = 0;
  }

  // Wall forces and contact counts of the forces just computed.
  void close_forces() {
    s_.pair_contacts = pair_touching_;
    s_.wall_contacts = wall_touching_;
    sum_wall_accumulators();
  }

  // The bookkeeping of a finished step.
  void close_step() {
    close_forces();
    for (auto& w : s_.walls) {
      w.impulse += w.force * s_.dt;
      if (!s_.settling) w.add_work(s_.time, s_.dt);
      w.note_force();
    }
    ++s_.step;
    step_open_ = false;
  }

  // Half kick (dem/kick.hpp), applied particle by particle inside other
  // passes (drift; wall forces), to save passes.
  using Kick = dem::Kick<D>;
  Kick kick_params(double h) const {
    return {s_.gravity, h, s_.contact.local_damping, !s_.contact.lock_rotation};
  }

  // Moves walls to the current time; true when a wall appeared or vanished.
  // (A run without walls once counted as never set up here, so it rebuilt the
  // neighbour list every step: hence the flag, not an empty primitive list.)
  bool update_walls(bool force) {
    bool changed = false;
    if (force || !walls_set_up_) {
      walls_set_up_ = true;
      s_.primitives.clear();
      s_.primitive_wall.clear();
      active_.clear();
      for (std::size_t w = 0; w < s_.walls.size(); ++w) {
        s_.walls[w].update(wall_time());
        for (const auto& prim : s_.walls[w].current) {
          s_.primitives.push_back(prim);
          s_.primitive_wall.push_back(static_cast<int>(w));
        }
        active_.push_back(wall_active(s_.walls[w]));
      }
      return true;
    }
    std::size_t k = 0;
    for (std::size_t w = 0; w < s_.walls.size(); ++w) {
      auto& wall = s_.walls[w];
      const bool act = wall_active(wall);
      if (act != active_[w]) {
        active_[w] = act;
        changed = true;
      }
      if (wall.moves()) {
        wall.update(wall_time());
        for (const auto& prim : wall.current) s_.primitives[k++] = prim;
      } else {
        k += wall.current.size();
      }
    }
    return changed;
  }

  // While the initial packing settles (before t = 0) every wall stands as it
  // is at t = 0 and is present, even one removed at t = 0: the gate holds the
  // release mass until the run starts.
  double wall_time() const { return s_.settling ? 0.0 : s_.time; }
  bool wall_active(const geometry::Wall& w) const { return s_.settling || w.active(s_.time); }

  double wall_motion_since_build() const {
    return wall_motion_since(s_.walls, wall_time(), s_.wall_displacement_at_build,
                             s_.wall_angle_at_build);
  }

  void remove_escaped() {
    auto& p = s_.particles;
    if (!s_.has_domain()) return;
    std::vector<int> keep;
    keep.reserve(p.size());
    for (std::size_t i = 0; i < p.size(); ++i) {
      const Vec3 x = Space<D>::to3(p.x[i]);
      bool inside = true;
      for (int d = 0; d < D; ++d)
        inside = inside && x[d] >= s_.domain_min[d] && x[d] <= s_.domain_max[d];
      if (inside)
        keep.push_back(static_cast<int>(i));
      else
        s_.removed_kinetic_energy += 0.5 * p.m[i] * p.v[i].squaredNorm();
    }
    if (keep.size() == p.size()) return;
    s_.removed += static_cast<int64_t>(p.size() - keep.size());
    // Renumber the lists for the survivors, so the next build can carry their history.
    auto& nl = s_.neighbours;
    std::vector<int> new_index(p.size(), -1);
    for (std::size_t k = 0; k < keep.size(); ++k) new_index[keep[k]] = static_cast<int>(k);
    std::vector<typename NeighbourList<D>::Pair> pairs;
    std::vector<Vec> shear;
    std::vector<Rot> roll;
    for (std::size_t k = 0; k < nl.pairs.size(); ++k) {
      const int a = new_index[nl.pairs[k].i], b = new_index[nl.pairs[k].j];
      if (a < 0 || b < 0) continue;
      pairs.push_back({a, b});
      shear.push_back(nl.pair_shear[k]);
      roll.push_back(nl.pair_roll[k]);
    }
    nl.pairs.swap(pairs);
    nl.pair_shear.swap(shear);
    nl.pair_roll.swap(roll);
    std::vector<int> ws{0}, wp;
    std::vector<ContactHistory<D>> wh;
    for (int i : keep) {
      for (int k = nl.wall_start[i]; k < nl.wall_start[i + 1]; ++k) {
        wp.push_back(nl.wall_prim[k]);
        wh.push_back(nl.wall_history[k]);
      }
      ws.push_back(static_cast<int>(wp.size()));
    }
    nl.wall_start.swap(ws);
    nl.wall_prim.swap(wp);
    nl.wall_history.swap(wh);
    p.permute(keep);
  }

  // Kinematics and force of pair k with the history h, advanced by dt; false
  // when the pair does not touch (then h is not used).
  TALUS_HOT bool evaluate_pair(std::size_t k, ContactHistory<D>& h, double dt,
                               PairKinematics<D>& pk, ContactForce<D>& cf) const {
    const auto& p = s_.particles;
    const int i = s_.neighbours.pairs[k].i, j = s_.neighbours.pairs[k].j;
    const Vec d = p.x[i] - p.x[j];
    const double d2 = d.squaredNorm();
    const double rs = p.r[i] + p.r[j];
    if (d2 >= rs * rs) return false;
    pk = pair_kinematics<D, Model::needs_inertia>(p, i, j, d, d2);
    Model::compute(coeffs_[p.material[i] * n_materials_ + p.material[j]], pk.kin, h, dt, cf);
    return true;
  }

  // Kinematics and force of pair k, its history advanced; false when the pair
  // does not touch (its history is reset).
  TALUS_HOT bool pair_force(std::size_t k, PairResult<D>& out) {
    auto& nl = s_.neighbours;
    ContactHistory<D> h{nl.pair_shear[k], nl.pair_roll[k]};
    PairKinematics<D> pk;
    ContactForce<D> cf;
    if (!evaluate_pair(k, h, s_.dt, pk, cf)) {
      nl.pair_shear[k] = zero_of<Vec>();
      if constexpr (Model::has_rolling) nl.pair_roll[k] = Space<D>::rot_zero();
      return false;
    }
    nl.pair_shear[k] = h.shear;
    if constexpr (Model::has_rolling) nl.pair_roll[k] = h.roll;
    out = pair_result(pk, cf);
    return true;
  }

  // Pair forces, then wall forces and the optional half kick `then_kick`
  // (each particle gets it as soon as its force is complete); called by every
  // thread of the team after prepare_step. Ends without a barrier: a thread
  // goes on with its own particles, the caller closes the forces once all
  // threads are done.
  void compute_forces(const Kick* then_kick) {
    auto& p = s_.particles;
    auto& nl = s_.neighbours;
    const int n = static_cast<int>(p.size());
    const std::size_t np = nl.pairs.size();
    int64_t touching = 0;
    if (!chunked()) {
      for (int i = 0; i < n; ++i) {
        p.f[i] = zero_of<Vec>();
        p.t[i] = Space<D>::rot_zero();
        p.contacts[i] = 0;
      }
      const ForceTarget<D> out{p.f.data(), p.t.data(), p.contacts.data(),
                               p.f.data(), p.t.data(), p.contacts.data(),
                               0,          n - 1,      0};
      touching = scatter_pairs(0, np, out);
      finish_particles(then_kick, 0, n, wall_acc_.data());
    } else {
      // Each thread takes chunks (its own first) and scatters their pairs:
      // forces on particles no other chunk's pairs touch straight into the
      // particle arrays, the others into the chunk's buffer. No barrier: it
      // finishes at once the particles no earlier chunk's pairs reach, the
      // rest once it has no chunk left to scatter and those chunks are done.
      const int tid = omp_get_thread_num();
      thread_local std::vector<int> taken;
      taken.clear();
      auto acc = [&](int c) {
        return wall_acc_.data() + static_cast<std::size_t>(c) * acc_stride();
      };
      auto split = [&](int c) {
        const auto& buf = partition_.chunk(c);
        return std::clamp(buf.wait_hi + 1, buf.p0, buf.p1);
      };
      for (int c = partition_.force_claims.take(tid); c >= 0;
           c = partition_.force_claims.take(tid)) {
        auto& buf = partition_.chunk(c);
        partition_.clear(c, p);
        const ForceTarget<D> out{p.f.data(),   p.t.data(),   p.contacts.data(),
                                 buf.f.data(), buf.t.data(), buf.contacts.data(),
                                 buf.own_lo,   buf.own_hi,   buf.lo};
        touching += scatter_pairs(buf.k0, buf.k1, out);
        partition_.mark_scattered(c, force_pass_);
        partition_.sum_buffers(p, c, split(c), buf.p1);
        finish_particles(then_kick, split(c), buf.p1, acc(c));
        taken.push_back(c);
      }
      for (const int c : taken) {
        const auto& buf = partition_.chunk(c);
        if (partition_.wait_for_earlier(c, force_pass_)) note_sleep();
        partition_.sum_buffers(p, c, buf.p0, split(c));
        finish_particles(then_kick, buf.p0, split(c), acc(c));
        partition_.mark_finished(c, force_pass_);
      }
    }
#pragma omp atomic
    pair_touching_ += touching;
  }

  // Forces of pairs [k0, k1) added into `out`; returns the number of
  // touching pairs. (Summing particle i's share in registers first was
  // measured 2 % slower.)
  int64_t scatter_pairs(std::size_t k0, std::size_t k1, const ForceTarget<D>& out) {
    if constexpr (kHertzBlocks) {
      const HertzPairsInput in{&s_.particles, &s_.neighbours, coeffs_law_.data(), n_materials_,
                               s_.dt};
      return hertz_scatter_pairs(in, k0, k1, out);
    }
    if constexpr (kLinearBlocks) {
      const LinearPairsInput in{&s_.particles, &s_.neighbours, coeffs_law_.data(), n_materials_,
                                s_.dt};
      return linear_scatter_pairs(in, k0, k1, out);
    }
    const auto& pairs = s_.neighbours.pairs;
    int64_t touching = 0;
    PairResult<D> r;
    for (std::size_t k = k0; k < k1; ++k) {
      if (!pair_force(k, r)) continue;
      out.add(pairs[k].i, pairs[k].j, r.f, r.ti, r.tj);
      ++touching;
    }
    return touching;
  }

  // Per-chunk sums of wall force and torque, zeroed every step and reduced in
  // chunk order.
  void prepare_wall_accumulators(int chunks) {
    const int nw = static_cast<int>(s_.walls.size());
    wall_acc_.assign(static_cast<std::size_t>(chunks) * acc_stride(), Vec3::Zero());
    pivots_.resize(nw);
    moving_.resize(nw);
    for (int w = 0; w < nw; ++w) {
      pivots_[w] = s_.walls[w].pivot_at(wall_time());
      moving_[w] = s_.walls[w].moves() && !s_.settling ? 1 : 0;
    }
  }

  // Each chunk's block of wall sums is followed by 192 spare bytes, so that
  // two threads never write the same cache line (measured: shared lines made
  // the wall pass 50 % slower on two threads).
  std::size_t acc_stride() const { return 2 * s_.walls.size() + 8; }

  void sum_wall_accumulators() {
    const int nw = static_cast<int>(s_.walls.size());
    for (int w = 0; w < nw; ++w) {
      s_.walls[w].force.setZero();
      s_.walls[w].torque.setZero();
      for (std::size_t t = 0; t < wall_acc_.size() / acc_stride(); ++t) {
        s_.walls[w].force += wall_acc_[t * acc_stride() + 2 * w];
        s_.walls[w].torque += wall_acc_[t * acc_stride() + 2 * w + 1];
      }
    }
  }

  // The closest points of particle i on its candidate wall primitives
  // (wall_prim[first, first + count)) and whether each touches. With several
  // candidates in 3D a shared edge or vertex of a mesh counts once
  // (geometry/mesh_contacts.hpp). Per-thread scratch arrays: no allocation
  // once they have grown.
  std::pair<const geometry::Closest<D>*, const char*> wall_hits(int i, int first, int count) {
    const auto& p = s_.particles;
    const auto& nl = s_.neighbours;
    thread_local std::vector<geometry::Closest<D>> near;
    thread_local std::vector<char> hit;
    thread_local std::vector<const geometry::Primitive*> prims;
    thread_local std::vector<int> walls;
    if (static_cast<int>(near.size()) < count) {  // grow only: resize is a call per particle
      near.resize(count);
      hit.resize(count);
      prims.resize(count);
      walls.resize(count);
    }
    for (int j = 0; j < count; ++j) {
      const int prim = nl.wall_prim[first + j];
      prims[j] = &s_.primitives[prim];
      walls[j] = s_.primitive_wall[prim];
      hit[j] = active_[walls[j]] &&
               geometry::closest_point<D>(*prims[j], p.x[i], p.r[i], near[j]) &&
               near[j].distance < p.r[i];
    }
    if (D == 3 && count > 1)
      geometry::drop_shared_features<D>(prims.data(), walls.data(), near.data(), hit.data(), count,
                                        p.r[i]);
    return {near.data(), hit.data()};
  }

  // The contact of particle i with wall candidate k (closest point c, which
  // touches): force and torque on the particle and on the wall (this thread's
  // sums `acc`). Returns 1, the contacts it adds.
  TALUS_HOT int wall_contact(int i, int k, const geometry::Closest<D>& c, Vec3* acc) {
    auto& p = s_.particles;
    auto& nl = s_.neighbours;
    const int w = s_.primitive_wall[nl.wall_prim[k]];
    Vec v_wall;
    if (moving_[w])
      v_wall = Space<D>::from3(s_.walls[w].velocity_at(Space<D>::to3(c.point), s_.time));
    const WallTouch<D> touch = wall_touch<D>(p, i, c, moving_[w] ? &v_wall : nullptr);
    ContactForce<D> cf;
    Model::compute(coeffs_[p.material[i] * n_materials_ + s_.walls[w].material], touch.kin,
                   nl.wall_history[k], s_.dt, cf);
    const Vec f = apply_wall_force<D>(p, i, touch, cf);
    const Vec3 f3 = Space<D>::to3(f);
    acc[2 * w] -= f3;
    acc[2 * w + 1] -= (Space<D>::to3(c.point) - pivots_[w]).cross(f3);
    return 1;
  }

  // Particles [i0, i1) once their pair forces are complete: wall contacts
  // (their sums on the walls into `acc`), then the optional half kick and
  // Kuen's rolling resistance.
  void finish_particles(const Kick* then_kick, int i0, int i1, Vec3* acc) {
    auto& p = s_.particles;
    auto& nl = s_.neighbours;
    const bool kuen_on = kuen_.enabled();
    const KuenStep kuen = kuen_.at(s_.dt);
    int64_t touching = 0;
    for (int i = i0; i < i1; ++i) {
      p.wall_contacts[i] = 0;
      const int first = nl.wall_start[i], count = nl.wall_start[i + 1] - first;
      if (D == 3 && count > 1) {
        // Several candidates in 3D: a mesh's shared edges and vertices count once.
        const auto [near, hit] = wall_hits(i, first, count);
        for (int k = first; k < first + count; ++k) {
          if (hit[k - first])
            touching += wall_contact(i, k, near[k - first], acc);
          else
            nl.wall_history[k] = ContactHistory<D>{};
        }
      } else {
        // Each candidate on its own (the same tests as wall_hits, without its
        // scratch arrays: most particles have none or one).
        for (int k = first; k < first + count; ++k) {
          const int prim = nl.wall_prim[k];
          geometry::Closest<D> c;
          if (active_[s_.primitive_wall[prim]] &&
              geometry::closest_point<D>(s_.primitives[prim], p.x[i], p.r[i], c) &&
              c.distance < p.r[i])
            touching += wall_contact(i, k, c, acc);
          else
            nl.wall_history[k] = ContactHistory<D>{};
        }
      }
      if constexpr (D == 3)
        if (membranes_) membranes_->add_to_grain(p, i);
      if (then_kick) {
        kick_one<D>(p, i, *then_kick);
        if (kuen_on) kuen.apply(p, i);
      }
    }
#pragma omp atomic
    wall_touching_ += touching;
  }

  // The peer benchmark's law in 3D and the flume's in 2D run their pair loop
  // in vectorised blocks.
  static constexpr bool kHertzBlocks =
      D == 3 && std::is_same_v<Model, ComposedContact<HertzMindlin, NoRolling>>;
  static constexpr bool kLinearBlocks =
      D == 2 && std::is_same_v<Model, ComposedContact<LinearSpringDashpot, NoRolling>>;
  std::vector<decltype(Model::Coeffs::law)> coeffs_law_;  // the law's part of coeffs_ (blocks)

  DemSystem<D>& s_;
  int n_materials_ = 0;
  std::vector<typename Model::Coeffs> coeffs_;
  std::vector<double> friction_;  // per material pair, for pair_contact_forces
  ChunkPartition<D> partition_;
  int team_ = 1;                                   // threads in the current parallel region
  TeamBarrier barrier_;                            // the step's one barrier (core/team_sync.hpp)
  TeamSegments segments_{s_.threads};              // the team or one thread, segment by segment
  std::atomic<int64_t> sleeps_{0};                 // waits that slept in this segment
  std::vector<double> moved_;                      // each thread's largest squared drift this step
  bool rebuild_now_ = false, team_tasks_ = false;  // decided by serial_part
  int64_t force_pass_ = 0;                         // counts the force computations
  std::vector<Vec3> wall_acc_, pivots_;
  std::vector<char> moving_, active_;
  int64_t pair_touching_ = 0, wall_touching_ = 0;
  bool walls_set_up_ = false;  // primitives and active_ hold every wall
  bool step_open_ = false;     // a step's forces are done, its bookkeeping is not
  std::exception_ptr error_;   // raised inside the parallel region, rethrown outside
  KuenRolling kuen_;
  std::unique_ptr<membrane::MembraneStep> membranes_;  // 3D runs with membranes only
};

template <int D, class Law>
std::unique_ptr<StepperBase<D>> with_rolling(DemSystem<D>& s) {
  if (s.contact.rolling == RollingModel::Epsd)
    return std::make_unique<Stepper<D, ComposedContact<Law, EpsdRolling>>>(s);
  return std::make_unique<Stepper<D, ComposedContact<Law, NoRolling>>>(s);
}

}  // namespace

template <int D>
std::unique_ptr<StepperBase<D>> make_stepper(DemSystem<D>& s) {
  const std::size_t law = ContactLaws::index_of(s.contact.model);
  if (law == ContactLaws::size)
    throw std::invalid_argument("unknown contact model " + s.contact.model);
  return ContactLaws::visit(law, [&]<class Law>() { return with_rolling<D, Law>(s); });
}

template std::unique_ptr<StepperBase<2>> make_stepper<2>(DemSystem<2>&);
template std::unique_ptr<StepperBase<3>> make_stepper<3>(DemSystem<3>&);

}  // namespace talus::dem
