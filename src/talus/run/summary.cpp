#include "talus/run/summary.hpp"

#include "talus/core/version.hpp"
#include "talus/io/archive.hpp"

namespace talus::run {

nlohmann::json summary_json(const SummaryInput& in) {
  const auto& r = in.report;
  nlohmann::json j = {{"talus_version", talus::version()},
                      {"status", in.status},
                      {"method", r.method},
                      {"dimension", r.dimension},
                      {"scenario", r.scenario}};
  if (!r.model.empty()) j["model"] = r.model;
  j["resolved"] = r.resolved;
  // Steps, times and the throughput: items (particles, blocks, points, cells)
  // advanced per second of the time loop.
  j["run"] = {{"steps", in.steps},
              {"simulated_time_s", in.simulated_time},
              {"loop_wall_s", in.loop_seconds},
              {"setup_wall_s", in.setup_seconds},
              {r.rate_key, in.loop_seconds > 0 ? r.items * in.steps / in.loop_seconds : 0.0}};
  if (in.estimated_steps >= 0.0) j["run"]["estimated_steps"] = in.estimated_steps;
  if (in.estimated_wall_seconds >= 0.0) j["run"]["estimated_wall_s"] = in.estimated_wall_seconds;
  if (in.mpi_ranks > 1) j["run"]["mpi_ranks"] = in.mpi_ranks;
  for (const auto& [k, v] : r.run_extra.items()) j["run"][k] = v;
  j["metrics"] = r.metrics;
  if (!r.warnings.empty()) j["warnings"] = r.warnings;
  for (const auto& [name, part] : in.experiments.items()) j[name] = part;
  if (!in.error.empty()) j["error"] = in.error;
  return j;
}

void write_summary(const std::filesystem::path& out, const SummaryInput& in) {
  io::write_file_atomically(out / "summary.json", summary_json(in).dump(2) + "\n");
}

}  // namespace talus::run
