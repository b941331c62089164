#include "talus/analysis/force_network.hpp"

#include <fmt/format.h>

#include <cmath>

#include "talus/core/error.hpp"

namespace talus::analysis {

ForceNetwork force_network(std::span<const dem::PairContactForce> pairs, double coulomb_tolerance) {
  if (!(coulomb_tolerance >= 0.0 && coulomb_tolerance < 1.0))
    throw InputError(fmt::format("force_network: coulomb tolerance must lie in [0, 1), got {}",
                                 coulomb_tolerance));
  ForceNetwork out;
  out.contacts = pairs.size();
  if (pairs.empty()) return out;
  std::size_t at_limit = 0;
  for (const auto& c : pairs) {
    out.mean_force += std::hypot(c.normal, c.tangential);
    out.mean_normal += c.normal;
    out.mean_tangential += c.tangential;
    at_limit += c.tangential >= (1.0 - coulomb_tolerance) * c.friction * std::abs(c.normal);
  }
  const double n = static_cast<double>(pairs.size());
  out.mean_force /= n;
  out.mean_normal /= n;
  out.mean_tangential /= n;
  out.coulomb_fraction = static_cast<double>(at_limit) / n;
  return out;
}

}  // namespace talus::analysis
