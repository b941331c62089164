#pragma once
// The granular beam in 3-point bending (Götz 2024 §5.2, spec/membranes-and-
// jamming.md, dem::BeamParams): the deflection at each load step and the
// beam's modulus from Timoshenko's formula (spec; source eq. 36)
//   Δz = F L³ / (48 E_b I) + 3 F L (1 + ν_b) / (5 E_b A),  E_b,eff = E_b / (1 - ν_b²),
// with I = b h³ / 12 and A = b h of the beam's cross-section.
//
// The observer records, at each series time, into <out>/beam.csv:
//   time, step (-1 before bending_start), load (N, along -z), the mean z of the
//   measured bottom-centre particles, the supports' reaction z, and the kinetic
//   energy of grains and membrane.
// At the end, <out>/beam_steps.csv holds per step: step, load, mean z and
// deflection (z at step 0 minus z; > 0 downwards) over the last half of the
// step, and the mean support reaction there.
#include <filesystem>
#include <memory>
#include <nlohmann/json.hpp>
#include <span>
#include <vector>

#include "talus/dem/builder.hpp"
#include "talus/dem/membrane/beam_rig.hpp"
#include "talus/io/csv_writer.hpp"

namespace talus::analysis {

struct BeamFit {
  double slope = 0.0;      // dΔz/dF by least squares (with intercept), m/N
  double intercept = 0.0;  // m
  double r2 = 0.0;         // coefficient of determination of the line
  double youngs_modulus = 0.0, effective_modulus = 0.0;  // E_b, E_b,eff (Pa)
};

// The line through (load, deflection) and E_b from its slope for span L,
// width b, height h and ν_b. Throws InputError for fewer than 2 points, no
// spread in load or a slope that is not positive.
BeamFit fit_three_point(std::span<const double> load, std::span<const double> deflection,
                        double span, double width, double height, double poisson_ratio);

// The beam as it stands: span between the supports' centroids, width (y)
// and height (z) between the membrane's opposite flat faces (their mean
// positions: the rounded edges stand out further).
struct BeamSection {
  double span = 0.0, width = 0.0, height = 0.0;
};
BeamSection measure_section(const dem::membrane::BeamRig& rig, std::span<const Vec3> x);
// Which membrane carries the rig and its rest size (x, y, z): the source's
// L_b and section. Throws InputError when the scenario has no [beam] or no
// membrane has the rig.
struct BeamMembrane {
  int index = -1;
  Vec3 rest_size = Vec3::Zero();
};
BeamMembrane find_beam_membrane(const dem::DemScenario& sc, const dem::DemSystem<3>& s);
// Mean z of the particles `set` (the deflection's measure).
double mean_z(const std::vector<int>& set, std::span<const Vec3> x);

class BeamObserver final {
 public:
  // Throws InputError when the scenario has no [beam] or no membrane has the rig.
  BeamObserver(std::filesystem::path out, const dem::DemScenario& sc, const dem::DemSystem<3>& s);
  void on_series(const dem::DemRun<3>& run);
  // The steps' table and the fit (loading branch) with the span and section
  // measured when the supports were pinned and with the membrane's rest size,
  // the largest gap between the loading and unloading branches; writes
  // beam_steps.csv.
  nlohmann::json finish() const;

 private:
  std::filesystem::path out_;
  dem::BeamParams b_;
  BeamMembrane beam_;
  std::unique_ptr<io::CsvSeries> csv_;
  struct StepMean {
    int rows = 0;
    double z = 0.0, reaction = 0.0;
  };
  std::vector<StepMean> steps_;
  // Measured at the first row from bending_start on.
  bool measured_ = false;
  BeamSection section_;
};

}  // namespace talus::analysis
