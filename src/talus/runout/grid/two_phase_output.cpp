#include "talus/runout/grid/two_phase_output.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <limits>

namespace talus::runout {

namespace {

std::vector<double> per_cell(const TwoPhaseSolver& s,
                             double (TwoPhaseSolver::*f)(std::size_t, Phase) const, Phase phase) {
  std::vector<double> v(s.state().hs.size());
  for (std::size_t c = 0; c < v.size(); ++c) v[c] = (s.*f)(c, phase);
  return v;
}

}  // namespace

std::vector<double> solid_fraction(const TwoPhaseSolver& s) {
  const auto& st = s.state();
  std::vector<double> alpha(st.hs.size(), std::numeric_limits<double>::quiet_NaN());
  for (std::size_t c = 0; c < alpha.size(); ++c)
    if (const double h = st.hs[c] + st.hf[c]; h > s.params().dry_depth) alpha[c] = st.hs[c] / h;
  return alpha;
}

TwoPhaseOutputs::TwoPhaseOutputs(std::filesystem::path dir, const GridSpec& grid, bool resume,
                                 double resume_time, bool snapshots)
    : dir_(std::move(dir)), grid_(grid) {
  if (resume) io::CsvSeries::truncate_after(dir_ / "series.csv", resume_time);
  series_ = std::make_unique<io::CsvSeries>(
      dir_ / "series.csv",
      std::vector<std::string>{"time", "solid_volume", "fluid_volume", "solid_outflow",
                               "fluid_outflow", "rained_volume", "infiltrated_volume", "mass",
                               "momentum_x", "momentum_y", "kinetic_energy", "max_speed",
                               "max_height", "flowing_area"},
      resume);
  if (snapshots) snapshots_ = std::make_unique<GridSnapshots>(dir_, grid, resume, resume_time);
}

void TwoPhaseOutputs::on_series(const TwoPhaseSolver& s) {
  const auto& d = s.params().drag;
  const std::size_t n = s.state().hs.size();
  std::size_t flowing = 0;
  double max_height = 0.0;
  for (std::size_t c = 0; c < n; ++c) {
    if (std::max(s.speed(c, Phase::Solid), s.speed(c, Phase::Fluid)) >= TwoPhaseSolver::kRestSpeed)
      ++flowing;
    max_height =
        std::max(max_height, s.normal_height(c, Phase::Solid) + s.normal_height(c, Phase::Fluid));
  }
  const auto t = s.totals();
  series_->row({s.state().time, s.solid_volume(), s.fluid_volume(), t.solid_outflow,
                t.fluid_outflow, t.rained, t.infiltrated,
                d.solid_density * s.solid_volume() + d.fluid_density * s.fluid_volume(),
                s.momentum_x(), s.momentum_y(), s.kinetic_energy(), s.max_speed(), max_height,
                static_cast<double>(flowing) * s.terrain().shape().cell_area()});
}

void TwoPhaseOutputs::on_snapshot(const TwoPhaseSolver& s) {
  const double t = s.state().time;
  auto height = per_cell(s, &TwoPhaseSolver::normal_height, Phase::Solid);
  const auto fluid = per_cell(s, &TwoPhaseSolver::normal_height, Phase::Fluid);
  for (std::size_t c = 0; c < height.size(); ++c) height[c] += fluid[c];
  snapshots_->add(t,
                  {{"height", std::move(height),
                    fmt::format("mixture flow height at t = {:.6g} s, bed-normal", t), "m"},
                   {"solid_fraction", solid_fraction(s),
                    fmt::format("solid fraction alpha_s at t = {:.6g} s (NaN where dry)", t), "-"},
                   {"solid_speed", per_cell(s, &TwoPhaseSolver::speed, Phase::Solid),
                    fmt::format("solid speed at t = {:.6g} s, bed-parallel", t), "m/s"},
                   {"fluid_speed", per_cell(s, &TwoPhaseSolver::speed, Phase::Fluid),
                    fmt::format("fluid speed at t = {:.6g} s, bed-parallel", t), "m/s"}});
}

void TwoPhaseOutputs::flush() {
  series_->flush();
  if (snapshots_) snapshots_->flush();
}

void TwoPhaseOutputs::write_results(const TwoPhaseSolver& s, const TwoPhaseMaxima& m) const {
  const auto solid = per_cell(s, &TwoPhaseSolver::normal_height, Phase::Solid);
  const auto fluid = per_cell(s, &TwoPhaseSolver::normal_height, Phase::Fluid);
  std::vector<double> deposit(solid.size());
  for (std::size_t c = 0; c < deposit.size(); ++c) deposit[c] = solid[c] + fluid[c];
  // Heights bed-normal, volumes vertical, as fv2d's maps.
  const std::vector<GridField> maps = {
      {"max_height", m.height, "maximum mixture height, bed-normal", "m"},
      {"max_solid_height", m.solid_height, "maximum solid height H_s, bed-normal", "m"},
      {"max_fluid_height", m.fluid_height, "maximum fluid height H_f, bed-normal", "m"},
      {"max_solid_speed", m.solid_speed, "maximum solid speed, bed-parallel", "m/s"},
      {"max_fluid_speed", m.fluid_speed, "maximum fluid speed, bed-parallel", "m/s"},
      {"max_pressure", m.pressure, "maximum mixture impact pressure sum alpha_p rho_p v_p^2", "Pa"},
      {"max_solid_pressure", m.solid_pressure, "maximum solid impact pressure alpha_s rho_s v_s^2",
       "Pa"},
      {"max_fluid_pressure", m.fluid_pressure, "maximum fluid impact pressure alpha_f rho_f v_f^2",
       "Pa"},
      {"deposit", deposit, "mixture height at the end, bed-normal", "m"},
      {"deposit_solid", solid, "solid height at the end, bed-normal", "m"},
      {"deposit_fluid", fluid, "fluid height at the end, bed-normal", "m"},
      {"solid_fraction", solid_fraction(s), "solid fraction alpha_s at the end (NaN where dry)",
       "-"},
      {"elevation", s.terrain().elevation(), "bed elevation with obstacles", "m"},
      {"arrival_time", m.arrival, "time the mixture height first exceeded 1 cm", "s"}};
  for (const auto& map : maps) write_result_map(dir_, grid_, map);
  series_->flush();
}

}  // namespace talus::runout
