#include "analyse.hpp"

#include <fmt/core.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>

#include "talus/analysis/coarse_grain.hpp"
#include "talus/core/error.hpp"
#include "talus/io/csv_writer.hpp"
#include "talus/io/image_writer.hpp"
#include "talus/io/snapshot_reader.hpp"

namespace fs = std::filesystem;

namespace talus::app {

namespace {

analysis::ParticleSample sample_of(const io::SnapshotEntry& e, const std::vector<double>& density,
                                   const fs::path& scenario) {
  const io::ParticleFrame f = io::read_particle_vtu(e.file);
  analysis::ParticleSample s;
  s.time = e.time;
  s.position = f.position;
  s.radius = f.radius;
  s.id.assign(f.id.begin(), f.id.end());
  for (int m : f.material) {
    if (m < 0 || m >= static_cast<int>(density.size()) || !(density[m] > 0))
      throw InputError(fmt::format("{}: material {} of the snapshot {} has no density",
                                   scenario.string(), m, e.file.string()));
    s.density.push_back(density[m]);
  }
  return s;
}

// Pairs of snapshots one period apart (to 1 % of the period: snapshots fall on time steps).
std::vector<std::pair<std::size_t, std::size_t>> period_pairs(
    const std::vector<io::SnapshotEntry>& e, const CoarseGrainOptions& o) {
  const double tol = 0.01 * o.period;
  const double end = o.to < 0 ? std::numeric_limits<double>::infinity() : o.to + tol;
  std::vector<std::pair<std::size_t, std::size_t>> pairs;
  for (std::size_t a = 0; a < e.size(); ++a) {
    if (e[a].time < o.from - tol) continue;
    for (std::size_t b = a + 1; b < e.size(); ++b)
      if (std::abs(e[b].time - e[a].time - o.period) <= tol && e[b].time <= end) {
        pairs.emplace_back(a, b);
        break;
      }
  }
  return pairs;
}

analysis::CellGrid grid_of(const CoarseGrainOptions& o, const analysis::ParticleSample& s) {
  analysis::CellGrid g;
  if (o.cells.size() != 3 || *std::min_element(o.cells.begin(), o.cells.end()) < 1)
    throw InputError("--cells: expected three positive integers NX,NY,NZ");
  g.cells = {o.cells[0], o.cells[1], o.cells[2]};
  if (!o.box.empty()) {
    if (o.box.size() != 6) throw InputError("--box: expected xmin,ymin,zmin,xmax,ymax,zmax");
    g.lo = Vec3(o.box[0], o.box[1], o.box[2]);
    g.hi = Vec3(o.box[3], o.box[4], o.box[5]);
    if (!(g.hi.array() > g.lo.array()).all()) throw InputError("--box: need max > min");
    return g;
  }
  g.lo = Vec3::Constant(std::numeric_limits<double>::infinity());
  g.hi = -g.lo;
  for (std::size_t n = 0; n < s.position.size(); ++n) {
    g.lo = g.lo.cwiseMin(s.position[n] - Vec3::Constant(s.radius[n]));
    g.hi = g.hi.cwiseMax(s.position[n] + Vec3::Constant(s.radius[n]));
  }
  return g;
}

void write_field_csv(const fs::path& path, const analysis::CoarseField& f) {
  io::CsvSeries csv(path, {"x", "y", "z", "solid_fraction", "mass_density", "vx", "vy", "vz"},
                    false);
  const auto v = f.velocity();
  const auto& g = f.grid;
  for (int k = 0; k < g.cells[2]; ++k)
    for (int j = 0; j < g.cells[1]; ++j)
      for (int i = 0; i < g.cells[0]; ++i) {
        const Vec3 c = g.cell_centre(i, j, k);
        const auto a = g.index(i, j, k);
        csv.row({c.x(), c.y(), c.z(), f.solid_fraction[a], f.mass_density[a], v[a].x(), v[a].y(),
                 v[a].z()});
      }
  csv.flush();
}

void write_radial_csv(const fs::path& path, const analysis::RadialField& r) {
  io::CsvSeries csv(path, {"r", "z", "solid_fraction", "v_r", "v_z"}, false);
  for (std::size_t b = 0; b < r.r.size(); ++b)
    csv.row({r.r[b], r.z[b], r.solid_fraction[b], r.v_r[b], r.v_z[b]});
  csv.flush();
}

}  // namespace

int coarse_grain_command(const CoarseGrainOptions& o) {
  const fs::path run(o.run_dir);
  if (!(o.period > 0)) throw InputError("--period: expected a positive number of seconds");
  if (!(o.axis_width > 0)) throw InputError("--axis-width: expected a positive length");
  const fs::path pvd = run / "particles.pvd", scenario = run / "scenario.toml";
  if (!fs::exists(pvd)) throw InputError(pvd.string() + ": no particle snapshots in this folder");
  const auto entries = io::read_pvd(pvd);
  const auto density = io::read_material_densities(scenario);
  const auto pairs = period_pairs(entries, o);
  if (pairs.empty())
    throw InputError(
        fmt::format("{}: no two snapshots {} s apart from t = {} on ({} snapshots; set "
                    "output.snapshot_interval to the period or a fraction of it)",
                    pvd.string(), o.period, o.from, entries.size()));

  std::map<std::size_t, analysis::ParticleSample> cache;  // each snapshot read once
  auto sample = [&](std::size_t k) -> const analysis::ParticleSample& {
    auto it = cache.find(k);
    if (it == cache.end()) it = cache.emplace(k, sample_of(entries[k], density, scenario)).first;
    return it->second;
  };
  const analysis::CellGrid grid = grid_of(o, sample(pairs.front().first));
  const Vec3 centre = 0.5 * (grid.lo + grid.hi);
  analysis::CellGrid column;  // the column around the axis as one cell
  column.lo = Vec3(centre.x() - 0.5 * o.axis_width, centre.y() - 0.5 * o.axis_width, grid.lo.z());
  column.hi = Vec3(centre.x() + 0.5 * o.axis_width, centre.y() + 0.5 * o.axis_width, grid.hi.z());
  // The column's lower and upper halves: symmetric four-cell convection moves the axis
  // material towards the nearer end (v_z < 0 below, > 0 above), one-directional flow does not.
  analysis::CellGrid lower = column, upper = column;
  lower.hi.z() = upper.lo.z() = centre.z();
  analysis::CoarseGrainer field(grid), axis(column), axis_lower(lower), axis_upper(upper);
  double diameter = 0.0;
  for (const auto& [a, b] : pairs) {
    const auto& first = sample(a);
    const auto& second = sample(b);
    const int matched = field.add_interval(first, second);
    axis.add_interval(first, second);
    axis_lower.add_interval(first, second);
    axis_upper.add_interval(first, second);
    if (!o.quiet)
      fmt::print(stderr, "  interval {:.4f} - {:.4f} s: {} grains\n", first.time, second.time,
                 matched);
    cache.erase(a);  // a snapshot is the first of at most one interval
  }
  {
    const auto& s = sample(pairs.front().first);
    for (double r : s.radius) diameter += 2 * r / s.radius.size();
  }

  const fs::path out = o.out.empty() ? run / "coarse_grain" : fs::path(o.out);
  fs::create_directories(out);
  const auto mean = field.mean();
  write_field_csv(out / "field.csv", mean);
  io::CellImage image;
  image.origin = grid.lo;
  image.spacing = grid.spacing();
  image.cells = grid.cells;
  image.scalars["solid_fraction"] = mean.solid_fraction;
  image.scalars["mass_density"] = mean.mass_density;
  image.vectors["velocity"] = mean.velocity();
  io::write_cell_image(out / "field.vti", image);
  const Vec3 h = grid.spacing();
  const double ring = std::min(h.x(), h.y());
  const int rings = static_cast<int>(
      std::ceil(0.5 * std::min(grid.hi.x() - grid.lo.x(), grid.hi.y() - grid.lo.y()) / ring));
  write_radial_csv(out / "rz.csv", analysis::azimuthal_average(mean, centre, rings, ring));

  const Vec3 v_axis = axis.mean().velocity().front();
  const double frequency = 1.0 / o.period;
  double v_max = 0.0, mass = 0.0, mass_speed = 0.0;  // strength: mass-weighted mean |v|
  const auto velocity = mean.velocity();
  for (std::size_t a = 0; a < velocity.size(); ++a) {
    v_max = std::max(v_max, velocity[a].norm());
    mass += mean.mass_density[a];
    mass_speed += mean.mass_density[a] * velocity[a].norm();
  }
  const double v_mean = mass > 0 ? mass_speed / mass : 0.0;
  nlohmann::json j;
  j["run"] = fs::absolute(run).string();
  j["period"] = o.period;
  j["intervals"] = pairs.size();
  j["first_time"] = entries[pairs.front().first].time;
  j["last_time"] = entries[pairs.back().second].time;
  j["cells"] = grid.cells;
  j["box"] = {grid.lo.x(), grid.lo.y(), grid.lo.z(), grid.hi.x(), grid.hi.y(), grid.hi.z()};
  j["axis"] = {centre.x(), centre.y()};
  j["mean_diameter"] = diameter;
  j["axis_column_width"] = o.axis_width;
  j["axis_velocity"] = {v_axis.x(), v_axis.y(), v_axis.z()};
  // Götz reports convection speeds as v / (f d_mean).
  j["axis_vz_normalised"] = v_axis.z() / (frequency * diameter);
  j["axis_lower_vz_normalised"] = axis_lower.mean().velocity().front().z() / (frequency * diameter);
  j["axis_upper_vz_normalised"] = axis_upper.mean().velocity().front().z() / (frequency * diameter);
  j["max_speed"] = v_max;
  j["max_speed_normalised"] = v_max / (frequency * diameter);
  j["mean_speed"] = v_mean;
  j["mean_speed_normalised"] = v_mean / (frequency * diameter);
  std::ofstream(out / "coarse_grain.json") << j.dump(2) << "\n";
  if (!o.quiet)
    fmt::print(stderr,
               "talus: {} intervals of {} s, {} x {} x {} cells; axis v_z = {:.4g} m/s "
               "({:.4g} f d), max |v| = {:.4g} m/s; results in {}\n",
               pairs.size(), o.period, grid.cells[0], grid.cells[1], grid.cells[2], v_axis.z(),
               v_axis.z() / (frequency * diameter), v_max, out.string());
  if (o.plot) {
    const std::string cmd = fmt::format("/usr/bin/python3 '{}/plots/plot_coarse_grain.py' '{}'",
                                        TALUS_SOURCE_DIR, out.string());
    if (std::system(cmd.c_str()) != 0) throw RunError("plotting failed: " + cmd);
  }
  return 0;
}

}  // namespace talus::app
