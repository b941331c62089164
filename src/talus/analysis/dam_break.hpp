#pragma once
// The slope a dam break leaves behind (spec: flume.md "Dam-break calibration"):
// the deposit surface along x and the angles of segments of equal horizontal
// length measured upstream from the toe, as Hungr (2008) read them off the lab
// test and Kuen fitted gamma_3..gamma_5 with the grain friction.
#include <filesystem>
#include <nlohmann/json.hpp>
#include <vector>

#include "talus/analysis/flume_measure.hpp"
#include "talus/dem/params.hpp"

namespace talus::analysis {

struct SlopeProfile {
  std::vector<double> x;    // bin centres, m
  std::vector<double> top;  // top of the highest grain in the bin above the floor (y = 0), m
};

struct SlopeAngles {
  double toe_x = 0.0;             // downstream end of the deposit, m
  std::vector<double> gamma_deg;  // gamma_1 (at the toe) .. gamma_n; NaN behind the back wall
  double gamma_total_deg = 0.0;   // over all n segments together
};

SlopeProfile slope_profile(const Grains& grains, double length, double bin);

// The toe: walking downstream from the back wall (x = 0), the end of the last
// bin of the unbroken run thicker than toe_thickness.
SlopeAngles slope_angles(const SlopeProfile& profile, double toe_thickness, double segment_length,
                         int segments);

// Measures the final state of a dam-break run, writes <out>/dam_break/surface.csv
// and returns the numbers for summary.json ("gamma_1" .. "gamma_n" in degrees,
// so that `talus calibrate` can name them).
nlohmann::json report_dam_break(const Grains& grains, const dem::DamBreakParams& params,
                                const std::filesystem::path& out);

}  // namespace talus::analysis
