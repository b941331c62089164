#include <fmt/core.h>

#include "talus/core/error.hpp"
#include "talus/run/method.hpp"
#include "talus/run/methods/methods.hpp"

namespace talus::run {

const std::vector<Method>& methods() {
  // One line per method.
  static const std::vector<Method> all = {
      dem_method(), mpm_method(), dan_method(), fv2d_method(), two_phase_method(),
  };
  return all;
}

const Method& method_for(const io::ScenarioFile& file) {
  for (const auto& m : methods())
    if (m.accepts(file)) return m;
  throw InputError(fmt::format("{}: no method runs method = \"{}\"", file.path, file.method));
}

}  // namespace talus::run
