#include "talus/analysis/mpm_flume_observer.hpp"

#include <cmath>

#include "talus/analysis/dam_break.hpp"
#include "talus/io/archive.hpp"
#include "talus/io/csv_reader.hpp"

namespace talus::analysis {

namespace {
const std::vector<std::string> kFrontColumns = {"time",    "front_s",      "front_x", "front_y",
                                                "runup_s", "runup_height", "on_chute"};
}  // namespace

MpmFlumeObserver::MpmFlumeObserver(std::filesystem::path out, const mpm::MpmFlumeParams& params,
                                   const mpm::Solver<2>& s, bool resume, double resume_time)
    : dir_(std::move(out) / "flume"),
      geometry_(geometry::make_flume(params.shape)),
      params_(params) {
  std::filesystem::create_directories(dir_);
  double volume = 0.0;
  for (double v : s.particles.volume0) volume += v;
  if (!s.particles.volume0.empty())
    spacing_ = std::sqrt(volume / static_cast<double>(s.particles.size()));
  const auto csv = dir_ / "front.csv";
  if (resume) io::CsvSeries::truncate_after(csv, resume_time);
  front_ = std::make_unique<io::CsvSeries>(csv, kFrontColumns, resume);
}

analysis::Grains MpmFlumeObserver::grains(const mpm::Solver<2>& s) const {
  analysis::Grains g;
  g.x = s.particles.x;
  for (double v : s.particles.volume) g.r.push_back(0.5 * std::sqrt(v));
  return g;
}

void MpmFlumeObserver::on_series(const mpm::Solver<2>& s) {
  const auto f = analysis::measure_front(geometry_, grains(s), params_.measures.front_quantile);
  front_->row({s.time, f.front_s, f.front.x(), f.front.y(), f.runup_s, f.runup_height,
               static_cast<double>(f.on_chute)});
}

void MpmFlumeObserver::on_checkpoint(const mpm::Solver<2>&) { front_->flush(); }

nlohmann::json MpmFlumeObserver::finish(const mpm::Solver<2>& s) {
  front_->flush();
  const analysis::Grains g = grains(s);
  const auto profile = analysis::deposit_profile(geometry_, g, params_.measures.profile_bin);
  {
    auto out =
        io::CsvSeries::whole(dir_ / "deposit_profile.csv",
                             {"s_low", "s_high", "count", "thickness", "surface_x", "surface_y"});
    for (const auto& b : profile)
      out.row({b.s_low, b.s_high, static_cast<double>(b.count), b.thickness, b.surface.x(),
               b.surface.y()});
    out.close();
  }
  {
    // Elevation over x as for the DEM (well defined over the arc too).
    const auto columns = analysis::slope_profile(g, geometry_.barrier_end.x(), 0.01);
    auto out = io::CsvSeries::whole(dir_ / "deposit_surface.csv", {"x", "y"});
    for (std::size_t k = 0; k < columns.x.size(); ++k)
      if (columns.top[k] > 0) out.row({columns.x[k], columns.top[k]});
    out.close();
  }
  // Three point spacings: the MPM's analogue of the DEM's three grain diameters.
  const double tail_thickness =
      params_.measures.tail_thickness > 0 ? params_.measures.tail_thickness : 3.0 * spacing_;
  const double tail = analysis::deposit_tail(profile, tail_thickness);
  int stranded = 0;
  for (const auto& x : g.x) stranded += geometry_.path_coordinate(x) < tail ? 1 : 0;
  const auto last = analysis::measure_front(geometry_, g, params_.measures.front_quantile);

  const auto table = io::read_csv(dir_ / "front.csv");
  const std::size_t t = table.column("time"), fs = table.column("front_s"),
                    rs = table.column("runup_s"), rh = table.column("runup_height");
  double reach_arc = -1.0, reach_barrier = -1.0, max_s = 0.0, max_h = 0.0, max_t = 0.0;
  for (const auto& row : table.rows) {
    if (reach_arc < 0 && row[fs] >= geometry_.chute_end_s()) reach_arc = row[t];
    if (reach_barrier < 0 && row[fs] >= geometry_.arc_end_s()) reach_barrier = row[t];
    if (row[rs] > max_s) max_s = row[rs], max_h = row[rh], max_t = row[t];
  }
  nlohmann::json j;
  j["path"] = {{"chute_end_s", geometry_.chute_end_s()},
               {"arc_end_s", geometry_.arc_end_s()},
               {"path_end_s", geometry_.path_end_s()},
               {"bed_low_y", analysis::bed_low_point(geometry_)}};
  j["front"] = {{"quantile", params_.measures.front_quantile},
                {"reach_arc_time", reach_arc},
                {"reach_barrier_time", reach_barrier},
                {"final_s", last.front_s}};
  j["runup"] = {{"max_s", max_s},
                {"max_height", max_h},
                {"max_time", max_t},
                {"final_s", last.runup_s},
                {"final_height", last.runup_height}};
  double mass = 0.0;
  for (double m : s.particles.mass) mass += m;
  j["deposit"] = {{"tail_s", tail},
                  {"tail_above_chute_end", geometry_.chute_end_s() - tail},
                  {"tail_thickness", tail_thickness},
                  {"stranded", stranded},
                  {"on_chute", last.on_chute},
                  {"points", s.particles.size()},
                  {"weight_per_m", mass * s.gravity().norm()}};
  io::write_file_atomically(dir_ / "summary.json", j.dump(2) + "\n");
  return j;
}

}  // namespace talus::analysis
