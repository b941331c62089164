#include "talus/mpm/output_observer.hpp"

#include <cmath>

#include "talus/io/csv_reader.hpp"
#include "talus/mpm/checkpoint.hpp"

namespace talus::mpm {

template <int D>
MpmOutputs<D>::MpmOutputs(std::filesystem::path dir, std::vector<double> c0, bool resume,
                          double resume_time)
    : dir_(std::move(dir)), c0_(std::move(c0)), resume_(resume), resume_time_(resume_time) {
  std::filesystem::create_directories(dir_);
  const auto csv = dir_ / "series.csv";
  if (resume) {
    io::CsvSeries::truncate_after(csv, resume_time);
    // The values the interrupted run saw, in the order it saw them.
    const auto table = io::read_csv(csv);
    const std::size_t t = table.column("time"), ke = table.column("kinetic_energy"),
                      fx = table.column("front_x"), tp = table.column("top");
    for (const auto& row : table.rows) {
      if (first_) initial_front_x = row[fx], initial_top = row[tp], first_ = false;
      if (row[ke] > peak_kinetic_energy)
        peak_kinetic_energy = row[ke], peak_kinetic_energy_time = row[t];
    }
  }
  series_ = std::make_unique<io::CsvSeries>(
      csv,
      std::vector<std::string>{"time", "step", "time_step", "points", "kinetic_energy",
                               "potential_energy", "front_x", "top", "max_speed", "yielding_points",
                               "cracked_points", "min_c_over_c0"},
      resume);
  particles_ = std::make_unique<io::PvdSeries>(dir_, "particles", resume);
  if (resume) particles_->truncate_after(resume_time);
}

template <int D>
void MpmOutputs<D>::on_checkpoint(const Solver<D>& s) {
  series_->flush();
  if (membranes_) membranes_->flush();
  save_checkpoint(s, checkpoint_path(dir_));
}

template <int D>
double MpmOutputs<D>::c_ratio(const Solver<D>& s, std::size_t p) const {
  const double c0 = c0_[s.particles.material[p]];
  return c0 > 0.0 ? s.particles.state[p].cohesion / c0 : 1.0;
}

template <int D>
MembraneOutputs<D>* MpmOutputs<D>::membranes(const Solver<D>& s) {
  if (!membranes_ && !s.membranes.empty())
    membranes_ = std::make_unique<MembraneOutputs<D>>(dir_, s.membranes, resume_, resume_time_);
  return membranes_.get();
}

template <int D>
void MpmOutputs<D>::on_series(const Solver<D>& s) {
  if (auto* m = membranes(s)) m->on_series(s.time, s.membranes);
  const auto& p = s.particles;
  const double ke = kinetic_energy(p);
  double max_speed = 0.0, min_ratio = 1.0;
  int yielding = 0, cracked = 0;
  for (std::size_t i = 0; i < p.size(); ++i) {
    max_speed = std::max(max_speed, p.v[i].norm());
    yielding += p.state[i].yielding;
    const double r = c_ratio(s, i);
    cracked += r < 1.0;
    min_ratio = std::min(min_ratio, r);
  }
  const double fx = front_x(p), tp = top(p, s.gravity());
  if (first_) {
    initial_front_x = fx;
    initial_top = tp;
    first_ = false;
  }
  if (ke > peak_kinetic_energy) {
    peak_kinetic_energy = ke;
    peak_kinetic_energy_time = s.time;
  }
  series_->row({s.time, static_cast<double>(s.steps), s.last_dt, static_cast<double>(p.size()), ke,
                potential_energy(p, s.gravity()), fx, tp, max_speed, static_cast<double>(yielding),
                static_cast<double>(cracked), min_ratio});
}

template <int D>
void MpmOutputs<D>::on_snapshot(const Solver<D>& s) {
  const auto& p = s.particles;
  const std::size_t n = p.size();
  io::ParticleFrame f;
  std::vector<double> sxx(n), syy(n), szz(n), sxy(n), sxz(n), syz(n), pressure(n), q(n), eps(n),
      ratio(n), volume(n);
  for (std::size_t i = 0; i < n; ++i) {
    f.position.push_back(Space<D>::to3(p.x[i]));
    f.velocity.push_back(Space<D>::to3(p.v[i]));
    f.angular_velocity.push_back(Vec3::Zero());
    // Half the point spacing, so that glyphs of this radius tile the body.
    f.radius.push_back(0.5 * std::pow(p.volume[i], 1.0 / D));
    f.id.push_back(static_cast<int64_t>(i));
    f.material.push_back(p.material[i]);
    f.contacts.push_back(0);
    const Mat3& st = p.state[i].stress;
    sxx[i] = st(0, 0), syy[i] = st(1, 1), szz[i] = st(2, 2), sxy[i] = st(0, 1);
    sxz[i] = st(0, 2), syz[i] = st(1, 2);
    pressure[i] = -st.trace() / 3.0;
    q[i] = von_mises(st);
    eps[i] = p.state[i].plastic_strain;
    ratio[i] = c_ratio(s, i);
    volume[i] = p.volume[i];
  }
  f.extra_scalars = {{"stress_xx", sxx},      {"stress_yy", syy},     {"stress_zz", szz},
                     {"stress_xy", sxy},      {"pressure", pressure}, {"von_mises", q},
                     {"plastic_strain", eps}, {"c_over_c0", ratio},   {"volume", volume}};
  if (D == 3) {
    f.extra_scalars["stress_xz"] = sxz;
    f.extra_scalars["stress_yz"] = syz;
  }
  particles_->add(s.time, f);
  if (auto* m = membranes(s)) m->on_snapshot(s.time, s.membranes);
  if (s.rigid_bodies.empty()) return;
  if (!boundary_) {
    boundary_ = std::make_unique<io::PvdSeries>(dir_, "boundary", resume_);
    if (resume_) boundary_->truncate_after(resume_time_);
  }
  io::ParticleFrame b;
  for (std::size_t r = 0; r < s.rigid_bodies.size(); ++r) {
    const auto& body = s.rigid_bodies[r];
    for (std::size_t i = 0; i < body.x.size(); ++i) {
      b.position.push_back(Space<D>::to3(body.x[i]));
      b.velocity.push_back(Space<D>::to3(body.velocity_at(body.x[i], s.time, s.last_dt)));
      b.angular_velocity.push_back(Vec3::Zero());
      b.radius.push_back(0.5 * std::pow(body.weight[i], 1.0 / D));
      b.id.push_back(static_cast<int64_t>(b.id.size()));
      b.material.push_back(static_cast<int>(r));
      b.contacts.push_back(0);
    }
  }
  boundary_->add(s.time, b);
}

template <int D>
void MpmOutputs<D>::flush() {
  series_->flush();
  if (membranes_) membranes_->flush();
}

template class MpmOutputs<2>;
template class MpmOutputs<3>;

}  // namespace talus::mpm
