#include "analyse_beam.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <vector>

#include "talus/analysis/beam_four_point.hpp"
#include "talus/core/error.hpp"
#include "talus/io/csv_reader.hpp"

namespace fs = std::filesystem;

namespace talus::app {

int beam_analysis_command(const BeamAnalysisOptions& o) {
  const fs::path run = o.run_dir, summary_path = run / "summary.json";
  std::ifstream summary_file(summary_path);
  if (!summary_file) throw InputError(fmt::format("{}: no summary.json there", run.string()));
  nlohmann::json summary;
  try {
    summary = nlohmann::json::parse(summary_file);
  } catch (const nlohmann::json::exception& e) {
    throw InputError(fmt::format("{}: {}", summary_path.string(), e.what()));
  }
  const auto params = summary.value("/scenario/beam"_json_pointer, nlohmann::json());
  if (params.value("test", "") != "four_point")
    throw InputError(
        fmt::format("{}: not a four-point beam run ([beam] test = \"four_point\")", run.string()));
  const double width = std::isnan(o.yield_smoothing) ? params.at("yield_smoothing").get<double>()
                                                     : o.yield_smoothing;
  if (!(width > 0)) throw InputError("--yield-smoothing: expected a strain > 0");
  if (!(o.linear_strain > 0)) throw InputError("--linear-strain: expected a strain > 0");
  const double start = params.at("bending_start").get<double>();

  const io::CsvTable table = io::read_csv(run / "beam.csv");
  const std::size_t ct = table.column("time"), ce = table.column("strain"),
                    cs = table.column("stress");
  std::vector<double> strain, stress;
  for (const auto& r : table.rows)
    if (r[ct] >= start) {  // before bending_start the columns hold zeros
      strain.push_back(r[ce]);
      stress.push_back(r[cs]);
    }
  if (strain.empty())
    throw InputError(
        fmt::format("{}: no row from bending_start ({} s) on", table.path.string(), start));

  nlohmann::json j{{"run", run.string()},
                   {"yield_smoothing", width},
                   {"linear_strain", o.linear_strain},
                   {"rows", strain.size()}};
  j.update(analysis::four_point_curve(strain, stress, o.linear_strain, width));
  if (j.contains("fit_error")) throw InputError(j["fit_error"].get<std::string>());
  const fs::path out = o.out.empty() ? run / "analysis" : fs::path(o.out);
  fs::create_directories(out);
  std::ofstream file(out / "beam_four_point.json");
  file << j.dump(2) << "\n";
  if (!file) throw RunError("cannot write " + (out / "beam_four_point.json").string());
  if (!o.quiet)
    fmt::print(stderr, "E_b {:.4g} Pa (r2 {:.4f}, {} points), Y_b {}, largest stress {:.4g} Pa\n",
               j["youngs_modulus"].get<double>(), j["fit_r2"].get<double>(),
               j["fit_points"].get<int>(),
               j["yield_found"].get<bool>()
                   ? fmt::format("{:.4g} Pa at strain {:.4g}", j["yield_strength"].get<double>(),
                                 j["yield_strain"].get<double>())
                   : std::string("none"),
               j["largest_stress"].get<double>());
  return 0;
}

}  // namespace talus::app
