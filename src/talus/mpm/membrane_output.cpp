#include "talus/mpm/membrane_output.hpp"

#include <algorithm>
#include <cmath>

#include "talus/io/csv_reader.hpp"

namespace talus::mpm {

template <int D>
std::vector<double> node_tensions(const Membrane<D>& m) {
  const std::size_t n = m.size();
  if (m.model == MembraneModel::York) {
    std::vector<double> t(n);
    for (std::size_t i = 0; i < n; ++i) t[i] = m.tension(i);
    return t;
  }
  std::vector<double> sum(n, 0.0), count(n, 0.0);
  for (std::size_t k = 0; k < m.carriers(); ++k) {
    const double t = m.tension(k);
    auto add = [&](std::size_t i) {
      sum[i] += t;
      count[i] += 1.0;
    };
    if (m.surface()) {
      for (uint32_t i : m.triangles[k]) add(i);
    } else {
      add(k), add((k + 1) % n);
    }
  }
  for (std::size_t i = 0; i < n; ++i) sum[i] = count[i] > 0 ? sum[i] / count[i] : 0.0;
  return sum;
}

template <int D>
MembraneOutputs<D>::MembraneOutputs(const std::filesystem::path& dir,
                                    const std::vector<Membrane<D>>& membranes, bool resume,
                                    double resume_time) {
  std::vector<std::string> columns{"time", "max_tension"};
  for (const auto& m : membranes) {
    columns.push_back(m.name + "_max_tension");
    columns.push_back(m.name + "_mean_tension");
  }
  const auto csv = dir / "membranes.csv";
  if (resume && std::filesystem::exists(csv)) {
    io::CsvSeries::truncate_after(csv, resume_time);
    // The peak as the interrupted run saw it, row by row as in on_series.
    const auto table = io::read_csv(csv);
    const std::size_t t = table.column("time"), mx = table.column("max_tension");
    for (const auto& row : table.rows)
      if (row[mx] > peak_tension) peak_tension = row[mx], peak_tension_time = row[t];
  }
  series_ = std::make_unique<io::CsvSeries>(csv, columns, resume);
  points_ = std::make_unique<io::PvdSeries>(dir, "membranes", resume);
  if (resume) points_->truncate_after(resume_time);
}

template <int D>
void MembraneOutputs<D>::on_series(double time, const std::vector<Membrane<D>>& membranes) {
  std::vector<double> row{time, 0.0};
  for (const auto& m : membranes) {
    const double t = m.max_tension();
    row[1] = std::max(row[1], t);
    row.push_back(t);
    row.push_back(m.mean_tension());
  }
  if (row[1] > peak_tension) {
    peak_tension = row[1];
    peak_tension_time = time;
  }
  series_->row(row);
}

template <int D>
void MembraneOutputs<D>::on_snapshot(double time, const std::vector<Membrane<D>>& membranes) {
  io::ParticleFrame f;
  std::vector<double> tension, strain;
  for (std::size_t b = 0; b < membranes.size(); ++b) {
    const auto& m = membranes[b];
    const auto t = node_tensions(m);
    // Glyph radius: half a node's share of the rest length, or for a surface
    // half the side of a square of its share of the rest area.
    std::vector<double> share(m.size(), 0.0);
    for (std::size_t k = 0; k < m.triangles.size(); ++k)
      for (uint32_t i : m.triangles[k]) share[i] += m.rest_area[k] / 3.0;
    for (std::size_t i = 0; i < m.size(); ++i) {
      f.position.push_back(Space<D>::to3(m.x[i]));
      f.velocity.push_back(Space<D>::to3(m.v[i]));
      f.angular_velocity.push_back(Vec3::Zero());
      f.radius.push_back(m.surface() ? 0.5 * std::sqrt(share[i])
                                     : 0.5 * m.rest_length[std::min(i, m.rest_length.size() - 1)]);
      f.id.push_back(static_cast<int64_t>(f.id.size()));
      f.material.push_back(static_cast<int>(b));
      f.contacts.push_back(0);
      tension.push_back(t[i]);
      strain.push_back(m.stiffness > 0.0 ? t[i] / m.stiffness : 0.0);
    }
  }
  f.extra_scalars = {{"tension", tension}, {"strain", strain}};
  points_->add(time, f);
}

template class MembraneOutputs<2>;
template class MembraneOutputs<3>;
template std::vector<double> node_tensions<2>(const Membrane<2>&);
template std::vector<double> node_tensions<3>(const Membrane<3>&);

}  // namespace talus::mpm
