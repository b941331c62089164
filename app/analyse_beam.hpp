#pragma once
// talus analyse beam: E_b and Y_b of a finished 4-point beam run (Götz 2024 §5.3) again
// from its beam.csv, with another smoothing width or strain limit than the run used: the
// source does not give its smoothing, and Y_b depends on it.
#include <limits>
#include <string>

#include "talus/analysis/beam_four_point.hpp"

namespace talus::app {

struct BeamAnalysisOptions {
  std::string run_dir, out;
  double yield_smoothing = std::numeric_limits<double>::quiet_NaN();  // NaN: the run's
  double linear_strain = analysis::kFourPointLinearStrain;            // E_b over 0 < ε <= this
  bool quiet = false;
};

// Writes <out>/beam_four_point.json (default <run>/analysis): E_b and its fit, the yield
// point (or that there is none), the largest stress, and the options used.
int beam_analysis_command(const BeamAnalysisOptions& options);

}  // namespace talus::app
