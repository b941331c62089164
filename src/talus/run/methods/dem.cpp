#include "talus/run/methods/dem.hpp"

#include <fmt/core.h>

#include <algorithm>
#include <cmath>
#include <limits>

#include "talus/core/error.hpp"
#include "talus/dem/checkpoint.hpp"
#include "talus/dem/gpu_support.hpp"
#include "talus/dem/health.hpp"
#include "talus/dem_gpu/backend.hpp"
#include "talus/io/archive.hpp"
#include "talus/run/forward.hpp"
#include "talus/run/methods/methods.hpp"

namespace talus::run {

DemControl dem_control(const dem::DemScenario& sc) {
  DemControl c;
  c.duration = sc.run.duration;
  c.series_interval = sc.output.series_interval;
  c.snapshot_interval = sc.output.write_snapshots ? sc.output.snapshot_interval : -1.0;
  c.checkpoint_interval = sc.output.checkpoint_interval;
  c.ke_blowup_factor = sc.run.ke_blowup_factor;
  if (sc.beam && sc.beam->bending_friction) {
    dem::FrictionChange f{sc.beam->bending_start, *sc.beam->bending_friction, {}};
    // The grains' materials: those the particle sources name.
    for (std::size_t k = 0; k < sc.materials.size(); ++k)
      for (const auto& src : sc.sources)
        if (src.material == sc.materials[k].name) {
          f.materials.push_back(static_cast<int>(k));
          break;
        }
    c.friction_change = f;
  }
  return c;
}

template <int D>
DemSimulation<D>::DemSimulation(dem::DemRun<D>& run, DemControl control)
    : run_(run), control_(std::move(control)), outputs_observer_(std::make_unique<Observer>()) {}

template <int D>
DemSimulation<D>::DemSimulation(dem::DemScenario scenario, std::unique_ptr<dem::DemRun<D>> run,
                                const std::filesystem::path& out, bool resume, int threads)
    : owned_(std::move(run)),
      run_(*owned_),
      control_(dem_control(scenario)),
      scenario_(std::move(scenario)),
      threads_(threads) {
  if (scenario_ && scenario_->run.backend == dem::Backend::Gpu)
    device_ = dem::gpu::device().description;
  files_ = std::make_unique<dem::DemOutputs<D>>(out, run_.system, resume, run_.system.time);
  outputs_observer_ = std::make_unique<Forward<dem::DemOutputs<D>, dem::DemRun<D>>>(*files_, run_);
}

template <int D>
Schedules DemSimulation<D>::schedules() const {
  const double dt = run_.system.dt;
  Schedules s;
  s.series = OutputSchedule(control_.series_interval > 0 ? control_.series_interval : 100.0 * dt);
  s.snapshots = OutputSchedule(control_.snapshot_interval);
  s.checkpoints =
      OutputSchedule(control_.checkpoint_interval > 0 ? control_.checkpoint_interval : -1);
  return s;
}

template <int D>
void DemSimulation<D>::start(bool fresh) {
  auto& s = run_.system;
  end_step_ = std::llround(control_.duration / s.dt);
  budget_ = dem::energy_budget(s);
  const auto& f = control_.friction_change;
  change_step_ = f ? std::llround(f->time / s.dt) : std::numeric_limits<std::int64_t>::max();
  // Due already (a resumed run past it, or a change at t = 0): before anything.
  changed_before_ = s.step >= change_step_;
  if (changed_before_) dem::apply_friction_change(run_, *f);
  health_every_ = std::max<std::int64_t>(1, std::min<std::int64_t>(1000, end_step_ / 100 + 1));
  if (fresh)
    run_.stepper->prime();
  else
    run_.stepper->resume();
}

// The first step whose time reaches t (time = step * dt exactly).
template <int D>
std::int64_t DemSimulation<D>::step_reaching(double t) const {
  const double dt = run_.system.dt;
  auto n = static_cast<std::int64_t>(std::ceil(t / dt));
  while (n > 0 && static_cast<double>(n - 1) * dt >= t) --n;
  while (static_cast<double>(n) * dt < t) ++n;
  return n;
}

template <int D>
void DemSimulation<D>::advance(double target, double tolerance, std::int64_t max_steps) {
  auto& s = run_.system;
  std::int64_t goal = std::min(end_step_, step_reaching(target - tolerance));
  if (max_steps < end_step_ - s.step) goal = std::min(goal, s.step + max_steps);
  while (s.step < goal) {
    std::int64_t next = std::min(goal, (s.step / health_every_ + 1) * health_every_);
    if (s.step < change_step_) next = std::min(next, change_step_);
    run_.stepper->advance(next - s.step);
    if (s.step == change_step_ && !changed_before_) {
      dem::apply_friction_change(run_, *control_.friction_change);
      run_.stepper->resume();
    }
    dem::check_health(run_, budget_, control_.ke_blowup_factor);
  }
}

template <int D>
void DemSimulation<D>::after_series() {
  // Before a checkpoint: a resumed run starts its first interval with fresh
  // extremes, as the uninterrupted run does (checkpoints fall on rows).
  for (auto& w : run_.system.walls) w.reset_force_extremes();
}

template <int D>
MethodReport DemSimulation<D>::report() const {
  using nlohmann::json;
  const auto& s = run_.system;
  const auto& p = s.particles;
  MethodReport r;
  r.method = "dem";
  r.dimension = D;
  r.rate_key = "particle_steps_per_s";
  r.items = static_cast<double>(p.size());
  if (scenario_) r.scenario = io::scenario_to_json(*scenario_);
  json walls = json::array();
  for (std::size_t w = 0; w < s.walls.size(); ++w) {
    const auto& wall = s.walls[w];
    walls.push_back({{"name", wall.name},
                     {"force_N", {wall.force.x(), wall.force.y(), wall.force.z()}},
                     {"peak_force_N", files_ ? files_->peak_wall_force[w] : 0.0},
                     {"impulse_Ns", {wall.impulse.x(), wall.impulse.y(), wall.impulse.z()}},
                     {"work_J", wall.work}});
  }
  r.resolved = {{"time_step_s", s.dt},
                {"critical_time_step_s", s.critical_time_step},
                {"reference_impact_speed_m_s", s.reference_speed},
                {"skin_m", s.skin},
                {"settle_time_s", s.settle_time},
                {"threads", threads_},
                {"backend", device_.empty() ? "cpu" : "gpu"}};
  if (!device_.empty()) r.resolved["device"] = device_;
  r.metrics = {{"particles", p.size()},
               {"removed_kinetic_energy_J", s.removed_kinetic_energy},
               {"particles_removed", s.removed},
               {"kinetic_energy_J", dem::kinetic_energy(p)},
               {"rotational_energy_J", dem::rotational_energy(p)},
               {"peak_kinetic_energy_J", files_ ? files_->peak_kinetic_energy : 0.0},
               {"peak_kinetic_energy_time_s", files_ ? files_->peak_kinetic_energy_time : 0.0},
               {"front_x_m", dem::front_x(p)},
               {"top_m", dem::top(p)},
               {"contacts_per_particle", p.size() ? 2.0 * s.pair_contacts / p.size() : 0.0},
               {"walls", walls}};
  r.run_extra = {{"neighbour_builds", s.neighbours.builds}};
  r.headline = headline();
  return r;
}

template <int D>
std::vector<StateArray> DemSimulation<D>::state_arrays() {
  auto& p = run_.system.particles;
  using Vec = typename dem::Particles<D>::Vec;
  using Rot = typename dem::Particles<D>::Rot;
  static_assert(sizeof(Vec) == D * sizeof(double), "positions must be D packed doubles");
  constexpr std::size_t spin = sizeof(Rot) / sizeof(double);  // 1 in 2D, 3 in 3D
  static_assert(spin == 1 || spin == D, "angular velocities: 1 or D packed doubles");
  const std::size_t n = p.size();
  using T = StateArray::Type;
  const std::vector<std::size_t> vec{n, D}, scalar{n};
  std::vector<StateArray> out{
      {"x", "m", T::Float64, p.x.data(), vec, false},
      {"v", "m/s", T::Float64, p.v.data(), vec, true},
      {"w", "rad/s", T::Float64, p.w.data(), spin == 1 ? scalar : vec, true},
      {"f", D == 2 ? "N/m" : "N", T::Float64, p.f.data(), vec, false},
      {"r", "m", T::Float64, p.r.data(), scalar, false},
      {"m", D == 2 ? "kg/m" : "kg", T::Float64, p.m.data(), scalar, false},
      {"id", "", T::Int64, p.id.data(), scalar, false}};
  // The walls' forces and torques: fields of the walls' structs, so strided
  // (one row per wall; in 2D the force's x, y and the torque's z).
  auto& walls = run_.system.walls;
  if (!walls.empty()) {
    const auto row = static_cast<std::ptrdiff_t>(sizeof(geometry::Wall));
    const auto item = static_cast<std::ptrdiff_t>(sizeof(double));
    const std::size_t nw = walls.size();
    out.push_back({"wall_force",
                   D == 2 ? "N/m" : "N",
                   T::Float64,
                   walls[0].force.data(),
                   std::vector<std::size_t>{nw, D},
                   false,
                   {row, item}});
    if (D == 2)
      out.push_back({"wall_torque",
                     "N",
                     T::Float64,
                     walls[0].torque.data() + 2,
                     std::vector<std::size_t>{nw},
                     false,
                     {row}});
    else
      out.push_back({"wall_torque",
                     "N m",
                     T::Float64,
                     walls[0].torque.data(),
                     std::vector<std::size_t>{nw, 3},
                     false,
                     {row, item}});
  }
  return out;
}

template <int D>
double DemSimulation<D>::kinetic_energy() const {
  return dem::kinetic_energy(run_.system.particles);
}

// "dem: 1160 particles, front at x = 0.31 m, top at 0.057 m; peak kinetic
// energy 0.84 J at t = 0.25 s; largest wall force 69 N on 'back'".
template <int D>
std::string DemSimulation<D>::headline() const {
  const auto& s = run_.system;
  const auto& p = s.particles;
  std::string line = fmt::format("dem: {} particles", p.size());
  if (s.removed > 0) line += fmt::format(" ({} left the domain)", s.removed);
  if (p.size() > 0)
    line += fmt::format(", front at x = {:.4g} m, top at {:.4g} m", dem::front_x(p), dem::top(p));
  if (!files_) return line;
  line += fmt::format("; peak kinetic energy {:.4g} J at t = {:.4g} s", files_->peak_kinetic_energy,
                      files_->peak_kinetic_energy_time);
  std::size_t largest = 0;
  for (std::size_t w = 0; w < s.walls.size(); ++w)
    if (files_->peak_wall_force[w] > files_->peak_wall_force[largest]) largest = w;
  if (!s.walls.empty() && files_->peak_wall_force[largest] > 0.0)
    line += fmt::format("; largest wall force {:.4g} N on '{}'", files_->peak_wall_force[largest],
                        s.walls[largest].name);
  return line;
}

template class DemSimulation<2>;
template class DemSimulation<3>;

namespace {

// run.backend = "gpu": refused before anything is built when the scenario uses
// what the GPU backend lacks (the list) or no GPU is usable here.
void check_backend(const dem::DemScenario& sc) {
  if (sc.run.backend != dem::Backend::Gpu) return;
  const auto missing = dem::gpu_missing_features(sc);
  if (!missing.empty()) throw InputError(dem::gpu_refusal(sc, missing));
  const auto device = dem::gpu::device();
  if (!device.usable) throw InputError("run.backend = \"gpu\": " + device.description);
}

template <int D>
std::unique_ptr<Simulation> create_dem(const dem::DemScenario& sc, const RunContext& ctx) {
  auto run = dem::build_dem<D>(sc, {ctx.threads, !ctx.resume, !ctx.resume});
  if (ctx.resume) {
    dem::load_checkpoint(run->system, dem::DemOutputs<D>::checkpoint_path(ctx.out));
    run->system.threads = ctx.threads;
  }
  if (sc.run.backend == dem::Backend::Gpu) run->stepper = dem::gpu::make_stepper<D>(run->system);
  return std::make_unique<DemSimulation<D>>(sc, std::move(run), ctx.out, ctx.resume, ctx.threads);
}

template <int D>
Validation validate_dem(const dem::DemScenario& sc) {
  check_backend(sc);
  // Building places the particles and checks the time step, without settling.
  auto run = dem::build_dem<D>(sc, {1, false});
  const double dt = run->system.dt;
  return {fmt::format("{}D DEM, {} particles, {} walls, time step {:.3g} s, critical {:.3g} s", D,
                      run->system.particles.size(), sc.walls.size(), dt,
                      run->system.critical_time_step),
          sc.run.duration / dt, sc.run.duration};
}

}  // namespace

Method dem_method() {
  Method m;
  m.name = "dem";
  m.accepts = [](const io::ScenarioFile& f) { return f.method == "dem"; };
  m.validate = [](const io::ScenarioFile& f) {
    const auto sc = io::parse_dem_scenario(f);
    return sc.run.dimension == 2 ? validate_dem<2>(sc) : validate_dem<3>(sc);
  };
  m.create = [](const io::ScenarioFile& f, const RunContext& ctx) {
    const auto sc = io::parse_dem_scenario(f);
    check_backend(sc);
    if (!ctx.resume) {
      ctx.prepare();
      // The resolved scenario makes the run reproducible and resumable.
      io::write_file_atomically(ctx.out / "scenario.toml", io::scenario_to_toml(sc));
    }
    return sc.run.dimension == 2 ? create_dem<2>(sc, ctx) : create_dem<3>(sc, ctx);
  };
  return m;
}

}  // namespace talus::run
