#include "talus/analysis/flume_observer.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "talus/analysis/dam_break.hpp"
#include "talus/core/error.hpp"
#include "talus/io/archive.hpp"
#include "talus/io/csv_reader.hpp"

namespace talus::analysis {

namespace {

const char* const kParts[3] = {"chute", "arc", "barrier"};

std::vector<std::string> front_columns() {
  std::vector<std::string> c = {"time",    "front_s",      "front_x", "front_y",
                                "runup_s", "runup_height", "on_chute"};
  for (const char* part : kParts) {
    c.push_back(std::string(part) + "_fx");
    c.push_back(std::string(part) + "_fy");
  }
  for (const char* part : kParts) {
    c.push_back(std::string(part) + "_fx_peak");
    c.push_back(std::string(part) + "_fy_peak");
  }
  return c;
}

// Horizontal bands of equal height over the settled mass, 0 at the bottom.
std::vector<int> initial_layers(const dem::Particles<2>& p, int layers) {
  double low = INFINITY, high = -INFINITY;
  int64_t max_id = -1;
  for (std::size_t i = 0; i < p.size(); ++i) {
    low = std::min(low, p.x[i].y());
    high = std::max(high, p.x[i].y());
    max_id = std::max(max_id, p.id[i]);
  }
  std::vector<int> by_id(static_cast<std::size_t>(max_id + 1), 0);
  const double band = (high - low) / layers;
  for (std::size_t i = 0; i < p.size(); ++i) {
    const int k = band > 0 ? static_cast<int>((p.x[i].y() - low) / band) : 0;
    by_id[static_cast<std::size_t>(p.id[i])] = std::clamp(k, 0, layers - 1);
  }
  return by_id;
}

}  // namespace

FlumeObserver::FlumeObserver(std::filesystem::path out, const geometry::FlumeGeometry& geometry,
                             const dem::FlumeParams& params, const dem::DemSystem<2>& system,
                             bool resume, double resume_time)
    : dir_(std::move(out) / "flume"), geometry_(geometry), params_(params) {
  std::filesystem::create_directories(dir_ / "frames");
  for (const char* part : kParts) {
    int index = -1;
    for (std::size_t w = 0; w < system.walls.size(); ++w) {
      if (system.walls[w].name == part) index = static_cast<int>(w);
    }
    wall_index_.push_back(index);
    last_impulse_.push_back(index >= 0 ? system.walls[index].impulse : Vec3::Zero());
  }
  last_time_ = system.time;
  {
    // The bed line, for plots: every millimetre of path.
    auto path = io::CsvSeries::whole(dir_ / "path.csv", {"s", "x", "y"});
    const double s0 = geometry_.chute_start_s(), s1 = geometry_.path_end_s();
    const int n = static_cast<int>(std::ceil((s1 - s0) / 1e-3));
    for (int k = 0; k <= n; ++k) {
      const double s = s0 + (s1 - s0) * k / n;
      const Vec2 x = geometry_.point_at(s);
      path.row({s, x.x(), x.y()});
    }
    path.close();
  }
  const auto layers_csv = dir_ / "layers.csv";
  if (resume) {
    const auto table = io::read_csv(layers_csv);
    for (const auto& row : table.rows) {
      const auto id = static_cast<std::size_t>(row[0]);
      if (layer_by_id_.size() <= id) layer_by_id_.resize(id + 1, 0);
      layer_by_id_[id] = static_cast<int>(row[1]);
    }
    io::CsvSeries::truncate_after(dir_ / "front.csv", resume_time);
  } else {
    layer_by_id_ = initial_layers(system.particles, params.layers);
    auto layers = io::CsvSeries::whole(layers_csv, {"id", "layer"});
    for (std::size_t id = 0; id < layer_by_id_.size(); ++id)
      layers.row({static_cast<double>(id), static_cast<double>(layer_by_id_[id])});
    layers.close();
  }
  front_ = std::make_unique<io::CsvSeries>(dir_ / "front.csv", front_columns(), resume);
}

int FlumeObserver::layer_of(int64_t id) const {
  const auto k = static_cast<std::size_t>(id);
  return k < layer_by_id_.size() ? layer_by_id_[k] : 0;
}

Grains FlumeObserver::grains(const dem::DemSystem<2>& system) const {
  return {system.particles.x, system.particles.r};
}

void FlumeObserver::on_series(const dem::DemRun<2>& run) {
  const auto& s = run.system;
  const FrontSample f = measure_front(geometry_, grains(s), params_.measures.front_quantile);
  std::vector<double> row = {s.time,
                             f.front_s,
                             f.front.x(),
                             f.front.y(),
                             f.runup_s,
                             f.runup_height,
                             static_cast<double>(f.on_chute)};
  const double dt = s.time - last_time_;
  Vec3 peak[3];
  for (std::size_t k = 0; k < 3; ++k) {
    Vec3 mean = Vec3::Zero();
    peak[k] = mean;
    if (wall_index_[k] >= 0) {
      const auto& wall = s.walls[wall_index_[k]];
      // The mean over the interval, from the impulse: a sample of the
      // instantaneous force would only show the contact chatter of one step.
      if (dt > 0) mean = (wall.impulse - last_impulse_[k]) / dt;
      last_impulse_[k] = wall.impulse;
      // And the largest force of a single step in the interval: the peak of
      // a grain's impact that the mean smooths away.
      peak[k] = wall.largest_force(mean);
    }
    row.push_back(mean.x());
    row.push_back(mean.y());
  }
  for (const Vec3& f : peak) {
    row.push_back(f.x());
    row.push_back(f.y());
  }
  last_time_ = s.time;
  front_->row(row);
}

void FlumeObserver::on_snapshot(const dem::DemRun<2>& run) {
  const auto& s = run.system;
  const auto& p = s.particles;
  auto frame = io::CsvSeries::whole(dir_ / "frames" / fmt::format("t_{:07.3f}.csv", s.time),
                                    {"x", "y", "r", "layer"});
  for (std::size_t i = 0; i < p.size(); ++i)
    frame.row({p.x[i].x(), p.x[i].y(), p.r[i], static_cast<double>(layer_of(p.id[i]))});
  frame.close();
}

void FlumeObserver::on_checkpoint(const dem::DemRun<2>&) { front_->flush(); }

void FlumeObserver::add_layers(const dem::DemSystem<2>& system, io::ParticleFrame& frame) const {
  auto& layer = frame.extra_scalars["layer"];
  layer.clear();
  for (int64_t id : system.particles.id) layer.push_back(layer_of(id));
}

nlohmann::json FlumeObserver::finish(const dem::DemRun<2>& run) {
  front_->flush();
  const auto& s = run.system;
  const Grains g = grains(s);
  const auto profile = deposit_profile(geometry_, g, params_.measures.profile_bin);
  {
    auto out =
        io::CsvSeries::whole(dir_ / "deposit_profile.csv",
                             {"s_low", "s_high", "count", "thickness", "surface_x", "surface_y"});
    for (const auto& b : profile) {
      out.row({b.s_low, b.s_high, static_cast<double>(b.count), b.thickness, b.surface.x(),
               b.surface.y()});
    }
    out.close();
  }
  {
    // The surface as elevation over x (the top of the highest grain in each
    // 1 cm column): over the arc the deposit is thicker than R and a profile
    // along the path normals is ill-defined there; this one is not.
    const SlopeProfile columns = slope_profile(g, geometry_.barrier_end.x(), 0.01);
    auto out = io::CsvSeries::whole(dir_ / "deposit_surface.csv", {"x", "y"});
    for (std::size_t k = 0; k < columns.x.size(); ++k) {
      if (columns.top[k] > 0) out.row({columns.x[k], columns.top[k]});
    }
    out.close();
  }
  double mean_diameter = 0.0, weight = 0.0;
  for (std::size_t i = 0; i < s.particles.size(); ++i) {
    mean_diameter += 2.0 * s.particles.r[i];
    weight += s.particles.m[i] * s.gravity.norm();
  }
  if (!s.particles.r.empty()) mean_diameter /= static_cast<double>(s.particles.size());
  const double tail_thickness =
      params_.measures.tail_thickness > 0 ? params_.measures.tail_thickness : 3.0 * mean_diameter;
  const double tail = deposit_tail(profile, tail_thickness);
  int stranded = 0;
  for (const Vec2& x : g.x) stranded += geometry_.path_coordinate(x) < tail ? 1 : 0;
  const FrontSample last = measure_front(geometry_, g, params_.measures.front_quantile);

  const auto table = io::read_csv(dir_ / "front.csv");
  const auto sum = summarise_front_series(geometry_, table.columns, table.rows, 0.1);
  nlohmann::json j;
  j["path"] = {{"chute_end_s", geometry_.chute_end_s()},
               {"arc_end_s", geometry_.arc_end_s()},
               {"path_end_s", geometry_.path_end_s()},
               {"bed_low_y", bed_low_point(geometry_)}};
  j["front"] = {{"quantile", params_.measures.front_quantile},
                {"reach_arc_time", sum.reach_arc_time},
                {"reach_barrier_time", sum.reach_barrier_time},
                {"final_s", last.front_s}};
  j["runup"] = {{"max_s", sum.max_runup_s},
                {"max_height", sum.max_runup_height},
                {"max_time", sum.max_runup_time},
                {"final_s", last.runup_s},
                {"final_height", last.runup_height}};
  j["deposit"] = {{"tail_s", tail},
                  {"tail_above_chute_end", geometry_.chute_end_s() - tail},
                  {"tail_thickness", tail_thickness},
                  {"stranded", stranded},
                  {"on_chute", last.on_chute},
                  {"lost", s.removed},
                  {"particles", s.particles.size()},
                  {"weight_per_m", weight}};
  for (int k = 0; k < 3; ++k) {
    nlohmann::json part;
    for (int c = 0; c < 2; ++c) {
      const std::string axis = c == 0 ? "x" : "y";
      part["peak_f" + axis] = sum.peak[k][c].value;
      part["peak_f" + axis + "_time"] = sum.peak[k][c].time;
      part["impulse_" + axis] = sum.impulse[k][c];
      part["final_f" + axis] = sum.final_force[k][c];
      part["peak_step_f" + axis] = sum.step_peak[k][c].value;
      part["peak_step_f" + axis + "_time"] = sum.step_peak[k][c].time;
    }
    j["forces"][kParts[k]] = part;
  }
  j["forces"]["mean_over"] = "series_interval (from impulses)";
  j["forces"]["final_over"] = 0.1;
  j["forces"]["peak_step_over"] = "every step";
  io::write_file_atomically(dir_ / "summary.json", j.dump(2) + "\n");
  return j;
}

FlumeSeriesSummary summarise_front_series(const geometry::FlumeGeometry& g,
                                          const std::vector<std::string>& columns,
                                          const std::vector<std::vector<double>>& rows,
                                          double settle_window) {
  auto col = [&](const std::string& name) {
    const auto it = std::find(columns.begin(), columns.end(), name);
    if (it == columns.end()) throw RunError("front.csv: no column '" + name + "'");
    return static_cast<std::size_t>(it - columns.begin());
  };
  auto keep_larger = [](FlumeSeriesSummary::Peak& peak, double f, double time) {
    if (std::abs(f) > std::abs(peak.value)) peak = {f, time};
  };
  FlumeSeriesSummary out;
  if (rows.empty()) return out;
  const std::size_t t = col("time"), fs = col("front_s"), rs = col("runup_s"),
                    rh = col("runup_height");
  std::size_t force[3][2], step_peak[3][2];
  for (int k = 0; k < 3; ++k) {
    for (int c = 0; c < 2; ++c) {
      const std::string name = std::string(kParts[k]) + (c == 0 ? "_fx" : "_fy");
      force[k][c] = col(name);
      step_peak[k][c] = col(name + "_peak");
    }
  }
  const double end = rows.back()[t];
  double window = 0.0;
  double previous = rows.front()[t];
  for (const auto& row : rows) {
    if (out.reach_arc_time < 0 && row[fs] >= g.chute_end_s()) out.reach_arc_time = row[t];
    if (out.reach_barrier_time < 0 && row[fs] >= g.arc_end_s()) out.reach_barrier_time = row[t];
    if (row[rs] > out.max_runup_s) {
      out.max_runup_s = row[rs];
      out.max_runup_height = row[rh];
      out.max_runup_time = row[t];
    }
    const double dt = row[t] - previous;
    previous = row[t];
    const bool late = row[t] > end - settle_window;
    if (late) window += dt;
    for (int k = 0; k < 3; ++k) {
      for (int c = 0; c < 2; ++c) {
        const double f = row[force[k][c]];
        keep_larger(out.peak[k][c], f, row[t]);
        keep_larger(out.step_peak[k][c], row[step_peak[k][c]], row[t]);
        out.impulse[k][c] += f * dt;
        if (late) out.final_force[k][c] += f * dt;
      }
    }
  }
  for (auto& part : out.final_force) {
    for (double& f : part) f = window > 0 ? f / window : 0.0;
  }
  return out;
}

}  // namespace talus::analysis
