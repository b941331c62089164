// Runs each method's scenario of a comparison file into <out>/<method>/, then
// puts their flume results side by side: comparison.json and .md (arrival at
// the barrier, final front, run-up, deposit tail), and for the plots
// compare/front_<method>.csv, compare/surface_<method>.csv and compare/path.csv.
#include "compare.hpp"

#include <fmt/core.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>

#include "commands.hpp"
#include "talus/core/error.hpp"
#include "talus/geometry/flume.hpp"
#include "talus/io/csv_reader.hpp"
#include "talus/io/csv_writer.hpp"
#include "talus/run/output_folder.hpp"
#include "talus/scenario/compare_file.hpp"
#include "talus/scenario/scenario.hpp"
#include "talus/scenario/scenario_mpm.hpp"
#include "talus/scenario/scenario_runout.hpp"

namespace fs = std::filesystem;

namespace talus::app {

namespace {

// The flume a method's scenario describes; InputError when it has none.
geometry::FlumeGeometry flume_of(const std::string& method, const std::string& path) {
  const auto file = io::load_scenario_file(path, {});
  if (method == "dem") {
    const auto sc = io::parse_dem_scenario(file);
    if (!sc.flume) throw InputError(path + ": the DEM scenario of a comparison needs a [flume]");
    return geometry::make_flume(sc.flume->shape);
  }
  if (method == "dan") {
    const auto sc = io::parse_runout_scenario(file);
    if (sc.model != runout::RunoutModel::Dan || sc.path.kind != runout::PathKind::Flume)
      throw InputError(path +
                       ": the DAN scenario of a comparison needs model = \"dan\" on a "
                       "[path] of type \"flume\"");
    return geometry::make_flume(sc.path.flume);
  }
  if (method == "fv2d" || method == "two_phase") {
    const auto sc = io::parse_runout_scenario(file);
    const auto model = method == "fv2d" ? runout::RunoutModel::Fv2d : runout::RunoutModel::TwoPhase;
    if (sc.model != model || !sc.grid.on_path)
      throw InputError(fmt::format(
          "{}: the {} scenario of a comparison needs model = \"{}\" on a [path] of type "
          "\"flume\" (the flume extruded into the grid)",
          path, method, method));
    return geometry::make_flume(sc.path.flume);
  }
  if (method == "mpm") {
    const auto sc = io::parse_mpm_scenario(file);
    if (!sc.flume || sc.flume->release_material_index < 0)
      throw InputError(path +
                       ": the MPM scenario of a comparison needs a [flume] with a "
                       "[flume.release]");
    return geometry::make_flume(sc.flume->shape);
  }
  throw InputError(
      fmt::format("{}: method '{}' cannot take part in a flume comparison yet", path, method));
}

bool same_flume(const geometry::FlumeGeometry& a, const geometry::FlumeGeometry& b) {
  const double tol = 1e-9;
  return std::abs(a.beta - b.beta) < tol && std::abs(a.radius - b.radius) < tol &&
         std::abs(a.l_star - b.l_star) < tol && std::abs(a.barrier_length - b.barrier_length) < tol;
}

struct Result {
  double arrival = NAN, front = NAN, runup_distance = NAN, runup_elevation = NAN, tail = NAN;
  std::vector<double> t, s, x, y;  // front versus time; final surface
};

nlohmann::json load_json(const fs::path& p) {
  nlohmann::json j;
  std::ifstream(p) >> j;
  return j;
}

double number(const nlohmann::json& j) { return j.is_number() ? j.get<double>() : NAN; }

// A DEM run's flume block, or an MPM run's (the MPM flume analysis writes the
// same keys and files, analysis/mpm_flume_observer.hpp).
Result read_dem(const fs::path& dir) {
  const auto f = load_json(dir / "summary.json").at("flume");
  Result r;
  r.arrival = number(f["front"]["reach_barrier_time"]);
  if (r.arrival < 0) r.arrival = NAN;
  r.front = number(f["front"]["final_s"]);
  r.runup_distance = number(f["runup"]["final_s"]);
  r.runup_elevation = number(f["runup"]["final_height"]) + number(f["path"]["bed_low_y"]);
  r.tail = number(f["deposit"]["tail_s"]);
  const auto front = io::read_csv(dir / "flume" / "front.csv");
  for (const auto& row : front.rows) {
    r.t.push_back(row[front.column("time")]);
    r.s.push_back(row[front.column("front_s")]);
  }
  const auto surface = io::read_csv(dir / "flume" / "deposit_surface.csv");
  for (const auto& row : surface.rows) {
    r.x.push_back(row[surface.column("x")]);
    r.y.push_back(row[surface.column("y")]);
  }
  return r;
}

Result read_dan(const fs::path& dir) {
  const auto m = load_json(dir / "summary.json").at("metrics");
  Result r;
  r.arrival = number(m["barrier_arrival_time_s"]);
  r.front = number(m["front_s_m"]);
  r.runup_distance = number(m["runup_final"]["distance_on_barrier_m"]);
  r.runup_elevation = number(m["runup_final"]["elevation_m"]);
  r.tail = number(m["tail_s_m"]);
  const auto front = io::read_csv(dir / "front.csv");
  for (const auto& row : front.rows) {
    r.t.push_back(row[front.column("time")]);
    r.s.push_back(row[front.column("s")]);
  }
  const auto deposit = io::read_csv(dir / "deposit.csv");
  for (const auto& row : deposit.rows) {
    r.x.push_back(row[deposit.column("x_surface")]);
    r.y.push_back(row[deposit.column("y_surface")]);
  }
  return r;
}

void write_pairs(const fs::path& path, const char* a, const char* b, const std::vector<double>& u,
                 const std::vector<double>& v) {
  io::CsvSeries csv(path, {a, b}, false);
  for (std::size_t k = 0; k < u.size(); ++k) csv.row({u[k], v[k]});
  csv.flush();
}

std::string cell(double v) { return std::isnan(v) ? "-" : fmt::format("{:.3f}", v); }
nlohmann::json json_number(double v) {
  return std::isnan(v) ? nlohmann::json() : nlohmann::json(v);
}

}  // namespace

int compare_command(const CompareOptions& given) {
  CompareOptions opt = given;
  opt.file = resolve_scenario(given.file);
  const auto file = io::read_compare_file(opt.file);
  std::vector<std::string> methods = opt.methods;
  if (methods.empty()) {
    for (const char* m : io::kCompareMethods) {
      if (file.methods.count(m)) methods.push_back(m);
    }
  }
  // Everything is checked before the first run: known methods, one flume for all.
  std::vector<geometry::FlumeGeometry> flumes;
  for (const auto& m : methods) {
    if (!file.methods.count(m))
      throw InputError(fmt::format("{}: [methods] has no '{}' (--methods)", opt.file, m));
    flumes.push_back(flume_of(m, file.methods.at(m)));
    if (!same_flume(flumes.front(), flumes.back()))
      throw InputError(
          fmt::format("{}: the {} and {} scenarios describe different flumes "
                      "(beta, R, L*, barrier length must agree)",
                      opt.file, methods.front(), m));
  }
  const fs::path out =
      opt.out.empty() ? fs::path("runs") / ("compare-" + file.name) : fs::path(opt.out);
  // Held to the end: the lock, then the record of what talus wrote there.
  const auto folder = run::OutputFolder::claim(out, opt.force);

  std::vector<Result> results;
  for (const auto& m : methods) {
    if (!opt.quiet) fmt::print(stderr, "talus compare: running {} ({})\n", m, file.methods.at(m));
    RunOptions run;
    run.file = file.methods.at(m);
    run.out = (out / m).string();
    run.threads = opt.threads;
    run.quiet = true;
    run_command(run);
    // The depth-averaged models write the same flume files and figures.
    const bool depth_averaged = m == "dan" || m == "fv2d" || m == "two_phase";
    results.push_back(depth_averaged ? read_dan(out / m) : read_dem(out / m));
  }

  fs::create_directories(out / "compare");
  const auto& g = flumes.front();
  {
    io::CsvSeries path(out / "compare" / "path.csv", {"s", "x", "y"}, false);
    const double s0 = g.chute_start_s(), s1 = g.path_end_s();
    for (int k = 0; k <= 2000; ++k) {
      const double s = s0 + (s1 - s0) * k / 2000;
      const auto p = g.point_at(s);
      path.row({s, p.x(), p.y()});
    }
    path.flush();
  }
  std::string md = fmt::format(
      "# {}: {}\n\nFlume beta = {:.1f} deg, R = {} m; s along the path from the gate foot "
      "(the barrier starts at s = {:.3f} m). Tails: DEM where the deposit is thicker than 3 grain "
      "diameters, MPM 3 point spacings, DAN at the first block and fv2d / two_phase at the "
      "first column with 10 % of the deepest depth.\n\n"
      "| method | arrival at barrier [s] | final front s [m] | run-up along barrier [m] | "
      "run-up elevation [m] | deposit tail s [m] |\n|---|---|---|---|---|---|\n",
      file.name, file.description, rad2deg(g.beta), g.radius, g.arc_end_s());
  nlohmann::json j = {{"name", file.name}, {"barrier_start_s", g.arc_end_s()}};
  for (std::size_t k = 0; k < methods.size(); ++k) {
    const auto& r = results[k];
    md += fmt::format("| {} | {} | {} | {} | {} | {} |\n", methods[k], cell(r.arrival),
                      cell(r.front), cell(r.runup_distance), cell(r.runup_elevation), cell(r.tail));
    j["methods"][methods[k]] = {{"scenario", file.methods.at(methods[k])},
                                {"arrival_at_barrier_s", json_number(r.arrival)},
                                {"final_front_s_m", json_number(r.front)},
                                {"runup_along_barrier_m", json_number(r.runup_distance)},
                                {"runup_elevation_m", json_number(r.runup_elevation)},
                                {"deposit_tail_s_m", json_number(r.tail)}};
    write_pairs(out / "compare" / ("front_" + methods[k] + ".csv"), "time", "s", r.t, r.s);
    write_pairs(out / "compare" / ("surface_" + methods[k] + ".csv"), "x", "y", r.x, r.y);
  }
  std::ofstream(out / "comparison.md") << md;
  std::ofstream(out / "comparison.json") << j.dump(2) << "\n";
  fmt::print("{}\nreport: {}\n", md, (out / "comparison.md").string());
  return 0;
}

}  // namespace talus::app
