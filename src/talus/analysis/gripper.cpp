#include "talus/analysis/gripper.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <limits>

#include "talus/core/error.hpp"

namespace talus::analysis {

GripperPhase gripper_phase(const dem::GripperParams& g, double t) {
  if (t < g.release) return GripperPhase::Fill;
  if (t < g.push_start) return GripperPhase::Settle;
  if (t < g.push_end) return GripperPhase::Push;
  if (t < g.vacuum_start) return GripperPhase::Relax;
  if (t < g.vacuum_end) return GripperPhase::Vacuum;
  if (t < g.pull_start) return GripperPhase::Hold;
  return GripperPhase::Pull;
}

std::string phase_name(GripperPhase p) {
  switch (p) {
    case GripperPhase::Fill:
      return "fill";
    case GripperPhase::Settle:
      return "settle";
    case GripperPhase::Push:
      return "push";
    case GripperPhase::Relax:
      return "relax";
    case GripperPhase::Vacuum:
      return "vacuum";
    case GripperPhase::Hold:
      return "hold";
    case GripperPhase::Pull:
      return "pull";
  }
  return "?";
}

GripperObserver::GripperObserver(std::filesystem::path out, const dem::DemScenario& sc,
                                 const dem::DemSystem<3>& s) {
  if (!sc.gripper) throw InputError("[gripper]: missing");
  if (s.objects.empty()) throw InputError("[gripper]: the run has no object");
  g_ = *sc.gripper;
  for (std::size_t k = 0; k < s.membranes.size(); ++k)
    if (s.membranes[k].name == g_.membrane) membrane_ = static_cast<int>(k);
  if (membrane_ < 0)
    throw InputError(fmt::format("[gripper]: no membrane named '{}'", g_.membrane));
  std::filesystem::create_directories(out);
  csv_ = std::make_unique<io::CsvSeries>(
      out / "gripper.csv",
      std::vector<std::string>{"time", "phase", "object_z", "force_x", "force_y", "force_z",
                               "object_contacts", "vacuum", "grain_contacts", "membrane_lowest_z"},
      false);
}

void GripperObserver::on_checkpoint(const dem::DemRun<3>&) { csv_->flush(); }

void GripperObserver::on_series(const dem::DemRun<3>& run) {
  const auto& s = run.system;
  const auto& o = s.objects.front();
  const auto& mb = s.membranes[membrane_];
  double lowest = std::numeric_limits<double>::infinity();
  for (const Vec3& x : mb.body.x) lowest = std::min(lowest, x.z());
  const GripperPhase phase = gripper_phase(g_, s.time);
  const double vacuum = -dem::membrane::pressure_at(mb, s.time);
  // The membrane holds the object back while it is pulled down: an upward force.
  if (phase == GripperPhase::Pull && o.force.z() > holding_force_) {
    holding_force_ = o.force.z();
    holding_time_ = s.time;
    holding_z_ = o.x.z();
  }
  if (phase == GripperPhase::Push) push_force_ = std::max(push_force_, -o.force.z());
  if (phase == GripperPhase::Hold) settled_force_ = o.force.z();
  last_time_ = s.time;
  last_contacts_ = o.contacts;
  ++rows_;
  csv_->row({s.time, static_cast<double>(phase), o.x.z(), o.force.x(), o.force.y(), o.force.z(),
             static_cast<double>(o.contacts), vacuum, static_cast<double>(mb.contacts), lowest});
}

nlohmann::json GripperObserver::finish() const {
  nlohmann::json j;
  j["release"] = g_.release;
  j["push_start"] = g_.push_start;
  j["push_end"] = g_.push_end;
  j["vacuum_start"] = g_.vacuum_start;
  j["vacuum_end"] = g_.vacuum_end;
  j["pull_start"] = g_.pull_start;
  j["vacuum"] = g_.vacuum;
  j["rows"] = rows_;
  if (rows_ == 0) return j;
  j["max_push_force"] = push_force_;
  j["force_before_pull"] = settled_force_;
  j["holding_force"] = holding_force_;
  if (holding_time_ >= 0) {
    j["holding_time"] = holding_time_;
    j["holding_object_z"] = holding_z_;
  }
  j["final_time"] = last_time_;
  j["final_object_contacts"] = last_contacts_;
  return j;
}

}  // namespace talus::analysis
