#include "talus/analysis/triaxial.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "talus/core/error.hpp"
#include "talus/io/csv_reader.hpp"

namespace talus::analysis {

namespace {

template <class List>
int index_of(const List& list, const std::string& name, const char* what) {
  for (std::size_t k = 0; k < list.size(); ++k)
    if (list[k].name == name) return static_cast<int>(k);
  throw InputError(fmt::format("[triaxial]: no {} named '{}'", what, name));
}

}  // namespace

TriaxialSetup make_triaxial_setup(const dem::DemScenario& sc, const dem::DemSystem<3>& s) {
  if (!sc.triaxial) throw InputError("[triaxial]: missing");
  const auto& p = *sc.triaxial;
  TriaxialSetup t;
  t.bottom = index_of(s.walls, p.bottom_plate, "wall");
  t.top = index_of(s.walls, p.top_plate, "wall");
  t.membrane = index_of(s.membranes, p.membrane, "membrane");
  const auto& spec = sc.membranes[index_of(sc.membranes, p.membrane, "membrane")];
  t.confining_pressure = -spec.pressure;
  t.area = M_PI * spec.radius * spec.radius;
  t.servo_stop = std::max(s.walls[t.bottom].motion.servo_stop, s.walls[t.top].motion.servo_stop);
  return t;
}

double plate_gap(const dem::DemSystem<3>& s, const TriaxialSetup& t) {
  const auto& b = s.walls[t.bottom];
  const auto& top = s.walls[t.top];
  return (top.current[0].p0 - b.current[0].p0).dot(b.servo_normal);
}

double gap_at_servo_stop(const dem::DemSystem<3>& s, const TriaxialSetup& t) {
  const auto& b = s.walls[t.bottom];
  const auto& top = s.walls[t.top];
  const Vec3 d = top.reference[0].p0 + top.displacement(t.servo_stop) -
                 (b.reference[0].p0 + b.displacement(t.servo_stop));
  return d.dot(b.servo_normal);
}

double membrane_mean_radius(const dem::DemSystem<3>& s, const TriaxialSetup& t, const Vec3& axis) {
  const auto& x = s.membranes[t.membrane].body.x;
  double sum = 0.0;
  for (const Vec3& q : x) sum += std::hypot(q.x() - axis.x(), q.y() - axis.y());
  return x.empty() ? 0.0 : sum / static_cast<double>(x.size());
}

TriaxialObserver::TriaxialObserver(std::filesystem::path out, const dem::DemScenario& sc,
                                   const dem::DemSystem<3>& s, bool resume, double resume_time)
    : setup_(make_triaxial_setup(sc, s)) {
  const auto& m = s.membranes[setup_.membrane].body;
  axis_ = Vec3::Zero();
  for (const Vec3& q : m.anchor) axis_ += q;
  if (!m.anchor.empty()) axis_ /= static_cast<double>(m.anchor.size());
  std::filesystem::create_directories(out);
  if (resume) {
    io::CsvSeries::truncate_after(out / "triaxial.csv", resume_time);
    restore(out, s);
  }
  csv_ = std::make_unique<io::CsvSeries>(
      out / "triaxial.csv",
      std::vector<std::string>{"time", "phase", "gap", "eps", "p_bottom", "p_top", "p_plates",
                               "p_confining", "sigma_d", "membrane_radius"},
      resume);
}

void TriaxialObserver::restore(const std::filesystem::path& out, const dem::DemSystem<3>& s) {
  const io::CsvTable tri = io::read_csv(out / "triaxial.csv");
  const io::CsvTable series = io::read_csv(out / "series.csv");
  if (tri.rows.empty() || series.rows.empty() ||
      tri.rows.back()[0] != series.rows.back()[series.column("time")])
    throw RunError(
        fmt::format("{}: cannot resume the triaxial record: it does not end with "
                    "series.csv at the checkpoint",
                    (out / "triaxial.csv").string()));
  const auto& last = series.rows.back();
  const int plates[2] = {setup_.bottom, setup_.top};
  for (int k = 0; k < 2; ++k)
    for (int d = 0; d < 3; ++d)
      last_impulse_[k][d] = last[series.column(s.walls[plates[k]].name + "_impulse_" + "xyz"[d])];
  last_time_ = tri.rows.back()[0];
  const std::size_t phase = tri.column("phase"), eps = tri.column("eps"),
                    p_plates = tri.column("p_plates"), sigma = tri.column("sigma_d");
  // The same updates as on_series, in the same order.
  for (const auto& row : tri.rows) {
    if (row[phase] != 1.0) continue;
    if (h0_ < 0) {
      h0_ = gap_at_servo_stop(s, setup_);
      p_at_h0_ = row[p_plates];
    }
    if (row[sigma] > peak_sigma_) peak_sigma_ = row[sigma], peak_eps_ = row[eps];
    last_eps_ = row[eps];
  }
}

void TriaxialObserver::on_checkpoint(const dem::DemRun<3>&) { csv_->flush(); }

void TriaxialObserver::on_series(const dem::DemRun<3>& run) {
  const auto& s = run.system;
  const double dt = s.time - last_time_;
  double p[2] = {0.0, 0.0};
  const int plates[2] = {setup_.bottom, setup_.top};
  for (int k = 0; k < 2; ++k) {
    const auto& w = s.walls[plates[k]];
    // The mean force over the interval (impulse difference): one step's
    // force would show the contact chatter; the first row has only that.
    const Vec3 f = dt > 0 ? Vec3((w.impulse - last_impulse_[k]) / dt) : w.force;
    p[k] = -f.dot(w.servo_normal) / setup_.area;
    last_impulse_[k] = w.impulse;
  }
  last_time_ = s.time;
  const double h = plate_gap(s, setup_);
  const bool loading = s.time >= setup_.servo_stop;
  const double p_plates = 0.5 * (p[0] + p[1]);
  const double sigma = p_plates - setup_.confining_pressure;
  double eps = 0.0;
  if (loading) {
    if (h0_ < 0) {
      h0_ = gap_at_servo_stop(s, setup_);
      p_at_h0_ = p_plates;
    }
    eps = axial_strain(h0_, h);
    if (sigma > peak_sigma_) peak_sigma_ = sigma, peak_eps_ = eps;
    last_eps_ = eps;
  }
  csv_->row({s.time, loading ? 1.0 : 0.0, h, eps, p[0], p[1], p_plates, setup_.confining_pressure,
             sigma, membrane_mean_radius(s, setup_, axis_)});
}

nlohmann::json TriaxialObserver::finish() const {
  nlohmann::json j;
  j["confining_pressure"] = setup_.confining_pressure;
  j["servo_stop"] = setup_.servo_stop;
  if (h0_ > 0) {
    j["h0"] = h0_;
    j["p_plates_at_h0"] = p_at_h0_;
    j["peak_deviator_stress"] = peak_sigma_;
    j["eps_at_peak"] = peak_eps_;
    j["final_eps"] = last_eps_;
  }
  return j;
}

}  // namespace talus::analysis
