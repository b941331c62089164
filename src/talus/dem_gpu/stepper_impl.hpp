#pragma once
// The GPU stepper: the state of a DEM run in device memory, advanced there
// step after step, copied back to the DemSystem only when advance() returns
// (the run loop's output times). Included by stepper_cuda.cu (nvcc: CUDA) and
// stepper_emulated.cpp (g++: Thrust's serial host backend, which the tests
// run on machines without a GPU); TALUS_GPU_NS names the namespace of each.
#include <thrust/binary_search.h>
#include <thrust/count.h>
#include <thrust/device_vector.h>
#include <thrust/execution_policy.h>
#include <thrust/functional.h>
#include <thrust/gather.h>
#include <thrust/iterator/counting_iterator.h>
#include <thrust/reduce.h>
#include <thrust/scan.h>
#include <thrust/sort.h>
#include <thrust/transform_reduce.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <memory>
#include <string>
#include <vector>

#include "talus/core/error.hpp"
#include "talus/dem/contact/pair_coefficients.hpp"
#include "talus/dem/stepper.hpp"
#include "talus/dem/wall_motion.hpp"
#include "talus/dem_gpu/kernels.hpp"

namespace talus::dem::TALUS_GPU_NS {

using namespace gpu_detail;

template <class T>
using dvec = thrust::device_vector<T>;

// Kernels are queued without waiting; a step waits once, for its rebuild flag.
inline auto policy() {
#ifdef __CUDACC__
  return thrust::cuda::par_nosync;
#else
  return thrust::device;
#endif
}

template <class T>
T* raw(dvec<T>& v) {
  return thrust::raw_pointer_cast(v.data());
}

// Byte copies between host and device (Eigen's small vectors are plain arrays
// of doubles; Thrust's element-wise path for non-trivial types is not needed).
template <class T>
void to_device(const std::vector<T>& h, dvec<T>& d) {
  d.resize(h.size());
  if (h.empty()) return;
#ifdef __CUDACC__
  cudaMemcpy(raw(d), h.data(), h.size() * sizeof(T), cudaMemcpyHostToDevice);
#else
  std::memcpy(static_cast<void*>(raw(d)), h.data(), h.size() * sizeof(T));
#endif
}
template <class T>
void to_host(dvec<T>& d, std::size_t n, std::vector<T>& h) {
  h.resize(n);
  if (n == 0) return;
#ifdef __CUDACC__
  cudaMemcpy(h.data(), raw(d), n * sizeof(T), cudaMemcpyDeviceToHost);
#else
  std::memcpy(static_cast<void*>(h.data()), raw(d), n * sizeof(T));
#endif
}

// Reorders the first n entries by `order` (new k holds old order[k]).
template <class T>
void gather(dvec<int>& order, int n, dvec<T>& a, dvec<T>& scratch) {
  scratch.resize(n);
  thrust::gather(policy(), order.begin(), order.begin() + n, a.begin(), scratch.begin());
  a.swap(scratch);
}

template <int D>
struct NotFinite {
  TALUS_HD bool operator()(const typename Space<D>::Vec& x) const {
    for (int d = 0; d < D; ++d)
      if (!(x[d] - x[d] == 0.0)) return true;  // inf - inf and NaN - NaN are NaN
    return false;
  }
};

// Kinetic energy 1/2 m v^2 of particle i.
template <int D>
struct KineticEnergyOf {
  const typename Space<D>::Vec* v;
  const double* m;
  TALUS_HD double operator()(int i) const { return 0.5 * m[i] * v[i].squaredNorm(); }
};

struct Box {
  double lo[3], hi[3];
};
template <int D>
struct PointBox {
  TALUS_HD Box operator()(const typename Space<D>::Vec& x) const {
    Box b{{0, 0, 0}, {0, 0, 0}};
    for (int d = 0; d < D; ++d) b.lo[d] = b.hi[d] = x[d];
    return b;
  }
};
struct JoinBoxes {
  TALUS_HD Box operator()(const Box& a, const Box& b) const {
    Box c;
    for (int d = 0; d < 3; ++d) {
      c.lo[d] = a.lo[d] < b.lo[d] ? a.lo[d] : b.lo[d];
      c.hi[d] = a.hi[d] > b.hi[d] ? a.hi[d] : b.hi[d];
    }
    return c;
  }
};

// Where a step's time goes (TALUS_GPU_PHASES=1, CUDA only): GPU time between
// events recorded at each phase's start, summed and printed to stderr when the
// stepper ends. Off, it records nothing.
enum class Phase { KickDrift, Rebuild, Pairs, Walls, Count };
class PhaseTimer {
 public:
  PhaseTimer() {
    const char* on = std::getenv("TALUS_GPU_PHASES");
    enabled_ = on && std::string(on) == "1";
  }
  ~PhaseTimer() {
#ifdef __CUDACC__
    if (!enabled_ || !started_) return;
    static const char* names[] = {"kick_drift", "rebuild", "pairs", "walls_close"};
    std::string line = "[gpu phases ms]";
    for (int k = 0; k < static_cast<int>(Phase::Count); ++k)
      line += std::string(" ") + names[k] + "=" + std::to_string(ms_[k]);
    std::fprintf(stderr, "%s\n", line.c_str());
    cudaEventDestroy(a_);
    cudaEventDestroy(b_);
#endif
  }
  void start(Phase p) {
#ifdef __CUDACC__
    if (!enabled_) return;
    if (!started_) {
      cudaEventCreate(&a_);
      cudaEventCreate(&b_);
      started_ = true;
    } else if (open_) {
      close();
    }
    cudaEventRecord(a_);
    phase_ = p;
    open_ = true;
#else
    (void)p;
#endif
  }
  void stop() {
#ifdef __CUDACC__
    if (enabled_ && open_) close();
#endif
  }

 private:
#ifdef __CUDACC__
  void close() {
    cudaEventRecord(b_);
    cudaEventSynchronize(b_);
    float ms = 0;
    cudaEventElapsedTime(&ms, a_, b_);
    ms_[static_cast<int>(phase_)] += ms;
    open_ = false;
  }
  cudaEvent_t a_{}, b_{};
#endif
  bool enabled_ = false, started_ = false, open_ = false;
  Phase phase_ = Phase::KickDrift;
  double ms_[static_cast<int>(Phase::Count)] = {};
};

template <int D, class Model>
class GpuStepper final : public StepperBase<D> {
 public:
  using Vec = typename Space<D>::Vec;
  using Rot = typename Space<D>::Rot;

  explicit GpuStepper(DemSystem<D>& s) : s_(s) {
    make_coefficients();
    for (double r : s.particles.r) r_max_ = std::max(r_max_, r);
    rebuild_flag_.resize(1);
    const char* loop = std::getenv("TALUS_GPU_PAIR_LOOP");
    row_loop_ = loop && std::string(loop) == "row";
  }

  void prime() override {
    upload();
    update_walls(true);
    rebuild();
    forces(false);
    close_walls(false);
    download();
  }

  // A state restored from a checkpoint, or changed by the run loop (a
  // friction change: the coefficients are made again).
  void resume() override {
    if (uploaded_) sync_lists();  // the history the host copy is made from
    make_coefficients();
    upload();
    update_walls(true);
    rebuild();
    download();
  }

  void advance(int64_t steps) override {
    if (!uploaded_) upload();
    upload_walls();  // the run loop resets the force extremes between calls
    for (int64_t k = 0; k < steps; ++k) one_step();
    download();
  }

  void sync_lists() override {
    if (lists_synced_ == builds_ + steps_done_) return;
    download_lists();
    lists_synced_ = builds_ + steps_done_;
  }

  void rebuild() override {
    if (!uploaded_) upload();
    rebuild_on_device();
    download();
  }

  // The CPU stepper's estimate for the same system (it reads only the
  // particles and materials).
  double critical_time_step(double v_ref) const override {
    return make_stepper<D>(s_)->critical_time_step(v_ref);
  }

  // Evaluated on the host from the lists sync_lists() brings into the system
  // (logically const: the device state is unchanged).
  std::vector<PairContactForce> pair_contact_forces() const override {
    const_cast<GpuStepper*>(this)->sync_lists();
    const auto& p = s_.particles;
    const auto& nl = s_.neighbours;
    std::vector<PairContactForce> out;
    for (std::size_t k = 0; k < nl.pairs.size(); ++k) {
      const int i = nl.pairs[k].i, j = nl.pairs[k].j;
      const Vec d = p.x[i] - p.x[j];
      const double d2 = d.squaredNorm(), rs = p.r[i] + p.r[j];
      if (d2 >= rs * rs) continue;
      const auto pk = pair_kinematics<D, Model::needs_inertia>(p, i, j, d, d2);
      ContactHistory<D> h{nl.pair_shear[k], nl.pair_roll[k]};  // a copy: left as it was
      ContactForce<D> cf;
      const int mi = p.material[i], mj = p.material[j];
      Model::template compute<D>(coeffs_host_[mi * n_materials_ + mj], pk.kin, h, 0.0, cf);
      out.push_back({i, j, cf.fn, cf.ft.norm(),
                     pair_coefficients(s_.contact, s_.materials[mi], s_.materials[mj]).friction});
    }
    return out;
  }

 private:
  void make_coefficients() {
    n_materials_ = static_cast<int>(s_.materials.size());
    coeffs_host_ = coefficient_table<Model>(s_.contact, s_.materials);
    to_device(coeffs_host_, coeffs_);
  }

  // ---- transfers

  // The system's particles, lists and walls into device memory. The system's
  // half list (any orientation) becomes the previous list the first rebuild
  // carries the history from.
  void upload() {
    const auto& p = s_.particles;
    n_ = static_cast<int>(p.size());
    to_device(p.x, x_);
    to_device(p.v, v_);
    to_device(p.f, f_);
    to_device(p.w, w_);
    to_device(p.t, t_);
    to_device(p.r, r_);
    to_device(p.m, m_);
    to_device(p.inv_m, inv_m_);
    to_device(p.inv_I, inv_I_);
    to_device(p.material, material_);
    to_device(p.id, id_);
    to_device(p.contacts, contacts_);
    to_device(p.wall_contacts, wall_contacts_);
    x_ref_ = x_;
    upload_history();
    upload_walls();
    wall_sum_.assign(2 * s_.walls.size(), Vec3(0, 0, 0));
    uploaded_ = true;
    static_builds_ = -1;
  }

  void upload_walls() {
    std::vector<Vec3> block;
    for (const auto& w : s_.walls) {
      const Vec3 work(w.work, 0, 0);
      const Vec3* fields[kWallFields] = {&w.force,     &w.torque,    &w.impulse,
                                         &w.force_max, &w.force_min, &work};
      for (const Vec3* v : fields) block.push_back(*v);
    }
    to_device(block, wall_);
  }

  void upload_history() {
    const auto& nl = s_.neighbours;
    const int n = n_;
    // Pairs of the system's list as rows of their lower index, history of lo against hi.
    std::vector<int> row(n + 1, 0), col;
    std::vector<Vec> shear;
    std::vector<Rot> roll;
    have_previous_ = !nl.pairs.empty();
    if (have_previous_) {
      for (const auto& pr : nl.pairs) ++row[std::min(pr.i, pr.j) + 1];
      for (int i = 0; i < n; ++i) row[i + 1] += row[i];
      col.resize(nl.pairs.size());
      shear.resize(nl.pairs.size());
      roll.resize(nl.pairs.size());
      std::vector<int> fill(row.begin(), row.end() - 1);
      for (std::size_t k = 0; k < nl.pairs.size(); ++k) {
        const int i = nl.pairs[k].i, j = nl.pairs[k].j;
        const int slot = fill[std::min(i, j)]++;
        col[slot] = std::max(i, j);
        const bool flip = i > j;
        shear[slot] = flip ? Vec(-nl.pair_shear[k]) : nl.pair_shear[k];
        roll[slot] = flip ? Rot(-nl.pair_roll[k]) : nl.pair_roll[k];
      }
    }
    to_device(row, row_start_);
    to_device(col, pair_j_);
    to_device(shear, pair_shear_);
    to_device(roll, pair_roll_);
    pair_i_.clear();
    // Wall histories, dense per particle and primitive.
    n_prims_ = 0;
    for (const auto& w : s_.walls) n_prims_ += static_cast<int>(w.reference.size());
    std::vector<ContactHistory<D>> wh(static_cast<std::size_t>(n) * n_prims_);
    if (static_cast<int>(nl.wall_start.size()) == n + 1)
      for (int i = 0; i < n; ++i)
        for (int k = nl.wall_start[i]; k < nl.wall_start[i + 1]; ++k)
          wh[static_cast<std::size_t>(i) * n_prims_ + nl.wall_prim[k]] = nl.wall_history[k];
    to_device(wh, wall_history_);
  }

  // Device state back into the system: what changes every step in one packed
  // copy, the rest only after a rebuild has reordered it. The lists wait for
  // sync_lists().
  void download() {
    auto& p = s_.particles;
    const std::size_t n = n_;
    moving_.resize(n);
    thrust::for_each_n(policy(), thrust::counting_iterator<int>(0), n_,
                       PackMoving<D>{view(), raw(moving_)});
    to_host(moving_, n, moving_host_);
    for (auto* a : {&p.contacts, &p.wall_contacts}) a->resize(n);
    p.x.resize(n), p.v.resize(n), p.f.resize(n), p.w.resize(n), p.t.resize(n);
    int64_t pair_contacts = 0, wall_contacts = 0;
    for (std::size_t i = 0; i < n; ++i) {
      const Moving<D>& q = moving_host_[i];
      p.x[i] = q.x, p.v[i] = q.v, p.f[i] = q.f, p.w[i] = q.w, p.t[i] = q.t;
      p.contacts[i] = q.contacts, p.wall_contacts[i] = q.wall_contacts;
      pair_contacts += q.contacts;
      wall_contacts += q.wall_contacts;
    }
    s_.pair_contacts = pair_contacts / 2;
    s_.wall_contacts = wall_contacts;
    if (static_builds_ != builds_) {
      to_host(r_, n, p.r);
      to_host(m_, n, p.m);
      to_host(inv_m_, n, p.inv_m);
      to_host(inv_I_, n, p.inv_I);
      to_host(material_, n, p.material);
      to_host(id_, n, p.id);
      static_builds_ = builds_;
    }
    std::vector<Vec3> block;
    to_host(wall_, kWallFields * s_.walls.size(), block);
    for (std::size_t k = 0; k < s_.walls.size(); ++k) {
      auto& w = s_.walls[k];
      const Vec3* b = block.data() + kWallFields * k;
      w.force = b[0], w.torque = b[1], w.impulse = b[2], w.force_max = b[3], w.force_min = b[4];
      w.work = b[5].x();
    }
    s_.neighbours.builds = static_cast<int>(builds_);
  }

  // The lists in the CPU stepper's layout (checkpoints and the force network
  // read them there): pairs as they are, wall histories for every primitive.
  void download_lists() {
    const std::size_t n = n_;
    auto& nl = s_.neighbours;
    std::vector<int> pi, pj;
    const std::size_t np = pair_j_.size();
    to_host(pair_i_, np, pi);
    to_host(pair_j_, np, pj);
    nl.pairs.resize(np);
    for (std::size_t k = 0; k < np; ++k) nl.pairs[k] = {pi[k], pj[k]};
    to_host(pair_shear_, np, nl.pair_shear);
    to_host(pair_roll_, np, nl.pair_roll);
    to_host(wall_history_, n * n_prims_, nl.wall_history);
    nl.wall_start.resize(n + 1);
    nl.wall_prim.resize(n * n_prims_);
    for (std::size_t i = 0; i <= n; ++i) nl.wall_start[i] = static_cast<int>(i * n_prims_);
    for (std::size_t k = 0; k < n * n_prims_; ++k) nl.wall_prim[k] = static_cast<int>(k % n_prims_);
    to_host(x_ref_, n, nl.reference_positions());
    nl.set_skin(s_.skin);
  }

  ParticleView<D> view() {
    return {raw(x_),
            raw(v_),
            raw(f_),
            raw(x_ref_),
            raw(w_),
            raw(t_),
            raw(r_),
            raw(m_),
            raw(inv_m_),
            raw(inv_I_),
            raw(material_),
            raw(contacts_),
            raw(wall_contacts_)};
  }

  Kick<D> half_kick() const {
    return {s_.gravity, 0.5 * s_.dt, s_.contact.local_damping, !s_.contact.lock_rotation};
  }

  // ---- the step (as the CPU stepper's one_step)

  void one_step() {
    const double dt = s_.dt, half_skin = 0.5 * s_.skin;
    timer_.start(Phase::KickDrift);
    thrust::for_each_n(
        policy(), thrust::counting_iterator<int>(0), n_,
        KickDrift<D>{view(), half_kick(), dt, half_skin * half_skin, raw(rebuild_flag_)});
    s_.time = static_cast<double>(s_.step + 1) * dt;
    const bool walls_changed = update_walls(false);
    const double wall_moved =
        wall_motion_since(s_.walls, s_.time, s_.wall_displacement_at_build, s_.wall_angle_at_build);
    const int moved_far = rebuild_flag_[0];  // waits for the kernel
    timer_.start(Phase::Rebuild);
    if (walls_changed || moved_far || wall_moved > half_skin) rebuild_on_device();
    forces(true);
    close_walls(true);
    timer_.stop();
    ++s_.step;
    ++steps_done_;
  }

  void forces(bool then_kick) {
    const int np = static_cast<int>(pair_j_.size());
    const PairForces<D, Model> pairs{view(),          raw(pair_i_), raw(pair_j_), raw(pair_shear_),
                                     raw(pair_roll_), raw(coeffs_), n_materials_, s_.dt};
    timer_.start(Phase::Pairs);
    if (row_loop_)
      thrust::for_each_n(policy(), thrust::counting_iterator<int>(0), n_,
                         RowForces<D, Model>{pairs, raw(row_start_)});
    else
      thrust::for_each_n(policy(), thrust::counting_iterator<int>(0), np, pairs);
    timer_.start(Phase::Walls);
    thrust::for_each_n(
        policy(), thrust::counting_iterator<int>(0), n_,
        WallForces<D, Model>{view(), raw(prims_), raw(prim_wall_), n_prims_, raw(wall_state_),
                             raw(wall_history_), raw(coeffs_), n_materials_, s_.dt, raw(wall_sum_),
                             half_kick(), then_kick});
  }

  void close_walls(bool close_step) {
    thrust::for_each_n(policy(), thrust::counting_iterator<int>(0),
                       static_cast<int>(s_.walls.size()),
                       CloseWalls{raw(wall_sum_), raw(wall_), raw(wall_state_), s_.dt, close_step});
  }

  // Moves the walls to the current time and sends what changed; true when a
  // wall appeared or vanished (the list is then rebuilt, as on the CPU).
  bool update_walls(bool force) {
    const double t = s_.time;
    bool changed = force, moved = force;
    std::vector<WallState> state(s_.walls.size());
    std::vector<geometry::Primitive> prims;
    std::vector<int> prim_wall;
    for (std::size_t k = 0; k < s_.walls.size(); ++k) {
      auto& w = s_.walls[k];
      if (w.moves()) {
        w.update(t);
        moved = true;
      }
      const Vec3 pivot = w.pivot_at(t);
      state[k] = {pivot,      w.velocity_at(pivot, t), w.angular_velocity_at(t),
                  w.material, w.active(t) ? 1 : 0,     w.moves() ? 1 : 0};
      if (k < active_.size() && active_[k] != state[k].active) changed = true;
      for (const auto& prim : w.current) {
        prims.push_back(prim);
        prim_wall.push_back(static_cast<int>(k));
      }
    }
    if (changed || moved) {
      active_.clear();
      for (const auto& st : state) active_.push_back(st.active);
      to_device(state, wall_state_);
      to_device(prims, prims_);
      to_device(prim_wall, prim_wall_);
    }
    return changed && !force;
  }

  // ---- neighbour search

  void rebuild_on_device() {
    const int n = n_;
    if (n > 0 && thrust::count_if(policy(), x_.begin(), x_.begin() + n, NotFinite<D>{}) > 0)
      throw RunError("the GPU run has particles at positions that are not finite numbers at step " +
                     std::to_string(s_.step) + " (t = " + std::to_string(s_.time) +
                     " s): the time step is too large for the contact stiffness, or the " +
                     "input is unstable");
    const double cell = 2.0 * r_max_ + s_.skin;
    CellGrid<D> grid{Vec3::Zero(), 1.0 / cell, D == 3 ? (1 << 21) - 1 : (1 << 30)};
    if (n > 0) {
      const Box b = thrust::transform_reduce(policy(), x_.begin(), x_.begin() + n, PointBox<D>{},
                                             PointBox<D>{}(x_[0]), JoinBoxes{});
      grid.lo = Vec3(b.lo[0], b.lo[1], b.lo[2]);
    }
    keys_.resize(n);
    order_.resize(n);
    thrust::for_each_n(policy(), thrust::counting_iterator<int>(0), n,
                       CellKeys<D>{raw(x_), grid, s_.domain_min, s_.domain_max, s_.has_domain(),
                                   raw(keys_), raw(order_)});
    thrust::sort_by_key(policy(), keys_.begin(), keys_.end(), order_.begin());
    const int kept = static_cast<int>(
        thrust::lower_bound(thrust::device, keys_.begin(), keys_.end(), kRemoved) - keys_.begin());
    s_.removed += n - kept;
    if (kept < n)  // order_ lists the removed ones last, by their index before the sort
      s_.removed_kinetic_energy += thrust::transform_reduce(
          policy(), order_.begin() + kept, order_.begin() + n, KineticEnergyOf<D>{raw(v_), raw(m_)},
          0.0, thrust::plus<double>());
    permute_particles(kept);
    find_pairs(grid);
    x_ref_ = x_;
    rebuild_flag_[0] = 0;
    ++builds_;
    s_.wall_displacement_at_build.clear();
    s_.wall_angle_at_build.clear();
    for (const auto& w : s_.walls) {
      s_.wall_displacement_at_build.push_back(w.displacement(s_.time));
      s_.wall_angle_at_build.push_back(w.rotation_angle(s_.time));
    }
  }

  void permute_particles(int kept) {
    gather(order_, kept, x_, scratch_vec_);
    gather(order_, kept, v_, scratch_vec_);
    gather(order_, kept, f_, scratch_vec_);
    gather(order_, kept, w_, scratch_rot_);
    gather(order_, kept, t_, scratch_rot_);
    gather(order_, kept, r_, scratch_double_);
    gather(order_, kept, m_, scratch_double_);
    gather(order_, kept, inv_m_, scratch_double_);
    gather(order_, kept, inv_I_, scratch_double_);
    gather(order_, kept, material_, scratch_int_);
    gather(order_, kept, contacts_, scratch_int_);
    gather(order_, kept, wall_contacts_, scratch_int_);
    gather(order_, kept, id_, scratch_id_);
    scratch_history_.resize(static_cast<std::size_t>(kept) * n_prims_);
    thrust::for_each_n(
        policy(), thrust::counting_iterator<int>(0), kept,
        GatherWallHistory<D>{raw(wall_history_), raw(scratch_history_), raw(order_), n_prims_});
    wall_history_.swap(scratch_history_);
    keys_.resize(kept);
    n_ = kept;
  }

  void find_pairs(const CellGrid<D>& grid) {
    const int n = n_;
    // The list being replaced becomes the one the history comes from.
    old_row_.swap(row_start_);
    old_j_.swap(pair_j_);
    old_shear_.swap(pair_shear_);
    old_roll_.swap(pair_roll_);
    const bool carry = have_previous_;
    count_.resize(n + 1);
    FindPairs<D> find{
        raw(x_),     raw(r_),         raw(keys_),     n,       grid,    s_.skin,     raw(count_),
        nullptr,     nullptr,         nullptr,        nullptr, nullptr, raw(order_), raw(old_row_),
        raw(old_j_), raw(old_shear_), raw(old_roll_), carry};
    thrust::for_each_n(policy(), thrust::counting_iterator<int>(0), n, find);
    count_[n] = 0;
    row_start_.resize(n + 1);
    thrust::exclusive_scan(policy(), count_.begin(), count_.end(), row_start_.begin());
    const int total = row_start_[n];
    pair_i_.resize(total);
    pair_j_.resize(total);
    pair_shear_.resize(total);
    pair_roll_.resize(total);
    find.row_start = raw(row_start_);
    find.out_i = raw(pair_i_);
    find.out_j = raw(pair_j_);
    find.out_shear = raw(pair_shear_);
    find.out_roll = raw(pair_roll_);
    thrust::for_each_n(policy(), thrust::counting_iterator<int>(0), n, find);
    have_previous_ = true;
  }

  DemSystem<D>& s_;
  int n_materials_ = 0, n_ = 0, n_prims_ = 0;
  int64_t builds_ = 0;
  double r_max_ = 0.0;
  bool uploaded_ = false, have_previous_ = false;
  std::vector<typename Model::Coeffs> coeffs_host_;
  std::vector<int> active_;
  dvec<typename Model::Coeffs> coeffs_;
  // Particles (the fields of dem::Particles) and the positions of the last build.
  dvec<Vec> x_, v_, f_, x_ref_;
  dvec<Rot> w_, t_;
  dvec<double> r_, m_, inv_m_, inv_I_;
  dvec<int> material_, contacts_, wall_contacts_;
  dvec<int64_t> id_;
  // The pair list: rows by lower index (CSR), history of i against j.
  dvec<int> row_start_, pair_i_, pair_j_, count_;
  dvec<Vec> pair_shear_;
  dvec<Rot> pair_roll_;
  dvec<int> old_row_, old_j_;
  dvec<Vec> old_shear_;
  dvec<Rot> old_roll_;
  // Walls.
  dvec<geometry::Primitive> prims_;
  dvec<int> prim_wall_;
  dvec<WallState> wall_state_;
  dvec<ContactHistory<D>> wall_history_, scratch_history_;
  dvec<Vec3> wall_sum_, wall_;  // wall_: kWallFields per wall (CloseWalls)
  dvec<Moving<D>> moving_;
  std::vector<Moving<D>> moving_host_;
  int64_t static_builds_ = -1, lists_synced_ = -1, steps_done_ = 0;
  bool row_loop_ = false;
  PhaseTimer timer_;
  // Rebuild work arrays.
  dvec<uint64_t> keys_;
  dvec<int> order_, rebuild_flag_;
  dvec<Vec> scratch_vec_;
  dvec<Rot> scratch_rot_;
  dvec<double> scratch_double_;
  dvec<int> scratch_int_;
  dvec<int64_t> scratch_id_;
};

}  // namespace talus::dem::TALUS_GPU_NS
