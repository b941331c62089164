// talus command line: a thin layer over the library. Exit codes: 0 success,
// 2 bad input (nothing ran), 1 failed run.
#include <fmt/core.h>

#include <CLI/CLI.hpp>
#include <cstdio>
#include <iostream>

#include "analyse.hpp"
#include "analyse_beam.hpp"
#include "analyse_structure.hpp"
#include "calibrate.hpp"
#include "commands.hpp"
#include "compare.hpp"
#include "talus/comm/comm.hpp"
#include "talus/core/error.hpp"
#include "talus/core/version.hpp"

int main(int argc, char** argv) {
  using namespace talus::app;
  // Under mpirun each process is a rank (src/talus/comm/): `talus run` of a
  // method that spreads over ranks uses them all; every other command is
  // refused on several ranks, rather than run N copies into one folder.
  talus::comm::Comm::init(&argc, &argv);
  struct EndMpi {
    ~EndMpi() { talus::comm::Comm::finalize(); }
  } end_mpi;
  const auto& world = talus::comm::Comm::world();
  if (!talus::comm::Comm::built_with_mpi() && talus::comm::Comm::launched_processes() > 1) {
    fmt::print(stderr,
               "talus: error: started by an MPI launcher on {} processes, but this talus was "
               "built without MPI (docs/mpi.md): start it without mpirun\n",
               talus::comm::Comm::launched_processes());
    return 2;
  }
  // An error on one rank ends them all (the others would wait for it in a
  // collective); a bad input, found alike on every rank, is printed by rank 0.
  auto fail = [&](int code, const char* kind, const char* what) {
    if (world.root() || code != 2)
      fmt::print(stderr, "talus: {}{}: {}\n", kind,
                 world.size() > 1 ? fmt::format(" (MPI rank {})", world.rank()) : "", what);
    if (world.size() > 1) {
      std::fflush(stderr);
      world.abort(code);
    }
    return code;
  };
  CLI::App cli{"talus: granular flows and mass movements (DEM, depth-averaged runout, MPM)"};
  cli.set_version_flag("--version", talus::version());
  cli.require_subcommand(1);

  RunOptions run;
  auto* run_cmd = cli.add_subcommand("run", "run a scenario file (or resume an interrupted run)");
  run_cmd->add_option("file", run.file, "scenario file (.toml)");
  run_cmd->add_option("--out,-o", run.out, "output folder (default: runs/<scenario name>)");
  run_cmd->add_option("--set", run.sets, "override a scenario value: key=value (repeatable)")
      ->allow_extra_args(false);
  run_cmd
      ->add_option("--threads,-j", run.threads,
                   "OpenMP threads (default 1; with --resume the run's own)")
      ->check(CLI::PositiveNumber);
  run_cmd->add_option("--resume", run.resume, "continue the interrupted run in this folder");
  run_cmd
      ->add_option("--backend", run.backend,
                   "where DEM steps run: cpu or gpu (sets run.backend; docs/gpu.md)")
      ->check(CLI::IsMember({"cpu", "gpu"}));
  run_cmd->add_flag("--force", run.force, "write into an existing output folder");
  run_cmd->add_flag("--quiet,-q", run.quiet, "no progress on stderr");
  run_cmd->add_flag("--allow-long-run", run.allow_long_run,
                    "run even when the run is estimated above 10^9 steps");
  run_cmd
      ->add_option("--log-interval", run.log_seconds,
                   "wall seconds between progress lines in log.txt (and on stderr when it is not "
                   "a terminal)")
      ->check(CLI::PositiveNumber);

  ValidateOptions val;
  auto* val_cmd = cli.add_subcommand("validate", "check a scenario file without running it");
  val_cmd->add_option("file", val.file, "scenario file")->required();
  val_cmd->add_option("--set", val.sets, "override a scenario value: key=value");
  val_cmd->add_option("--backend", val.backend, "cpu or gpu (sets run.backend)")
      ->check(CLI::IsMember({"cpu", "gpu"}));
  val_cmd->add_flag("--allow-long-run", val.allow_long_run,
                    "accept a run estimated above 10^9 steps");

  auto* list_cmd = cli.add_subcommand("list", "list the bundled scenarios");
  CompareOptions cmp;
  auto* cmp_cmd = cli.add_subcommand(
      "compare", "run one flume with several methods and report them side by side");
  cmp_cmd->add_option("file", cmp.file, "comparison file (method = \"compare\")")->required();
  cmp_cmd
      ->add_option("--methods", cmp.methods, "methods to run, e.g. dem,dan (default: all listed)")
      ->delimiter(',');
  cmp_cmd->add_option("--out,-o", cmp.out, "output folder (default: runs/compare-<name>)");
  cmp_cmd->add_option("--threads,-j", cmp.threads, "OpenMP threads")->check(CLI::PositiveNumber);
  cmp_cmd->add_flag("--force", cmp.force, "write into an existing output folder");
  cmp_cmd->add_flag("--quiet,-q", cmp.quiet, "no progress on stderr");
  CalibrateOptions cal;
  auto* cal_cmd = cli.add_subcommand(
      "calibrate",
      "fit parameters to measured numbers: a grid of trial values of one, or a bounded optimiser "
      "over several");
  cal_cmd->add_option("file", cal.file, "scenario file")->required();
  cal_cmd->add_option("--parameter,-p", cal.parameter, "grid: the key to vary, as for --set");
  cal_cmd->add_option("--values", cal.values, "grid: trial values (comma separated)")
      ->delimiter(',');
  cal_cmd->add_option("--param", cal.params,
                      "optimiser: KEY=LO:HI[:START], a --set key and its bounds (repeatable)");
  cal_cmd
      ->add_option("--optimizer", cal.optimizer,
                   "optimiser: NLopt's bobyqa (default), sbplx, neldermead or cobyla")
      ->check(CLI::IsMember({"bobyqa", "sbplx", "neldermead", "cobyla"}));
  cal_cmd->add_option("--max-evals", cal.max_evals, "optimiser: most runs (default 40)")
      ->check(CLI::PositiveNumber);
  cal_cmd
      ->add_option("--xtol", cal.xtol,
                   "optimiser: stop when a step moves every parameter by less than this fraction "
                   "of its range (default 1e-3)")
      ->check(CLI::PositiveNumber);
  cal_cmd
      ->add_option("--objective", cal.objective,
                   "optimiser: squares (sum of squared deviations, default) or abs")
      ->check(CLI::IsMember({"squares", "abs"}));
  cal_cmd
      ->add_option("--target", cal.targets,
                   "metric=value: a dotted path in summary.json and its measured value "
                   "(repeatable)")
      ->required();
  cal_cmd->add_option("--set", cal.sets, "override a scenario value: key=value (repeatable)");
  cal_cmd->add_option("--out,-o", cal.out, "output folder (default: runs/calibrate-<scenario>)");
  cal_cmd->add_option("--threads,-j", cal.threads, "OpenMP threads")->check(CLI::PositiveNumber);
  cal_cmd->add_flag("--force", cal.force, "write into an existing output folder");
  cal_cmd->add_flag("--quiet,-q", cal.quiet, "no progress on stderr");

  CoarseGrainOptions cg;
  auto* ana_cmd = cli.add_subcommand("analyse", "analyses of a finished run's output folder");
  ana_cmd->require_subcommand(1);
  auto* cg_cmd = ana_cmd->add_subcommand(
      "coarse-grain", "coarse-grained density and velocity fields over one period (Goetz app. C)");
  cg_cmd->add_option("run", cg.run_dir, "output folder of a DEM run")->required();
  cg_cmd->add_option("--cells", cg.cells, "grid cells NX,NY,NZ")->required()->delimiter(',');
  cg_cmd->add_option("--period", cg.period, "interval between the two snapshots of a velocity, s")
      ->required();
  cg_cmd->add_option("--from", cg.from, "first interval starts at this time, s (default 0)");
  cg_cmd->add_option("--to", cg.to, "last interval ends by this time, s (default: the end)");
  cg_cmd->add_option("--box", cg.box, "grid box xmin,ymin,zmin,xmax,ymax,zmax (default: grains)")
      ->delimiter(',');
  cg_cmd->add_option("--axis-width", cg.axis_width, "side of the column around the axis, m");
  cg_cmd->add_option("--out,-o", cg.out, "output folder (default: RUN/coarse_grain)");
  cg_cmd->add_flag("--plot", cg.plot, "draw the r-z velocity field (plots/plot_coarse_grain.py)");
  cg_cmd->add_flag("--quiet,-q", cg.quiet, "no progress on stderr");
  // The structure of the grains (Goetz 5.3): each command reads RUN's particle snapshots and
  // writes into RUN/analysis unless --out is given.
  auto structure = [&](const char* name, const char* what, StructureOptions& o) {
    auto* c = ana_cmd->add_subcommand(name, what);
    c->add_option("run", o.run_dir, "output folder of a DEM run")->required();
    c->add_option("--out,-o", o.out, "output folder (default: RUN/analysis)");
    c->add_flag("--quiet,-q", o.quiet, "no summary on stderr");
    return c;
  };
  ContactsOptions zc;
  auto* z_cmd =
      structure("contacts", "contact number z of every snapshot, from the grains' overlaps", zc);
  z_cmd->add_option("--from", zc.from,
                    "first snapshot at or after this time, s (default: the first)");
  z_cmd->add_option("--to", zc.to, "last snapshot at or before this time, s (default: the last)");
  z_cmd->add_option("--gap", zc.gap,
                    "grains whose surfaces are closer than this touch, m (default 0: overlap)");
  z_cmd->add_option("--min-contacts", zc.min_contacts,
                    "rattlers: grains with fewer contacts (default D+1)");
  RdfCommandOptions rc;
  auto* rdf_cmd = structure("rdf", "radial distribution function g(r) of one snapshot", rc);
  rdf_cmd->add_option("--time,-t", rc.time, "snapshot nearest this time, s (default: the last)");
  rdf_cmd->add_option("--rmax", rc.r_max, "largest distance, m (default: 5 mean diameters)");
  rdf_cmd->add_option("--bins", rc.bins, "number of bins (default 100)");
  D2minCommandOptions dc;
  auto* d2_cmd =
      structure("d2min", "non-affine displacement D2min of every grain between two snapshots", dc);
  d2_cmd->add_option("--from", dc.from,
                     "reference snapshot nearest this time, s (default: the first)");
  d2_cmd->add_option("--to", dc.to, "later snapshot nearest this time, s (default: the last)");
  d2_cmd->add_option("--cutoff", dc.cutoff,
                     "neighbours within this distance at --from, m (default: 2.5 mean diameters)");
  d2_cmd->add_option("--min-contacts", dc.min_contacts,
                     "leave out grains with fewer contacts at --from (default 0; Goetz: 3)");
  d2_cmd->add_option("--gap", dc.gap, "contact gap for --min-contacts, m (default 0)");
  auto* corr_opt = d2_cmd->add_option(
      "--correlation", dc.correlation,
      "also the spatial autocorrelation C(r) of D_min in bins of this width, m (Goetz eq. 48)");
  d2_cmd
      ->add_option("--correlation-rmax", dc.correlation_rmax,
                   "largest distance of C(r), m (default: 5 mean diameters)")
      ->needs(corr_opt);
  PackingOptions pc;
  auto* pk_cmd = structure(
      "packing", "local packing fraction of every grain from its radical Voronoi cell", pc);
  pk_cmd->add_option("--time,-t", pc.time, "snapshot nearest this time, s (default: the last)");
  pk_cmd->add_option("--margin", pc.margin,
                     "also leave grains this close to the box out of the mean, m");

  BeamAnalysisOptions bc;
  auto* beam_cmd = ana_cmd->add_subcommand(
      "beam", "E_b and Y_b of a 4-point beam run again, with another smoothing (Goetz 5.3)");
  beam_cmd->add_option("run", bc.run_dir, "output folder of a four-point [beam] run")->required();
  beam_cmd->add_option("--yield-smoothing", bc.yield_smoothing,
                       "Gaussian width in strain for Y_b (default: the run's)");
  beam_cmd->add_option("--linear-strain", bc.linear_strain,
                       "E_b from the fit over 0 < strain <= this (default 0.002)");
  beam_cmd->add_option("--out,-o", bc.out, "output folder (default: RUN/analysis)");
  beam_cmd->add_flag("--quiet,-q", bc.quiet, "no summary on stderr");

  try {
    cli.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    const int rc = cli.exit(e);
    return rc == 0 ? 0 : 2;
  }
  if (world.size() > 1 && !run_cmd->parsed()) {
    if (world.root())
      fmt::print(stderr,
                 "talus: error: started on {} MPI ranks; only `talus run` of an fv2d scenario "
                 "runs on several (docs/mpi.md): start this command without mpirun\n",
                 world.size());
    return 2;
  }
  try {
    if (run_cmd->parsed()) return run_command(run);
    if (val_cmd->parsed()) return validate_command(val);
    if (list_cmd->parsed()) return list_command();
    if (cal_cmd->parsed()) return calibrate_command(cal);
    if (cmp_cmd->parsed()) return compare_command(cmp);
    if (cg_cmd->parsed()) return coarse_grain_command(cg);
    if (z_cmd->parsed()) return contacts_command(zc);
    if (rdf_cmd->parsed()) return rdf_command(rc);
    if (d2_cmd->parsed()) return d2min_command(dc);
    if (pk_cmd->parsed()) return packing_command(pc);
    if (beam_cmd->parsed()) return beam_analysis_command(bc);
  } catch (const talus::InputError& e) {
    return fail(2, "error", e.what());
  } catch (const talus::RunError& e) {
    return fail(1, "run failed", e.what());
  } catch (const std::exception& e) {
    return fail(1, "run failed", e.what());
  }
  return 0;
}
