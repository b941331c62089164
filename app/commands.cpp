#include "commands.hpp"

#include <fmt/core.h>
#include <omp.h>
#include <toml++/toml.h>
#include <unistd.h>

#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <fstream>

#include "summary.hpp"
#include "talus/analysis/beam.hpp"
#include "talus/analysis/beam_four_point.hpp"
#include "talus/analysis/dam_break.hpp"
#include "talus/analysis/flume_observer.hpp"
#include "talus/analysis/gripper.hpp"
#include "talus/analysis/hollow_sphere.hpp"
#include "talus/analysis/triaxial.hpp"
#include "talus/core/error.hpp"
#include "talus/core/version.hpp"
#include "talus/dem/builder.hpp"
#include "talus/dem/checkpoint.hpp"
#include "talus/dem/driver.hpp"
#include "talus/dem/output_observer.hpp"
#include "talus/io/compare_file.hpp"
#include "talus/io/scenario.hpp"
#include "talus/io/scenario_mpm.hpp"
#include "talus/io/scenario_runout.hpp"
#include "talus/mpm/checkpoint.hpp"
#include "talus/mpm/flume_observer.hpp"
#include "talus/mpm/output_observer.hpp"
#include "talus/mpm/scenario.hpp"
#include "talus/runout/builder.hpp"
#include "talus/runout/grid/fv2d_builder.hpp"
#include "talus/runout/grid/fv2d_output.hpp"
#include "talus/runout/output_observer.hpp"

namespace fs = std::filesystem;

namespace talus::app {

void prepare_output(const std::string& out_text, bool force) {
  const fs::path out(out_text);
  if (fs::exists(out) && !fs::is_directory(out))
    throw InputError(out.string() + ": output path exists and is not a folder");
  if (fs::exists(out) && !fs::is_empty(out)) {
    if (!force)
      throw InputError(out.string() +
                       ": output folder exists and is not empty; use --force to overwrite it or "
                       "--out to choose another");
    for (const auto& e : fs::directory_iterator(out)) fs::remove_all(e.path());
  }
  fs::create_directories(out);
}

std::string scenarios_folder() {
  if (const char* env = std::getenv("TALUS_SCENARIOS")) return env;
  return std::string(TALUS_SOURCE_DIR) + "/scenarios";
}

namespace {

void progress_line(double t, double end, double sps, double dt) {
  const double left = sps > 0 ? (end - t) / dt / sps : 0.0;
  fmt::print(stderr, "\r  t = {:.4f} / {:.4f} s   {:.0f} steps/s   {:.0f} s left   ", t, end, sps,
             left);
  if (t >= end) fmt::print(stderr, "\n");
  std::fflush(stderr);
}

// The numbers a barrier designer looks at first, from the flume's summary.
void print_flume_headline(const nlohmann::json& f, double series_interval) {
  const auto& b = f["forces"]["barrier"];
  auto when = [](const nlohmann::json& t) {  // -1: never
    return t.get<double>() < 0 ? std::string("never") : fmt::format("{:.3f} s", t.get<double>());
  };
  fmt::print(stderr,
             "talus: flume: front at the arc {}, at the barrier {}; run-up {:.3f} m "
             "along the barrier ({:.3f} m high), {:.3f} m at most; main deposit from s = {:.3f} m, "
             "{} grains upstream of it\n",
             when(f["front"]["reach_arc_time"]), when(f["front"]["reach_barrier_time"]),
             f["runup"]["final_s"].get<double>(), f["runup"]["final_height"].get<double>(),
             f["runup"]["max_s"].get<double>(), f["deposit"]["tail_s"].get<double>(),
             f["deposit"]["stranded"].get<int>());
  fmt::print(stderr,
             "talus: flume: barrier per metre of width: x impulse {:.1f} N s, peak F_x {:.0f} N "
             "({:.3g} ms mean) and {:.0f} N (single step), F_x at the end {:.0f} N\n",
             b["impulse_x"].get<double>(), b["peak_fx"].get<double>(), series_interval * 1e3,
             b["peak_step_fx"].get<double>(), b["final_fx"].get<double>());
}

template <int D>
int run_dem_scenario(const dem::DemScenario& sc, const fs::path& out, const RunOptions& opt,
                     bool resume) {
  const auto t_setup = std::chrono::steady_clock::now();
  auto run = dem::build_dem<D>(sc, {opt.threads, !resume, !resume});
  if (resume) {
    dem::load_checkpoint(run->system, dem::DemOutputs<D>::checkpoint_path(out));
    run->system.threads = opt.threads;
  }
  const double setup_s =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - t_setup).count();
  dem::DemOutputs<D> outputs(out, run->system, resume, run->system.time);
  const bool show = !opt.quiet && isatty(STDERR_FILENO);
  const double dt = run->system.dt;
  if (show) outputs.progress = [dt](double t, double e, double s) { progress_line(t, e, s, dt); };
  const auto control = dem::make_run_control(sc, dt);
  RunSummary summary;
  summary.output = out;
  summary.setup_seconds = setup_s;
  std::vector<dem::DemObserver<D>*> observers = {&outputs};
  std::unique_ptr<analysis::FlumeObserver> flume;
  if constexpr (D == 2) {
    if (sc.flume) {
      const auto& f = *sc.flume;
      const auto geometry = geometry::make_flume(f);
      flume = std::make_unique<analysis::FlumeObserver>(out, geometry, f, run->system, resume,
                                                        run->system.time);
      outputs.decorate = [&flume](const dem::DemSystem<2>& s, io::ParticleFrame& frame) {
        flume->add_layers(s, frame);
      };
      observers.push_back(flume.get());
    }
  }
  std::unique_ptr<analysis::TriaxialObserver> triaxial;
  std::unique_ptr<analysis::HollowSphereObserver> hollow;
  std::unique_ptr<analysis::GripperObserver> gripper;
  std::unique_ptr<analysis::BeamObserver> beam;
  std::unique_ptr<analysis::FourPointObserver> beam4;
  if constexpr (D == 3) {
    if (sc.triaxial) {
      triaxial = std::make_unique<analysis::TriaxialObserver>(out, sc, run->system, resume,
                                                              run->system.time);
      // Before the outputs, whose on_checkpoint writes the checkpoint: a run
      // killed in between then has triaxial.csv flushed up to it.
      observers.insert(observers.begin(), triaxial.get());
    }
    if (sc.hollow_sphere) {
      hollow = std::make_unique<analysis::HollowSphereObserver>(out, sc, run->system, resume,
                                                                run->system.time);
      observers.insert(observers.begin(), hollow.get());  // flushed before the checkpoint
    }
    if (sc.gripper) {
      gripper = std::make_unique<analysis::GripperObserver>(out, sc, run->system);
      observers.insert(observers.begin(), gripper.get());
    }
    if (sc.beam && sc.beam->test == dem::BeamTest::ThreePoint) {
      beam = std::make_unique<analysis::BeamObserver>(out, sc, run->system);
      observers.insert(observers.begin(), beam.get());
    } else if (sc.beam) {
      beam4 = std::make_unique<analysis::FourPointObserver>(out, sc, run->system);
      observers.insert(observers.begin(), beam4.get());
    }
  }
  try {
    const auto stats = dem::run_dem<D>(*run, control, observers, !resume);
    summary.steps = stats.steps;
    summary.loop_seconds = stats.wall_seconds;
    if constexpr (D == 2) {
      if (flume) summary.analysis["flume"] = flume->finish(*run);
      if (sc.dam_break) {
        const analysis::Grains grains{run->system.particles.x, run->system.particles.r};
        summary.analysis["dam_break"] = analysis::report_dam_break(grains, *sc.dam_break, out);
      }
    }
    if (triaxial) summary.analysis["triaxial"] = triaxial->finish();
    if (hollow) summary.analysis["hollow_sphere"] = hollow->finish();
    if (gripper) summary.analysis["gripper"] = gripper->finish();
    if (beam) summary.analysis["beam"] = beam->finish();
    if (beam4) summary.analysis["beam"] = beam4->finish();
    write_dem_summary<D>(sc, *run, outputs, summary, opt.threads, "completed", "");
  } catch (const RunError& e) {
    write_dem_summary<D>(sc, *run, outputs, summary, opt.threads, "failed", e.what());
    throw;
  }
  if (!opt.quiet) {
    fmt::print(stderr, "talus: {} steps in {:.2f} s; results in {}\n", summary.steps,
               summary.loop_seconds, out.string());
    if (summary.analysis.contains("flume"))
      print_flume_headline(summary.analysis["flume"], sc.output.series_interval);
  }
  return 0;
}

// --- runout, model = "fv2d": 2D on a terrain grid ---
int run_fv2d_scenario(const runout::RunoutScenario& sc, const fs::path& out,
                      const RunOptions& opt) {
  const auto t_setup = std::chrono::steady_clock::now();
  auto solver = runout::build_fv2d(sc);
  prepare_output(out, opt.force);
  std::ofstream(out / "scenario.toml") << io::runout_scenario_to_toml(sc);
  runout::Fv2dOutputs outputs(out, sc.grid);
  if (!opt.quiet && isatty(STDERR_FILENO))
    outputs.progress = [](double t, double e, double sps) { progress_line(t, e, sps, 1e-2); };
  RunSummary summary;
  summary.output = out;
  summary.setup_seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - t_setup).count();
  runout::Fv2dMaxima maxima;
  const double v0 = solver.volume();
  try {
    const auto stats = runout::run_fv2d(solver, runout::fv2d_run_control(sc), maxima, {&outputs});
    summary.steps = stats.steps;
    summary.loop_seconds = stats.wall_seconds;
    outputs.write_results(solver, maxima);
    write_fv2d_summary(sc, solver, maxima, v0, summary, opt.threads, "completed", "");
  } catch (const RunError& e) {
    write_fv2d_summary(sc, solver, maxima, v0, summary, opt.threads, "failed", e.what());
    throw;
  }
  if (!opt.quiet)
    fmt::print(stderr, "talus: {} steps in {:.3f} s; results in {}\n", summary.steps,
               summary.loop_seconds, out.string());
  return 0;
}

// --- runout (method = "runout"): 1D DAN ---
int run_runout_scenario(const io::ScenarioFile& file, const RunOptions& opt) {
  const auto sc = io::parse_runout_scenario(file);
  const fs::path out =
      opt.out.empty() ? fs::path("runs") / (sc.name.empty() ? "run" : sc.name) : fs::path(opt.out);
  if (sc.model == runout::RunoutModel::Fv2d) return run_fv2d_scenario(sc, out, opt);
  const auto t_setup = std::chrono::steady_clock::now();
  auto setup = runout::build_dan(sc);
  prepare_output(out, opt.force);
  std::ofstream(out / "scenario.toml") << io::runout_scenario_to_toml(sc);
  runout::DanOutputs outputs(out);
  if (!opt.quiet && isatty(STDERR_FILENO))
    outputs.progress = [dt = sc.control.time_step > 0 ? sc.control.time_step : 1e-4](
                           double t, double e, double sps) { progress_line(t, e, sps, dt); };
  runout::RunoutTracker tracker(setup.barrier_start_s, sc.tail_fraction);
  RunSummary summary;
  summary.output = out;
  summary.setup_seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - t_setup).count();
  try {
    const auto stats = runout::run_dan(setup.model, sc.control, tracker, {&outputs});
    summary.steps = stats.steps;
    summary.loop_seconds = stats.wall_seconds;
    outputs.write_results(tracker.results());
    write_runout_summary(sc, setup.model, tracker.results(), summary, "completed", "");
  } catch (const RunError& e) {
    write_runout_summary(sc, setup.model, tracker.results(), summary, "failed", e.what());
    throw;
  }
  if (!opt.quiet)
    fmt::print(stderr, "talus: {} steps in {:.3f} s; results in {}\n", summary.steps,
               summary.loop_seconds, out.string());
  return 0;
}

// --- MPM ---
template <int D>
int run_mpm_scenario(const mpm::MpmScenario& sc, const fs::path& out, const RunOptions& opt) {
  const auto t_setup = std::chrono::steady_clock::now();
  const bool resume = !opt.resume.empty();
  auto solver = mpm::build_mpm<D>(sc);
  if (resume) mpm::load_checkpoint(solver, mpm::MpmOutputs<D>::checkpoint_path(out));
  const double setup_s =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - t_setup).count();
  std::vector<double> c0;
  for (const auto& m : sc.materials) c0.push_back(mpm::initial_cohesion(m));
  mpm::MpmOutputs<D> outputs(out, c0, resume, solver.time);
  if (!opt.quiet && isatty(STDERR_FILENO))
    outputs.progress = [&solver](double t, double e, double sps) {
      progress_line(t, e, sps, solver.last_dt > 0 ? solver.last_dt : 1.0);
    };
  mpm::MpmRunControl control;
  control.duration = sc.duration;
  control.series_interval =
      sc.output.series_interval > 0 ? sc.output.series_interval : sc.duration / 200.0;
  control.snapshot_interval = sc.output.snapshots ? sc.output.snapshot_interval : -1.0;
  control.checkpoint_interval = sc.output.checkpoint_interval;
  control.ke_blowup_factor = sc.ke_blowup_factor;
  RunSummary summary;
  summary.output = out;
  summary.setup_seconds = setup_s;
  std::vector<mpm::MpmObserver<D>*> observers = {&outputs};
  std::unique_ptr<mpm::MpmFlumeObserver> flume;
  if constexpr (D == 2) {
    if (sc.flume) {
      flume = std::make_unique<mpm::MpmFlumeObserver>(out, *sc.flume, solver, resume, solver.time);
      observers.push_back(flume.get());
    }
  }
  try {
    const auto stats = mpm::run_mpm<D>(solver, control, observers, !resume);
    summary.steps = stats.steps;
    summary.loop_seconds = stats.wall_seconds;
    if constexpr (D == 2)
      if (flume) summary.analysis["flume"] = flume->finish(solver);
    write_mpm_summary<D>(sc, solver, outputs, summary, opt.threads, "completed", "");
  } catch (const RunError& e) {
    summary.steps = solver.steps;
    write_mpm_summary<D>(sc, solver, outputs, summary, opt.threads, "failed", e.what());
    throw;
  }
  if (!opt.quiet)
    fmt::print(stderr, "talus: {} steps in {:.2f} s; results in {}\n", summary.steps,
               summary.loop_seconds, out.string());
  return 0;
}

int run_mpm_command(const io::ScenarioFile& file, const RunOptions& opt) {
  auto sc = io::parse_mpm_scenario(file);
  fs::path out = opt.resume;
  if (opt.resume.empty()) {
    out = opt.out.empty() ? fs::path("runs") / (sc.name.empty() ? "run" : sc.name)
                          : fs::path(opt.out);
    prepare_output(out, opt.force);
    std::ofstream(out / "scenario.toml") << io::mpm_scenario_to_toml(sc);
    // The run uses the resolved file it wrote, as a resume does: an angle
    // through degrees and back may differ in the last bit, and a resumed run
    // must start from the very same numbers to end in the same state.
    sc = io::parse_mpm_scenario(io::load_scenario_file((out / "scenario.toml").string(), {}));
  }
  return sc.dimension == 2 ? run_mpm_scenario<2>(sc, out, opt) : run_mpm_scenario<3>(sc, out, opt);
}

}  // namespace

int run_command(const RunOptions& opt) {
  omp_set_num_threads(opt.threads);
  fs::path out;
  std::string scenario_path;
  const bool resume = !opt.resume.empty();
  if (resume) {
    out = opt.resume;
    scenario_path = (out / "scenario.toml").string();
    if (!fs::exists(dem::DemOutputs<3>::checkpoint_path(out)))
      throw InputError(out.string() +
                       ": no checkpoint.bin to resume from (set "
                       "output.checkpoint_interval to write checkpoints)");
  } else {
    if (opt.file.empty()) throw InputError("talus run: a scenario file is required");
    scenario_path = opt.file;
  }
  const auto file =
      io::load_scenario_file(scenario_path, resume ? std::vector<std::string>{} : opt.sets);
  if (file.method == "runout") {
    if (resume) throw InputError(out.string() + ": runout runs write no checkpoints to resume");
    return run_runout_scenario(file, opt);
  }
  if (file.method == "mpm") return run_mpm_command(file, opt);
  if (file.method == "compare")
    throw InputError(scenario_path + ": a comparison file; run it with `talus compare " +
                     scenario_path + "`");
  const auto sc = io::parse_dem_scenario(file);
  if (!resume) {
    out = opt.out.empty() ? fs::path("runs") / (sc.name.empty() ? "run" : sc.name)
                          : fs::path(opt.out);
    prepare_output(out, opt.force);
    // The resolved scenario makes the run reproducible and resumable.
    std::ofstream(out / "scenario.toml") << io::scenario_to_toml(sc);
  }
  return sc.run.dimension == 2 ? run_dem_scenario<2>(sc, out, opt, resume)
                               : run_dem_scenario<3>(sc, out, opt, resume);
}

int validate_command(const ValidateOptions& opt) {
  const auto file = io::load_scenario_file(opt.file, opt.sets);
  if (file.method == "compare") {
    const auto c = io::read_compare_file(opt.file);
    for (const auto& [method, path] : c.methods) validate_command({path, {}});
    fmt::print("{}: valid comparison of {} methods\n", opt.file, c.methods.size());
    return 0;
  }
  if (file.method == "runout") {
    const auto rsc = io::parse_runout_scenario(file);
    if (rsc.model == runout::RunoutModel::Fv2d) {
      const auto solver = runout::build_fv2d(rsc);
      fmt::print("{}: valid (2D runout on a {} x {} grid of {} m cells, {:.4g} m^3 released)\n",
                 opt.file, rsc.grid.shape.nx, rsc.grid.shape.ny, rsc.grid.shape.dx,
                 solver.volume());
      return 0;
    }
    const auto setup = runout::build_dan(rsc);
    fmt::print("{}: valid (1D DAN runout, {} boundary blocks, {:.4g} m^3 released)\n", opt.file,
               setup.model.size(), setup.model.total_mass() / rsc.params.density);
    return 0;
  }
  if (file.method == "mpm") {  // --- MPM ---
    const auto sc = io::parse_mpm_scenario(file);
    std::size_t n = 0;
    double dt = 0;
    if (sc.dimension == 2) {
      const auto s = mpm::build_mpm<2>(sc);
      n = s.particles.size(), dt = s.time_step();
    } else {
      const auto s = mpm::build_mpm<3>(sc);
      n = s.particles.size(), dt = s.time_step();
    }
    fmt::print("{}: valid ({}D MPM, {} points, {} material{}, first time step {:.3g} s)\n",
               opt.file, sc.dimension, n, sc.materials.size(), sc.materials.size() == 1 ? "" : "s",
               dt);
    return 0;
  }
  const auto sc = io::parse_dem_scenario(file);
  // Building places the particles and checks the time step, without settling.
  double dt = 0, crit = 0;
  std::size_t n = 0;
  if (sc.run.dimension == 2) {
    auto run = dem::build_dem<2>(sc, {1, false});
    dt = run->system.dt, crit = run->system.critical_time_step, n = run->system.particles.size();
  } else {
    auto run = dem::build_dem<3>(sc, {1, false});
    dt = run->system.dt, crit = run->system.critical_time_step, n = run->system.particles.size();
  }
  fmt::print("{}: valid ({}D DEM, {} particles, {} walls, time step {:.3g} s, critical {:.3g} s)\n",
             opt.file, sc.run.dimension, n, sc.walls.size(), dt, crit);
  return 0;
}

int list_command() {
  const fs::path dir = scenarios_folder();
  if (!fs::is_directory(dir)) throw InputError(dir.string() + ": scenarios folder not found");
  std::vector<fs::path> files;
  for (const auto& e : fs::directory_iterator(dir))
    if (e.path().extension() == ".toml") files.push_back(e.path());
  std::sort(files.begin(), files.end());
  for (const auto& f : files) {
    std::string desc;
    try {
      const auto t = toml::parse_file(f.string());
      desc = t["description"].value_or(std::string());
    } catch (const std::exception&) {
      desc = "(unreadable)";
    }
    fmt::print("{:<28} {}\n", f.stem().string(), desc);
  }
  return 0;
}

}  // namespace talus::app
