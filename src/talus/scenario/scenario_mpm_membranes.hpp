#pragma once
// [[membranes]] of MPM scenarios (mpm.md "Membranes in MPM"): reading one
// table with file:line:key errors, and writing it back in resolved form.
// Documented in docs/scenario-format.md (MPM, [[membranes]]).
#include <nlohmann/json.hpp>

#include "talus/scenario/scenario_detail.hpp"
#include "talus/mpm/scenario.hpp"

namespace talus::io::detail {

// index: 1-based position among the [[membranes]], for the default name.
mpm::MembraneParams read_mpm_membrane(TomlReader& r, std::size_t index, const mpm::MpmScenario& s,
                                      const DemContext& ctx);
nlohmann::ordered_json mpm_membrane_table(const mpm::MembraneParams& m, int dimension);

}  // namespace talus::io::detail
