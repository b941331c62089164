#pragma once
// The granular gripper of Götz 2024 §4.2 (spec/membranes-and-jamming.md,
// dem::GripperParams): the force between the object and the gripper through
// the protocol, and the holding force F_h, the largest upward force on the
// object while it is pulled down (the membrane's friction and grip holding
// it back).
//
// This observer records, at each series time, into <out>/gripper.csv:
//   time, phase (GripperPhase as a number), the object's centre z, the force
//   of the membrane on the object (x, y, z), its contacts with the membrane,
//   the vacuum applied (Pa, > 0), the grain-membrane contacts and the
//   membrane's lowest z.
#include <filesystem>
#include <memory>
#include <nlohmann/json.hpp>
#include <string>

#include "talus/dem/builder.hpp"
#include "talus/io/csv_writer.hpp"

namespace talus::analysis {

enum class GripperPhase {
  Fill = 0,
  Settle = 1,
  Push = 2,
  Relax = 3,
  Vacuum = 4,
  Hold = 5,
  Pull = 6
};
// The phase at time t: fill until release, settle until push_start, then
// push, relax, vacuum, hold and pull as GripperParams derives them.
GripperPhase gripper_phase(const dem::GripperParams& g, double t);
std::string phase_name(GripperPhase p);

class GripperObserver final {
 public:
  // Throws InputError when the scenario has no [gripper] or the system no object.
  GripperObserver(std::filesystem::path out, const dem::DemScenario& sc,
                  const dem::DemSystem<3>& s);
  void on_series(const dem::DemRun<3>& run);
  void on_checkpoint(const dem::DemRun<3>& run);
  // The holding force and where it was reached; the largest push force; the
  // phase times; the object's last contacts (0: pulled free).
  nlohmann::json finish() const;

 private:
  dem::GripperParams g_;
  int membrane_ = -1;
  std::unique_ptr<io::CsvSeries> csv_;
  double holding_force_ = 0.0, holding_time_ = -1.0, holding_z_ = 0.0;
  double push_force_ = 0.0, settled_force_ = 0.0;
  double last_time_ = 0.0;
  int last_contacts_ = 0, rows_ = 0;
};

}  // namespace talus::analysis
