// The MPM method on the run loop: one CFL step at a time, landing exactly on
// the end time; the energy watch of mpm/health.hpp every tenth step. With
// several threads the steps run in segments with the whole team or one thread
// alone, whichever is faster now (core/team_segments.hpp): the solver's chunks
// follow the thread count asked for, so the bits are the same either way.
#include "talus/run/methods/mpm.hpp"

#include <fmt/core.h>

#include <algorithm>

#include "talus/core/error.hpp"
#include "talus/io/archive.hpp"
#include "talus/mpm/checkpoint.hpp"
#include "talus/mpm/health.hpp"
#include "talus/mpm/metrics.hpp"
#include "talus/mpm/output_observer.hpp"
#include "talus/mpm/scenario.hpp"
#include "talus/run/forward.hpp"
#include "talus/run/methods/methods.hpp"
#include "talus/scenario/scenario_mpm.hpp"

namespace talus::run {

namespace {

std::vector<double> initial_cohesions(const mpm::MpmScenario& sc) {
  std::vector<double> c0;
  for (const auto& m : sc.materials) c0.push_back(mpm::initial_cohesion(m));
  return c0;
}

}  // namespace

template <int D>
MpmSimulation<D>::MpmSimulation(mpm::MpmScenario scenario, mpm::Solver<D> solver,
                                const std::filesystem::path& out, bool resume, int threads)
    : scenario_(std::move(scenario)),
      solver_(std::move(solver)),
      threads_(threads),
      segments_(threads) {
  if (threads_ > 1) solver_.set_chunks(threads_);
  if (out.empty()) {
    files_observer_ = std::make_unique<Observer>();
    return;
  }
  files_ =
      std::make_unique<mpm::MpmOutputs<D>>(out, initial_cohesions(scenario_), resume, solver_.time);
  files_observer_ = std::make_unique<Forward<mpm::MpmOutputs<D>, mpm::Solver<D>>>(*files_, solver_);
}

template <int D>
Schedules MpmSimulation<D>::schedules() const {
  const auto& o = scenario_.output;
  Schedules s;
  s.series = OutputSchedule(o.series_interval > 0 ? o.series_interval : scenario_.duration / 200.0);
  s.snapshots = OutputSchedule(o.snapshots ? o.snapshot_interval : -1.0);
  s.checkpoints = OutputSchedule(o.checkpoint_interval > 0 ? o.checkpoint_interval : -1.0);
  return s;
}

template <int D>
void MpmSimulation<D>::start(bool /*fresh*/) {
  blowup_ = scenario_.ke_blowup_factor;
  if (blowup_ > 0.0) budget_ = mpm::energy_budget(solver_);
}

template <int D>
void MpmSimulation<D>::advance(double target, double tolerance, std::int64_t max_steps) {
  auto& s = solver_;
  const double end = end_time();
  TeamSize size(threads_);
  for (std::int64_t taken = 0; taken < max_steps;) {
    const std::int64_t segment = segments_.begin(max_steps - taken);
    size.set(segments_.team());
    std::int64_t stepped = 0;
    bool reached = false;
    for (; stepped < segment; ++stepped) {
      reached = s.time >= target - tolerance || s.time >= end - this->tolerance();
      if (reached) break;
      double dt = s.time_step();
      // Land exactly on the end time.
      if (s.time + dt > end) dt = end - s.time;
      s.step(dt);
      const bool last = s.time >= end - this->tolerance();
      // Every 10th step: an O(n) sum beside a step of many O(n) passes.
      if (blowup_ > 0.0 && (s.steps % 10 == 0 || last)) mpm::check_energy(s, budget_, blowup_);
    }
    taken += stepped;
    segments_.end(stepped);
    if (reached || stepped == 0) break;
  }
}

template <int D>
MethodReport MpmSimulation<D>::report() const {
  using nlohmann::json;
  const auto& s = solver_;
  const auto& p = s.particles;
  int yielding = 0, cracked = 0;
  for (std::size_t i = 0; i < p.size(); ++i) {
    yielding += p.state[i].yielding;
    const double c0 = mpm::initial_cohesion(scenario_.materials[p.material[i]]);
    cracked += c0 > 0.0 && p.state[i].cohesion < c0;
  }
  const double front = mpm::front_x(p), height = mpm::top(p, s.gravity());
  MethodReport r;
  r.method = "mpm";
  r.dimension = D;
  r.scenario = io::mpm_scenario_to_json(scenario_);
  r.rate_key = "point_steps_per_s";
  r.items = static_cast<double>(p.size());
  r.resolved = {{"last_time_step_s", s.last_dt},
                {"cell_size_m", s.grid.h},
                {"gimp_half_width_over_h", s.params.gimp_half_width},
                {"grid_nodes", s.grid.nodes()},
                {"threads", threads_}};
  r.metrics = {{"points", p.size()},          {"kinetic_energy_J", mpm::kinetic_energy(p)},
               {"front_x_m", front},          {"top_m", height},
               {"yielding_points", yielding}, {"cracked_points", cracked}};
  if (!s.rigid_bodies.empty()) {
    auto& works = r.metrics["rigid_body_work_J"] = json::array();
    for (const auto& body : s.rigid_bodies) works.push_back(body.work);
  }
  if (files_) {  // the peaks and changes are read from the series
    r.metrics["peak_kinetic_energy_J"] = files_->peak_kinetic_energy;
    r.metrics["peak_kinetic_energy_time_s"] = files_->peak_kinetic_energy_time;
    r.metrics["front_advance_m"] = front - files_->initial_front_x;
    r.metrics["top_change_m"] = height - files_->initial_top;
  }
  if (const auto* m = files_ ? files_->membrane_outputs() : nullptr) {
    double final_max = 0.0;
    for (const auto& mb : s.membranes) final_max = std::max(final_max, mb.max_tension());
    r.metrics["membrane_peak_tension_N_m"] = m->peak_tension;
    r.metrics["membrane_peak_tension_time_s"] = m->peak_tension_time;
    r.metrics["membrane_final_max_tension_N_m"] = final_max;
  }
  r.headline = headline(r.metrics);
  return r;
}

template <int D>
std::vector<StateArray> MpmSimulation<D>::state_arrays() {
  auto& p = solver_.particles;
  using Vec = typename mpm::Particles<D>::Vec;
  static_assert(sizeof(Vec) == D * sizeof(double), "positions must be D packed doubles");
  const std::size_t n = p.x.size();
  using T = StateArray::Type;
  const std::vector<std::size_t> vec{n, D}, scalar{n};
  std::vector<StateArray> out = {
      {"x", "m", T::Float64, p.x.data(), vec, false},
      {"v", "m/s", T::Float64, p.v.data(), vec, true},
      {"mass", "kg", T::Float64, p.mass.data(), scalar, false},
      {"volume", D == 2 ? "m^2" : "m^3", T::Float64, p.volume.data(), scalar, false}};
  // The stress is the first member of each point's MaterialState; Eigen's
  // matrices are column-major, so (i, j) lies (i + 3 j) doubles in.
  const auto row = static_cast<std::ptrdiff_t>(sizeof(double));
  out.push_back({"stress",
                 "Pa",
                 T::Float64,
                 n > 0 ? p.state[0].stress.data() : nullptr,
                 {n, 3, 3},
                 false,
                 {static_cast<std::ptrdiff_t>(sizeof(mpm::MaterialState)), row, 3 * row}});
  return out;
}

template <int D>
double MpmSimulation<D>::kinetic_energy() const {
  return mpm::total_kinetic_energy(solver_);
}

// "mpm: 5000 points, front advanced 0.42 m, top changed -0.11 m; peak kinetic
// energy 3.1 J at t = 0.35 s; 120 points cracked".
template <int D>
std::string MpmSimulation<D>::headline(const nlohmann::json& m) {
  std::string line = fmt::format("mpm: {} points", m["points"].get<std::size_t>());
  if (m.contains("front_advance_m"))
    line += fmt::format(
        ", front advanced {:.4g} m, top changed {:.4g} m; peak kinetic energy "
        "{:.4g} J at t = {:.4g} s",
        m["front_advance_m"].get<double>(), m["top_change_m"].get<double>(),
        m["peak_kinetic_energy_J"].get<double>(), m["peak_kinetic_energy_time_s"].get<double>());
  else
    line += fmt::format(", front at x = {:.4g} m, top at {:.4g} m", m["front_x_m"].get<double>(),
                        m["top_m"].get<double>());
  if (const int cracked = m["cracked_points"].get<int>(); cracked > 0)
    line += fmt::format("; {} points cracked", cracked);
  if (m.contains("membrane_peak_tension_N_m"))
    line += fmt::format("; membrane peak tension {:.4g} N/m",
                        m["membrane_peak_tension_N_m"].get<double>());
  return line;
}

template class MpmSimulation<2>;
template class MpmSimulation<3>;

namespace {

// "file:line: [run] 'time_step'" for messages.
std::string where_time_step(const io::ScenarioFile& f) { return where_key(f, "run", "time_step"); }

// A fixed step above the stability limit (the CFL rule with Courant number 1
// at the initial state) would blow up a few steps in and be reported as a
// point leaving the grid: refuse it before the run.
template <int D>
void check_fixed_step(const mpm::Solver<D>& s, const std::string& where) {
  const double fixed = s.params.fixed_time_step;
  if (!(fixed > 0.0)) return;
  const double limit = s.cfl_time_step(1.0);
  if (fixed > limit)
    throw InputError(fmt::format(
        "{}: {:.3g} s is above the stable step {:.3g} s of this scenario (cell size / (wave "
        "speed + speed) at the start); use time_step = \"auto\" (the CFL rule, {:.3g} s) or a "
        "step below {:.3g} s",
        where, fixed, limit, s.cfl_time_step(s.params.cfl), limit));
}

template <int D>
std::unique_ptr<Simulation> create_mpm(mpm::MpmScenario sc, const RunContext& ctx,
                                       const std::string& where) {
  auto solver = mpm::build_mpm<D>(sc);
  check_fixed_step(solver, where);
  if (ctx.resume) mpm::load_checkpoint(solver, mpm::MpmOutputs<D>::checkpoint_path(ctx.out));
  return std::make_unique<MpmSimulation<D>>(std::move(sc), std::move(solver), ctx.out, ctx.resume,
                                            ctx.threads);
}

template <int D>
Validation validate_mpm(const mpm::MpmScenario& sc, const std::string& where) {
  const auto s = mpm::build_mpm<D>(sc);
  check_fixed_step(s, where);
  const double dt = s.time_step();
  return {
      fmt::format("{}D MPM, {} points, {} material{}, first time step {:.3g} s", D,
                  s.particles.size(), sc.materials.size(), sc.materials.size() == 1 ? "" : "s", dt),
      sc.duration / dt, sc.duration};
}

}  // namespace

Method mpm_method() {
  Method m;
  m.name = "mpm";
  m.accepts = [](const io::ScenarioFile& f) { return f.method == "mpm"; };
  m.validate = [](const io::ScenarioFile& f) {
    const auto sc = io::parse_mpm_scenario(f);
    return sc.dimension == 2 ? validate_mpm<2>(sc, where_time_step(f))
                             : validate_mpm<3>(sc, where_time_step(f));
  };
  m.create = [](const io::ScenarioFile& f, const RunContext& ctx) {
    auto sc = io::parse_mpm_scenario(f);
    if (!ctx.resume) {
      ctx.prepare();
      const auto path = ctx.out / "scenario.toml";
      io::write_file_atomically(path, io::mpm_scenario_to_toml(sc));
      // The run uses the resolved file it wrote, as a resume does: an angle
      // through degrees and back may differ in the last bit, and a resumed run
      // must start from the very same numbers to end in the same state.
      sc = io::parse_mpm_scenario(io::load_scenario_file(path.string(), {}));
    }
    return sc.dimension == 2 ? create_mpm<2>(std::move(sc), ctx, where_time_step(f))
                             : create_mpm<3>(std::move(sc), ctx, where_time_step(f));
  };
  return m;
}

}  // namespace talus::run
