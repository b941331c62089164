#pragma once
// summary.json: what ran, with which resolved parameters, how long it took and
// the headline results.
#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>

#include "talus/dem/builder.hpp"
#include "talus/dem/output_observer.hpp"
#include "talus/runout/grid/fv2d_run.hpp"
#include "talus/runout/results.hpp"
#include "talus/runout/scenario.hpp"
#include "talus/mpm/output_observer.hpp"
#include "talus/mpm/scenario.hpp"

namespace talus::app {

struct RunSummary {
  std::filesystem::path output;
  int64_t steps = 0;
  double loop_seconds = 0.0, setup_seconds = 0.0;
  // Method-specific analyses by name ("flume", "dam_break"), each a top-level key.
  nlohmann::json analysis = nlohmann::json::object();
};

template <int D>
void write_dem_summary(const dem::DemScenario& sc, const dem::DemRun<D>& run,
                       const dem::DemOutputs<D>& outputs, const RunSummary& summary, int threads,
                       const std::string& status, const std::string& error);

void write_runout_summary(const runout::RunoutScenario& sc, const runout::DanModel& model,
                          const runout::RunoutResults& results, const RunSummary& summary,
                          const std::string& status, const std::string& error);
// --- MPM ---
template <int D>
void write_mpm_summary(const mpm::MpmScenario& sc, const mpm::Solver<D>& solver,
                       const mpm::MpmOutputs<D>& outputs, const RunSummary& summary, int threads,
                       const std::string& status, const std::string& error);

void write_fv2d_summary(const runout::RunoutScenario& sc, const runout::Fv2dSolver& solver,
                        const runout::Fv2dMaxima& maxima, double initial_volume,
                        const RunSummary& summary, int threads, const std::string& status,
                        const std::string& error);

}  // namespace talus::app
