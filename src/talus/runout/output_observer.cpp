#include "talus/runout/output_observer.hpp"

#include <cmath>

namespace talus::runout {

DanOutputs::DanOutputs(std::filesystem::path dir, bool resume, double resume_time)
    : path_written_(resume), dir_(std::move(dir)) {
  if (resume) io::CsvSeries::truncate_after(dir_ / "series.csv", resume_time);
  series_ = std::make_unique<io::CsvSeries>(
      dir_ / "series.csv",
      std::vector<std::string>{"time", "front_s", "tail_s", "front_x", "front_y", "max_speed",
                               "max_depth", "kinetic_energy", "momentum", "mass", "volume"},
      resume);
  blocks_ = std::make_unique<io::PvdSeries>(dir_, "blocks", resume);
  if (resume) blocks_->truncate_after(resume_time);
}

void DanOutputs::on_series(const DanModel& m) {
  if (!path_written_) write_path_csv(dir_, m.path()), path_written_ = true;
  const auto& b = m.blocks();
  const Vec2 front = m.path().point(b.s.back());
  double max_depth = 0;
  for (std::size_t j = 0; j + 1 < m.size(); ++j) max_depth = std::max(max_depth, m.block_depth(j));
  series_->row({b.time, b.s.back(), b.s.front(), front.x(), front.y(), m.max_speed(), max_depth,
                m.kinetic_energy(), m.momentum(), m.total_mass(), m.deformed_volume()});
}

void DanOutputs::on_snapshot(const DanModel& m) {
  io::ParticleFrame f;
  const auto& b = m.blocks();
  auto& depth = f.extra_scalars["depth"];
  auto& s_out = f.extra_scalars["s"];
  for (std::size_t i = 0; i < m.size(); ++i) {
    const Vec2 p = m.path().point(b.s[i]);
    const double a = m.path().angle(b.s[i]);
    f.position.emplace_back(p.x(), p.y(), 0.0);
    f.velocity.emplace_back(b.v[i] * std::cos(a), b.v[i] * std::sin(a), 0.0);
    f.angular_velocity.emplace_back(0.0, 0.0, 0.0);
    f.radius.push_back(m.boundary_depth(i));
    f.id.push_back(static_cast<int64_t>(i));
    f.material.push_back(0);
    f.contacts.push_back(0);
    depth.push_back(m.boundary_depth(i));
    s_out.push_back(b.s[i]);
  }
  blocks_->add(b.time, f);
  series_->flush();
}

void write_path_csv(const std::filesystem::path& dir, const RunoutPath& path) {
  // 5 mm along the path: smooth enough for a plot of the bed, small on disk.
  auto out = io::CsvSeries::whole(dir / "path.csv", {"s", "x", "y", "width"});
  const double s0 = path.s_begin(), s1 = path.s_end();
  const auto n = static_cast<std::size_t>(std::ceil((s1 - s0) / 0.005));
  for (std::size_t k = 0; k <= n; ++k) {
    const double s = s0 + (s1 - s0) * static_cast<double>(k) / static_cast<double>(n);
    const Vec2 p = path.point(s);
    out.row({s, p.x(), p.y(), path.width(s)});
  }
  out.close();
}

void write_path_results(const std::filesystem::path& dir, const RunoutResults& r) {
  auto deposit = io::CsvSeries::whole(dir / "deposit.csv",
                                      {"s", "x_bed", "y_bed", "depth", "x_surface", "y_surface"});
  for (const auto& p : r.deposit)
    deposit.row({p.s, p.x_bed, p.y_bed, p.depth, p.x_surface, p.y_surface});
  deposit.close();
  auto front = io::CsvSeries::whole(dir / "front.csv", {"time", "s", "x", "y"});
  for (const auto& f : r.front) front.row({f.time, f.s, f.x, f.y});
  front.close();
}

void DanOutputs::flush() { series_->flush(); }

void DanOutputs::write_results(const RunoutResults& r) const {
  write_path_results(dir_, r);
  series_->flush();
}

}  // namespace talus::runout
