#include "talus/analysis/dam_break.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include "talus/io/csv_writer.hpp"

namespace talus::analysis {

SlopeProfile slope_profile(const Grains& grains, double length, double bin) {
  const auto n = static_cast<std::size_t>(std::ceil(length / bin));
  SlopeProfile p;
  p.top.assign(n, 0.0);
  for (std::size_t k = 0; k < n; ++k) p.x.push_back((static_cast<double>(k) + 0.5) * bin);
  for (std::size_t i = 0; i < grains.x.size(); ++i) {
    const double k = std::floor(grains.x[i].x() / bin);
    if (k < 0 || k >= static_cast<double>(n)) continue;
    double& top = p.top[static_cast<std::size_t>(k)];
    top = std::max(top, grains.x[i].y() + grains.r[i]);
  }
  return p;
}

namespace {

// Surface height at x, linear between bin centres.
double height_at(const SlopeProfile& p, double x) {
  if (x <= p.x.front()) return p.top.front();
  if (x >= p.x.back()) return p.top.back();
  const auto it = std::upper_bound(p.x.begin(), p.x.end(), x);
  const auto k = static_cast<std::size_t>(it - p.x.begin());
  const double w = (x - p.x[k - 1]) / (p.x[k] - p.x[k - 1]);
  return (1 - w) * p.top[k - 1] + w * p.top[k];
}

}  // namespace

SlopeAngles slope_angles(const SlopeProfile& p, double toe_thickness, double segment_length,
                         int segments) {
  SlopeAngles out;
  if (p.x.empty()) return out;
  const double bin = p.x.size() > 1 ? p.x[1] - p.x[0] : 2 * p.x[0];
  std::size_t last = 0;
  while (last + 1 < p.top.size() && p.top[last + 1] > toe_thickness) ++last;
  out.toe_x = p.x[last] + 0.5 * bin;
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double h0 = height_at(p, out.toe_x);
  double previous = h0;
  for (int k = 1; k <= segments; ++k) {
    const double x = out.toe_x - k * segment_length;
    if (x < 0) {
      out.gamma_deg.push_back(nan);
      continue;
    }
    const double h = height_at(p, x);
    out.gamma_deg.push_back(std::atan((h - previous) / segment_length) * 180 / M_PI);
    previous = h;
  }
  const double x_end = out.toe_x - segments * segment_length;
  out.gamma_total_deg =
      x_end < 0 ? nan
                : std::atan((height_at(p, x_end) - h0) / (segments * segment_length)) * 180 / M_PI;
  return out;
}

nlohmann::json report_dam_break(const Grains& grains, const dem::DamBreakParams& params,
                                const std::filesystem::path& out) {
  const SlopeProfile profile = slope_profile(grains, params.floor_length, params.profile_bin);
  double mean_diameter = 0.0;
  for (double r : grains.r) mean_diameter += 2.0 * r;
  if (!grains.r.empty()) mean_diameter /= static_cast<double>(grains.r.size());
  const double toe_thickness =
      params.toe_thickness > 0 ? params.toe_thickness : 3.0 * mean_diameter;
  const SlopeAngles a =
      slope_angles(profile, toe_thickness, params.segment_length, params.segments);
  std::filesystem::create_directories(out / "dam_break");
  auto csv = io::CsvSeries::whole(out / "dam_break" / "surface.csv", {"x", "top"});
  for (std::size_t k = 0; k < profile.x.size(); ++k) csv.row({profile.x[k], profile.top[k]});
  csv.close();
  // JSON has no NaN: a segment behind the back wall is null.
  auto number = [](double v) { return std::isnan(v) ? nlohmann::json() : nlohmann::json(v); };
  nlohmann::json j = {{"toe_x", a.toe_x},
                      {"toe_thickness", toe_thickness},
                      {"segment_length", params.segment_length},
                      {"gamma_total", number(a.gamma_total_deg)}};
  for (std::size_t k = 0; k < a.gamma_deg.size(); ++k)
    j["gamma_" + std::to_string(k + 1)] = number(a.gamma_deg[k]);
  return j;
}

}  // namespace talus::analysis
