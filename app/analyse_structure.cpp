#include "analyse_structure.hpp"

#include <fmt/core.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <unordered_map>

#include "talus/analysis/contacts.hpp"
#include "talus/analysis/d2min.hpp"
#include "talus/analysis/rdf.hpp"
#include "talus/analysis/voronoi_packing.hpp"
#include "talus/core/error.hpp"
#include "talus/io/csv_writer.hpp"
#include "talus/io/snapshot_reader.hpp"
#include "talus/io/vtk_writer.hpp"

namespace fs = std::filesystem;

namespace talus::app {

namespace {

struct Run {
  fs::path dir;
  std::vector<io::SnapshotEntry> snapshots;
  int dimension = 3;
};

Run open_run(const StructureOptions& o) {
  Run run{fs::path(o.run_dir), {}, 3};
  const fs::path pvd = run.dir / "particles.pvd";
  if (!fs::exists(pvd)) throw InputError(pvd.string() + ": no particle snapshots in this folder");
  run.snapshots = io::read_pvd(pvd);
  if (run.snapshots.empty()) throw InputError(pvd.string() + ": lists no snapshot");
  run.dimension = io::read_run_dimension(run.dir / "scenario.toml");
  return run;
}

// The snapshot nearest to `time`; a time further than half a snapshot interval outside the
// snapshots' span (or not finite) is refused, naming the option.
std::size_t snapshot_at(const Run& run, double time, const char* option) {
  const auto& s = run.snapshots;
  auto refuse = [&] {
    return InputError(
        fmt::format("{} {}: no snapshot near that time in {} ({} snapshots, t = {:.6g} "
                    "to {:.6g} s)",
                    option, time, (run.dir / "particles.pvd").string(), s.size(), s.front().time,
                    s.back().time));
  };
  if (!std::isfinite(time)) throw refuse();
  std::size_t best = 0;
  for (std::size_t k = 1; k < s.size(); ++k)
    if (std::abs(s[k].time - time) < std::abs(s[best].time - time)) best = k;
  const double tol =
      s.size() > 1 ? 0.5 * std::max(s[1].time - s[0].time, s.back().time - s[s.size() - 2].time)
                   : 1e-9 * std::max(1.0, std::abs(s[0].time));
  if (time < s.front().time - tol || time > s.back().time + tol) throw refuse();
  return best;
}

// The snapshot a `--time` option names: the last one when the option is not given (NaN).
const io::SnapshotEntry& snapshot_of_time_option(const Run& run, double time) {
  const double t = std::isnan(time) ? run.snapshots.back().time : time;
  return run.snapshots[snapshot_at(run, t, "--time")];
}

// A snapshot with the checks the analyses need (finite positions, positive radii).
io::ParticleFrame read_frame(const io::SnapshotEntry& e) {
  io::ParticleFrame f = io::read_particle_vtu(e.file);
  for (std::size_t i = 0; i < f.position.size(); ++i)
    if (!f.position[i].allFinite() || !(f.radius[i] > 0) || !std::isfinite(f.radius[i]))
      throw InputError(
          fmt::format("{}: grain {} has a position that is not finite or a radius "
                      "that is not positive",
                      e.file.string(), f.id[i]));
  if (f.position.empty()) throw InputError(e.file.string() + ": no grains in this snapshot");
  return f;
}

double mean_diameter(const io::ParticleFrame& f) {
  double d = 0.0;
  for (double r : f.radius) d += 2 * r / f.radius.size();
  return d;
}

fs::path output_dir(const StructureOptions& o, const Run& run) {
  const fs::path out = o.out.empty() ? run.dir / "analysis" : fs::path(o.out);
  fs::create_directories(out);
  return out;
}

void write_json(const fs::path& path, const nlohmann::json& j) {
  std::ofstream file(path);
  file << j.dump(2) << "\n";
  if (!file) throw RunError("cannot write " + path.string());
}

}  // namespace

int contacts_command(const ContactsOptions& o) {
  const Run run = open_run(o);
  if (!(o.from <= o.to)) throw InputError("--from: expected a time at or before --to");
  if (!std::isfinite(o.gap)) throw InputError("--gap: expected a finite length");
  const int threshold = o.min_contacts < 0 ? run.dimension + 1 : o.min_contacts;
  const double eps = 1e-9 * std::max(1.0, std::abs(run.snapshots.back().time));
  std::vector<std::vector<double>> rows;
  for (const auto& e : run.snapshots) {
    if (e.time < o.from - eps || e.time > o.to + eps) continue;
    const io::ParticleFrame f = read_frame(e);
    const auto z = analysis::contact_number(f.position, f.radius, threshold, o.gap);
    double recorded = std::numeric_limits<double>::quiet_NaN();
    if (!f.contacts.empty()) {
      recorded = 0.0;
      for (int c : f.contacts) recorded += static_cast<double>(c) / f.contacts.size();
    }
    rows.push_back({e.time, static_cast<double>(z.grains), static_cast<double>(z.contacts), z.z,
                    static_cast<double>(z.rattlers), z.z_no_rattlers, recorded});
  }
  if (rows.empty())
    throw InputError(
        fmt::format("--from {} --to {}: no snapshot in that interval (t = {:.6g} to {:.6g} s)",
                    o.from, o.to, run.snapshots.front().time, run.snapshots.back().time));
  const fs::path out = output_dir(o, run);
  io::CsvSeries csv(out / "contacts.csv",
                    {"time", "grains", "contacts", "z", "rattlers", "z_no_rattlers", "z_snapshot"},
                    false);
  for (const auto& r : rows) csv.row(r);
  csv.flush();
  if (!o.quiet)
    fmt::print(stderr,
               "talus: {} snapshots, z = {:.4g} at t = {:.6g} s ({:.4g} without {} rattlers); {}\n",
               rows.size(), rows.back()[3], rows.back()[0], rows.back()[5], rows.back()[4],
               (out / "contacts.csv").string());
  return 0;
}

int rdf_command(const RdfCommandOptions& o) {
  const Run run = open_run(o);
  const auto& e = snapshot_of_time_option(run, o.time);
  const io::ParticleFrame f = read_frame(e);
  analysis::RdfOptions ro;
  ro.dimension = run.dimension;
  ro.r_max = std::isnan(o.r_max) ? 5 * mean_diameter(f) : o.r_max;
  ro.bins = o.bins;
  if (!std::isnan(o.r_max) && !(o.r_max > 0))
    throw InputError(fmt::format("--rmax: expected a positive length, got {}", o.r_max));
  const analysis::Rdf rdf = analysis::radial_distribution(f.position, f.radius, ro);

  const fs::path out = output_dir(o, run);
  io::CsvSeries csv(out / "rdf.csv", {"r", "g", "coordination"}, false);
  for (std::size_t b = 0; b < rdf.r.size(); ++b) csv.row({rdf.r[b], rdf.g[b], rdf.coordination[b]});
  csv.flush();
  nlohmann::json j;
  j["run"] = fs::absolute(run.dir).string();
  j["time"] = e.time;
  j["snapshot"] = e.file.filename().string();
  j["dimension"] = run.dimension;
  j["r_max"] = ro.r_max;
  j["bins"] = ro.bins;
  j["grains"] = f.position.size();
  j["reference_grains"] = rdf.reference_grains;
  j["density"] = rdf.density;
  j["mean_diameter"] = mean_diameter(f);
  j["box"] = {rdf.lo.x(), rdf.lo.y(), rdf.lo.z(), rdf.hi.x(), rdf.hi.y(), rdf.hi.z()};
  write_json(out / "rdf.json", j);
  if (!o.quiet)
    fmt::print(
        stderr, "talus: g(r) at t = {:.6g} s, {} of {} grains as reference, r_max = {:.4g} m; {}\n",
        e.time, rdf.reference_grains, f.position.size(), ro.r_max, (out / "rdf.csv").string());
  return 0;
}

int d2min_command(const D2minCommandOptions& o) {
  const Run run = open_run(o);
  const std::size_t a =
      snapshot_at(run, std::isnan(o.from) ? run.snapshots.front().time : o.from, "--from");
  const std::size_t b =
      snapshot_at(run, std::isnan(o.to) ? run.snapshots.back().time : o.to, "--to");
  if (!(run.snapshots[b].time > run.snapshots[a].time))
    throw InputError(
        fmt::format("--to: the snapshot (t = {} s) must come after the one of --from "
                    "(t = {} s)",
                    run.snapshots[b].time, run.snapshots[a].time));
  if (o.min_contacts < 0) throw InputError("--min-contacts: expected a count >= 0");
  if (!std::isfinite(o.gap)) throw InputError("--gap: expected a finite length");
  const io::ParticleFrame f0 = read_frame(run.snapshots[a]);
  const io::ParticleFrame f1 = read_frame(run.snapshots[b]);
  // Grains present in both snapshots, matched by id, in the order of the later one.
  std::unordered_map<int64_t, std::size_t> at0;
  for (std::size_t i = 0; i < f0.id.size(); ++i) at0.emplace(f0.id[i], i);
  std::vector<std::size_t> i0, i1;
  for (std::size_t i = 0; i < f1.id.size(); ++i)
    if (const auto it = at0.find(f1.id[i]); it != at0.end())
      i0.push_back(it->second), i1.push_back(i);
  if (i0.empty()) throw InputError("d2min: no grain is in both snapshots");
  std::vector<Vec3> x0, x1;
  std::vector<double> radius;
  for (std::size_t k = 0; k < i0.size(); ++k) {
    x0.push_back(f0.position[i0[k]]);
    x1.push_back(f1.position[i1[k]]);
    radius.push_back(f0.radius[i0[k]]);
  }
  std::vector<char> included;
  if (o.min_contacts > 0) {
    const auto counts = analysis::contact_counts(x0, radius, o.gap);
    for (int c : counts) included.push_back(c >= o.min_contacts);
  }
  analysis::D2minOptions d2o;
  d2o.dimension = run.dimension;
  d2o.cutoff = std::isnan(o.cutoff) ? 2.5 * mean_diameter(f0) : o.cutoff;
  if (!std::isnan(o.cutoff) && !(o.cutoff > 0))
    throw InputError(fmt::format("--cutoff: expected a positive length, got {}", o.cutoff));
  const analysis::D2min d = analysis::non_affine_displacement(x0, x1, radius, d2o, included);
  // C(r) of D_min at the later snapshot's positions, where d2min.csv and the .vtu show the
  // values. Computed before the output folder exists, so a bad bin width writes nothing.
  const bool correlate = !std::isnan(o.correlation);
  analysis::D2minCorrelationOptions co;
  analysis::D2minCorrelation corr;
  if (correlate) {
    co.dimension = run.dimension;
    co.bin_width = o.correlation;
    co.r_max = std::isnan(o.correlation_rmax) ? 5 * d.mean_diameter : o.correlation_rmax;
    if (!std::isnan(o.correlation_rmax) && !(o.correlation_rmax > 0))
      throw InputError(fmt::format("--correlation-rmax: expected a positive length, got {}",
                                   o.correlation_rmax));
    std::vector<double> d_min(d.d_min_norm.size());  // D_min = sqrt(D^2_min / n_i), m
    for (std::size_t k = 0; k < d_min.size(); ++k) d_min[k] = d.d_min_norm[k] * d.mean_diameter;
    corr = analysis::d2min_correlation(x1, d_min, d.mean_diameter, co);
  }

  const fs::path out = output_dir(o, run);
  io::CsvSeries csv(out / "d2min.csv", {"id", "x", "y", "z", "neighbours", "d2min", "d_min_norm"},
                    false);
  for (std::size_t k = 0; k < x1.size(); ++k)
    csv.row({static_cast<double>(f1.id[i1[k]]), x1[k].x(), x1[k].y(), x1[k].z(),
             static_cast<double>(d.neighbours[k]), d.d2min[k], d.d_min_norm[k]});
  csv.flush();
  // The later snapshot's grains (matched ones only) with the values as point data.
  io::ParticleFrame v;
  for (std::size_t i : i1) {
    v.position.push_back(f1.position[i]);
    v.velocity.push_back(f1.velocity[i]);
    v.angular_velocity.push_back(f1.angular_velocity.empty() ? Vec3::Zero()
                                                             : f1.angular_velocity[i]);
    v.radius.push_back(f1.radius[i]);
    v.id.push_back(f1.id[i]);
    v.material.push_back(f1.material[i]);
    v.contacts.push_back(f1.contacts.empty() ? 0 : f1.contacts[i]);
  }
  v.extra_scalars["d2min"] = d.d2min;
  v.extra_scalars["d_min_norm"] = d.d_min_norm;
  v.extra_scalars["neighbours"].assign(d.neighbours.begin(), d.neighbours.end());
  io::PvdSeries(out, "d2min").add(run.snapshots[b].time, v);
  nlohmann::json j;
  j["run"] = fs::absolute(run.dir).string();
  j["from"] = run.snapshots[a].time;
  j["to"] = run.snapshots[b].time;
  j["dimension"] = run.dimension;
  j["cutoff"] = d2o.cutoff;
  j["min_contacts"] = o.min_contacts;
  j["grains"] = x0.size();
  j["evaluated"] = d.evaluated;
  j["mean_diameter"] = d.mean_diameter;
  j["mean_d2min"] = d.mean_d2min;
  j["mean_d_min_norm"] = d.mean_d_min_norm;
  if (correlate) {
    io::CsvSeries cc(out / "d2min_correlation.csv", {"r", "C", "C_over_C0", "grains", "pairs"},
                     false);
    // Row r = 0: C(0) from the grains' own values (no pair), the normalisation of the rest.
    cc.row({0.0, corr.c0, corr.c0 > 0 ? 1.0 : std::numeric_limits<double>::quiet_NaN(),
            static_cast<double>(corr.valued), 0.0});
    for (std::size_t b = 0; b < corr.r.size(); ++b)
      cc.row({corr.r[b], corr.c[b], corr.c_over_c0[b], static_cast<double>(corr.grains[b]),
              static_cast<double>(corr.pairs[b])});
    cc.flush();
    j["correlation"] = {{"bin_width", co.bin_width},
                        {"r_max", corr.r.size() * co.bin_width},
                        {"c0", corr.c0},
                        {"grains", corr.valued}};
  }
  write_json(out / "d2min.json", j);
  if (!o.quiet)
    fmt::print(stderr,
               "talus: D2min from t = {:.6g} to {:.6g} s, {} of {} grains, mean {:.4g} m^2 "
               "(D_min/d = {:.4g}); {}\n",
               run.snapshots[a].time, run.snapshots[b].time, d.evaluated, x0.size(), d.mean_d2min,
               d.mean_d_min_norm, (out / "d2min.csv").string());
  return 0;
}

int packing_command(const PackingOptions& o) {
  const Run run = open_run(o);
  const auto& e = snapshot_of_time_option(run, o.time);
  const io::ParticleFrame f = read_frame(e);
  const analysis::LocalPacking p =
      analysis::voronoi_packing(f.position, f.radius, run.dimension, o.margin);

  const fs::path out = output_dir(o, run);
  io::CsvSeries csv(out / "packing.csv",
                    {"id", "x", "y", "z", "radius", "cell_volume", "phi", "boundary"}, false);
  for (std::size_t i = 0; i < f.position.size(); ++i)
    csv.row({static_cast<double>(f.id[i]), f.position[i].x(), f.position[i].y(), f.position[i].z(),
             f.radius[i], p.cell_volume[i], p.solid_fraction[i],
             static_cast<double>(p.boundary[i])});
  csv.flush();
  nlohmann::json j;
  j["run"] = fs::absolute(run.dir).string();
  j["time"] = e.time;
  j["snapshot"] = e.file.filename().string();
  j["dimension"] = run.dimension;
  j["margin"] = o.margin;
  j["grains"] = f.position.size();
  j["interior_grains"] = p.interior;
  j["mean_phi_interior"] = p.mean_interior;
  j["phi_interior"] = p.overall_interior;
  j["phi_all"] = p.overall_all;
  j["box"] = {p.lo.x(), p.lo.y(), p.lo.z(), p.hi.x(), p.hi.y(), p.hi.z()};
  write_json(out / "packing.json", j);
  if (!o.quiet)
    fmt::print(stderr,
               "talus: Voronoi packing at t = {:.6g} s: mean phi = {:.4g} over {} interior "
               "grains of {}; {}\n",
               e.time, p.mean_interior, p.interior, f.position.size(),
               (out / "packing.csv").string());
  return 0;
}

}  // namespace talus::app
