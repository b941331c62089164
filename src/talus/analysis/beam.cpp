#include "talus/analysis/beam.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "talus/core/error.hpp"

namespace talus::analysis {

BeamFit fit_three_point(std::span<const double> load, std::span<const double> deflection,
                        double span, double width, double height, double poisson_ratio) {
  const std::size_t n = load.size();
  if (n < 2 || deflection.size() != n)
    throw InputError("beam fit: needs two or more (load, deflection) pairs");
  double mf = 0, md = 0;
  for (std::size_t i = 0; i < n; ++i) mf += load[i], md += deflection[i];
  mf /= n;
  md /= n;
  double sff = 0, sfd = 0, sdd = 0;
  for (std::size_t i = 0; i < n; ++i) {
    sff += (load[i] - mf) * (load[i] - mf);
    sfd += (load[i] - mf) * (deflection[i] - md);
    sdd += (deflection[i] - md) * (deflection[i] - md);
  }
  if (!(sff > 0)) throw InputError("beam fit: all loads are equal");
  BeamFit fit;
  fit.slope = sfd / sff;
  fit.intercept = md - fit.slope * mf;
  fit.r2 = sdd > 0 ? sfd * sfd / (sff * sdd) : 1.0;
  if (!(fit.slope > 0))
    throw InputError(fmt::format(
        "beam fit: the deflection does not grow with the load (slope {} m/N)", fit.slope));
  const double inertia = width * height * height * height / 12.0, area = width * height;
  const double compliance =
      span * span * span / (48.0 * inertia) + 3.0 * span * (1.0 + poisson_ratio) / (5.0 * area);
  fit.youngs_modulus = compliance / fit.slope;
  fit.effective_modulus = fit.youngs_modulus / (1.0 - poisson_ratio * poisson_ratio);
  return fit;
}

BeamSection measure_section(const dem::membrane::BeamRig& rig, std::span<const Vec3> x) {
  auto mean = [&](const std::vector<int>& set, int axis) {
    double sum = 0.0;
    for (int i : set) sum += x[i][axis];
    return sum / static_cast<double>(set.size());
  };
  return {dem::membrane::support_span(rig, x), mean(rig.faces[1], 1) - mean(rig.faces[0], 1),
          mean(rig.faces[3], 2) - mean(rig.faces[2], 2)};
}

BeamMembrane find_beam_membrane(const dem::DemScenario& sc, const dem::DemSystem<3>& s) {
  if (!sc.beam) throw InputError("[beam]: missing");
  BeamMembrane b;
  for (std::size_t k = 0; k < s.membranes.size(); ++k)
    if (s.membranes[k].rig) b.index = static_cast<int>(k);
  if (b.index < 0) throw InputError("[beam]: no membrane carries the rig");
  for (const auto& m : sc.membranes)
    if (m.name == sc.beam->membrane) b.rest_size = Vec3(m.size_x, m.size_y, m.size_z);
  return b;
}

double mean_z(const std::vector<int>& set, std::span<const Vec3> x) {
  double z = 0.0;
  for (int i : set) z += x[i].z();
  return z / static_cast<double>(set.size());
}

BeamObserver::BeamObserver(std::filesystem::path out, const dem::DemScenario& sc,
                           const dem::DemSystem<3>& s)
    : out_(std::move(out)) {
  beam_ = find_beam_membrane(sc, s);
  b_ = *sc.beam;
  steps_.resize(2 * b_.load_steps + 1);
  std::filesystem::create_directories(out_);
  csv_ = std::make_unique<io::CsvSeries>(
      out_ / "beam.csv",
      std::vector<std::string>{"time", "step", "load", "bottom_centre_z", "support_reaction_z",
                               "kinetic_energy"},
      false);
}

void BeamObserver::on_series(const dem::DemRun<3>& run) {
  const auto& s = run.system;
  const auto& mb = s.membranes[beam_.index];
  const auto& rig = *mb.rig;
  const double z = mean_z(rig.measured, mb.body.x);
  const int k = b_.step_at(s.time);
  if (k >= 0 && !measured_) {
    measured_ = true;
    section_ = measure_section(rig, mb.body.x);
  }
  if (k >= 0 && k < static_cast<int>(steps_.size()) &&
      s.time - b_.bending_start - k * b_.step_time >= 0.5 * b_.step_time) {
    auto& m = steps_[k];
    ++m.rows;
    m.z += z;
    m.reaction += mb.reaction.z();
  }
  const double ke = dem::kinetic_energy(s.particles) + dem::membrane::kinetic_energy(mb);
  csv_->row({s.time, static_cast<double>(k), b_.load_at(s.time), z, mb.reaction.z(), ke});
}

nlohmann::json BeamObserver::finish() const {
  csv_->flush();
  nlohmann::json j;
  j["mould_end"] = b_.mould_end;
  j["bending_start"] = b_.bending_start;
  j["span"] = section_.span;
  j["width"] = section_.width;
  j["height"] = section_.height;
  const int n = b_.load_steps;
  // Only complete steps count: a run cut short (or a step without a series
  // row in its second half) leaves the table at the last complete one.
  int done = 0;
  while (done < static_cast<int>(steps_.size()) && steps_[done].rows > 0) ++done;
  j["steps_done"] = done;
  if (done == 0) return j;
  const double z0 = steps_[0].z / steps_[0].rows;
  std::vector<double> loads, deflections;
  auto table = io::CsvSeries::whole(out_ / "beam_steps.csv", {"step", "load", "bottom_centre_z",
                                                              "deflection", "support_reaction_z"});
  for (int k = 0; k < done; ++k) {
    const double zk = steps_[k].z / steps_[k].rows, rk = steps_[k].reaction / steps_[k].rows;
    table.row({static_cast<double>(k), b_.step_load(k), zk, z0 - zk, rk});
    loads.push_back(b_.step_load(k));
    deflections.push_back(z0 - zk);
  }
  table.close();
  j["load"] = loads;
  j["deflection"] = deflections;
  if (done > n) {
    j["deflection_at_max_load"] = deflections[n];
    try {
      const BeamFit fit =
          fit_three_point(std::span(loads).first(n + 1), std::span(deflections).first(n + 1),
                          section_.span, section_.width, section_.height, b_.beam_poisson_ratio);
      j["slope_m_per_N"] = fit.slope;
      j["intercept_m"] = fit.intercept;
      j["r2"] = fit.r2;
      j["youngs_modulus"] = fit.youngs_modulus;
      j["effective_modulus"] = fit.effective_modulus;
      // Same line, the rest geometry: the modulus a reader of the source compares.
      const Vec3& nominal = beam_.rest_size;
      const BeamFit rest =
          fit_three_point(std::span(loads).first(n + 1), std::span(deflections).first(n + 1),
                          nominal.x(), nominal.y(), nominal.z(), b_.beam_poisson_ratio);
      j["nominal_size"] = {nominal.x(), nominal.y(), nominal.z()};
      j["youngs_modulus_nominal"] = rest.youngs_modulus;
      j["effective_modulus_nominal"] = rest.effective_modulus;
    } catch (const InputError& e) {
      j["fit_error"] = e.what();  // the run's outputs stay; the summary says why
    }
  }
  // Loading and unloading at the same load: step k and 2n - k.
  double gap = 0.0;
  for (int k = n + 1; k < done; ++k)
    gap = std::max(gap, std::abs(deflections[k] - deflections[2 * n - k]));
  if (done > n + 1) j["largest_hysteresis_gap"] = gap;
  return j;
}

}  // namespace talus::analysis
