#include "talus/analysis/hollow_sphere.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "talus/core/error.hpp"
#include "talus/dem/membrane/forces.hpp"
#include "talus/io/csv_reader.hpp"

namespace talus::analysis {

double continuum_object_pressure(double p_vac, double r_out, double r_obj, double nu) {
  const double x = std::pow(r_out / r_obj, 3);
  return p_vac * 2.0 * (1.0 - x) * (2.0 * nu - 1.0) / (2.0 * (1.0 - 2.0 * nu) + x * (1.0 + nu));
}

namespace {

int membrane_index(const dem::DemSystem<3>& s, const std::string& name) {
  for (std::size_t k = 0; k < s.membranes.size(); ++k)
    if (s.membranes[k].name == name) return static_cast<int>(k);
  throw InputError(fmt::format("[hollow_sphere]: no membrane named '{}'", name));
}

const dem::MembraneSpec& spec_of(const dem::DemScenario& sc, const std::string& name) {
  for (const auto& m : sc.membranes)
    if (m.name == name) return m;
  throw InputError(fmt::format("[hollow_sphere]: no membrane named '{}'", name));
}

}  // namespace

HollowSphereSetup make_hollow_sphere_setup(const dem::DemScenario& sc, const dem::DemSystem<3>& s) {
  if (!sc.hollow_sphere) throw InputError("[hollow_sphere]: missing");
  const auto& p = *sc.hollow_sphere;
  HollowSphereSetup h;
  h.object = membrane_index(s, p.object);
  h.shell = membrane_index(s, p.shell);
  const auto& obj = spec_of(sc, p.object);
  const auto& shell = spec_of(sc, p.shell);
  h.centre = obj.origin;
  h.r_object = obj.core_radius;
  h.r_shell = shell.radius;
  h.p_vac = -shell.pressure;
  h.ramp_end = std::max(obj.pressure_ramp_end, shell.pressure_ramp_end);
  h.poisson_ratio = p.poisson_ratio;
  const auto& m = s.membranes[h.object].body;
  std::vector<Vec3> x(m.x.size()), unit(m.x.size(), Vec3::Zero());
  for (std::size_t i = 0; i < x.size(); ++i)
    x[i] = h.centre + h.r_object * (m.x[i] - h.centre).normalized();
  dem::membrane::add_pressure_forces(m.mesh.triangles, 1.0, x, unit);
  for (std::size_t i = 0; i < x.size(); ++i)
    h.unit_pressure_load += unit[i].dot((x[i] - h.centre).normalized());
  return h;
}

double object_pressure(const dem::DemSystem<3>& s, const HollowSphereSetup& h) {
  const auto& mb = s.membranes[h.object];
  const auto& m = mb.body;
  double load = 0.0;
  for (std::size_t i = 0; i < m.x.size(); ++i)
    if (mb.on_core(m.x[i])) load += std::max(0.0, -m.f[i].dot((m.x[i] - h.centre).normalized()));
  return load / h.unit_pressure_load;
}

double shell_mean_radius(const dem::DemSystem<3>& s, const HollowSphereSetup& h) {
  const auto& x = s.membranes[h.shell].body.x;
  double sum = 0.0;
  for (const Vec3& q : x) sum += (q - h.centre).norm();
  return x.empty() ? 0.0 : sum / static_cast<double>(x.size());
}

HollowSphereObserver::HollowSphereObserver(std::filesystem::path out, const dem::DemScenario& sc,
                                           const dem::DemSystem<3>& s, bool resume,
                                           double resume_time)
    : setup_(make_hollow_sphere_setup(sc, s)) {
  std::filesystem::create_directories(out);
  const auto path = out / "hollow_sphere.csv";
  if (resume && std::filesystem::exists(path)) {
    io::CsvSeries::truncate_after(path, resume_time);
    const io::CsvTable t = io::read_csv(path);
    const std::size_t p = t.column("p_obj");
    for (const auto& row : t.rows) time_.push_back(row[0]), p_obj_.push_back(row[p]);
  }
  csv_ = std::make_unique<io::CsvSeries>(
      path,
      std::vector<std::string>{"time", "p_vac", "p_obj", "normal_force", "shell_radius",
                               "object_contacts"},
      resume);
}

void HollowSphereObserver::on_checkpoint(const dem::DemRun<3>&) { csv_->flush(); }

void HollowSphereObserver::on_series(const dem::DemRun<3>& run) {
  const auto& s = run.system;
  const auto& obj = s.membranes[setup_.object];
  const double p = object_pressure(s, setup_);
  const double area = obj.body.mesh.area();
  last_shell_radius_ = shell_mean_radius(s, setup_);
  time_.push_back(s.time);
  p_obj_.push_back(p);
  const double p_vac = 0.0 - dem::membrane::pressure_at(s.membranes[setup_.shell], s.time);
  csv_->row({s.time, p_vac, p, p * area, last_shell_radius_, static_cast<double>(obj.contacts)});
}

nlohmann::json HollowSphereObserver::finish() const {
  nlohmann::json j;
  j["p_vac"] = setup_.p_vac;
  j["object_radius"] = setup_.r_object;
  j["shell_radius"] = setup_.r_shell;
  j["poisson_ratio"] = setup_.poisson_ratio;
  j["p_obj_continuum"] = continuum_object_pressure(setup_.p_vac, setup_.r_shell, setup_.r_object,
                                                   setup_.poisson_ratio);
  if (time_.empty()) return j;
  j["p_obj_final"] = p_obj_.back();
  j["shell_radius_final"] = last_shell_radius_;
  // The plateau: the second half of the time after the ramp (the first half
  // lets the packing settle under the full vacuum).
  const double t0 = setup_.ramp_end + 0.5 * (time_.back() - setup_.ramp_end);
  double sum = 0.0;
  int n = 0;
  for (std::size_t k = 0; k < time_.size(); ++k)
    if (time_[k] >= t0 && time_[k] > setup_.ramp_end) sum += p_obj_[k], ++n;
  if (n > 0) {
    j["p_obj_plateau"] = sum / n;
    j["plateau_from"] = t0;
    j["plateau_rows"] = n;
  }
  return j;
}

}  // namespace talus::analysis
