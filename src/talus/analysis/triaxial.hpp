#pragma once
// The triaxial test of Götz 2024 §3.3.1 (spec/membranes-and-jamming.md): a
// grain sample in an open cylindrical membrane under the confining pressure
// p_c, between two plane plates that a servo first brings to the gap h0 where
// the grains push on them with p_c, and that then approach at a constant speed.
// This observer records, at each series time, into <out>/triaxial.csv:
//   time, phase (0 servo, 1 loading), gap h, axial strain eps = ln(h0/h)
//   (0 in the servo phase), the plates' pressures (mean force over the series
//   interval, from their impulses, over the sample's cross-section pi R0^2),
//   p_plates (their mean), p_c, the deviator stress sigma_d = p_plates - p_c,
//   and the membrane's mean radius (lateral bulging).
#include <cmath>
#include <filesystem>
#include <memory>
#include <nlohmann/json.hpp>

#include "talus/dem/builder.hpp"
#include "talus/io/csv_writer.hpp"

namespace talus::analysis {

// eps = ln(h0 / h), positive in compression.
inline double axial_strain(double h0, double h) { return std::log(h0 / h); }

// Where the test's parts are in the system, and its constants.
struct TriaxialSetup {
  int bottom = -1, top = -1, membrane = -1;  // indices of the walls and membrane
  double confining_pressure = 0.0;           // p_c = -membrane pressure, Pa
  double area = 0.0;                         // pi R0^2, m^2
  double servo_stop = 0.0;                   // s, the later of the plates' servo stops
};
// Throws InputError when a named part is missing.
TriaxialSetup make_triaxial_setup(const dem::DemScenario& sc, const dem::DemSystem<3>& s);

// Gap between the plates now (along the bottom plate's normal), and the gap
// the plates had when their servos stopped (valid once time >= servo_stop).
double plate_gap(const dem::DemSystem<3>& s, const TriaxialSetup& t);
double gap_at_servo_stop(const dem::DemSystem<3>& s, const TriaxialSetup& t);
// Mean distance of the membrane particles from the vertical line through `axis`
// (the membrane's initial axis).
double membrane_mean_radius(const dem::DemSystem<3>& s, const TriaxialSetup& t, const Vec3& axis);

class TriaxialObserver final {
 public:
  // resume = true continues the triaxial.csv of a run resumed at
  // resume_time (the system as restored from its checkpoint), after the run's
  // DemOutputs has cut series.csv back to that time: the observer's state is
  // read back from both files (see restore()).
  TriaxialObserver(std::filesystem::path out, const dem::DemScenario& sc,
                   const dem::DemSystem<3>& s, bool resume = false, double resume_time = 0.0);
  void on_series(const dem::DemRun<3>& run);
  // Flushes triaxial.csv: a resumed run reads it back up to the checkpoint.
  void on_checkpoint(const dem::DemRun<3>& run);
  // h0, the pressures at the switch, the peak deviator stress and its strain,
  // the final strain: for summary.json.
  nlohmann::json finish() const;

 private:
  // The state of the last on_series before the checkpoint, from the rows
  // written then (shortest round-trip text, so exact): the plates' impulses
  // from series.csv, h0, the pressures at the switch and the peak from
  // triaxial.csv. Throws RunError when the two files do not end at the same time.
  void restore(const std::filesystem::path& out, const dem::DemSystem<3>& s);

  TriaxialSetup setup_;
  Vec3 axis_;  // a point on the membrane's axis (x, y of its centre)
  std::unique_ptr<io::CsvSeries> csv_;
  Vec3 last_impulse_[2] = {Vec3::Zero(), Vec3::Zero()};
  double last_time_ = 0.0;
  double h0_ = -1.0, p_at_h0_ = 0.0;
  double peak_sigma_ = -1e300, peak_eps_ = 0.0, last_eps_ = 0.0;
};

}  // namespace talus::analysis
