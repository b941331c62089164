#pragma once
// The force network of the grains (Götz 2024 §5.3.4, Abb. 30): the mean force
// per contact <F> = <|f_n n + f_t|>, its normal and tangential parts <f_n>,
// <|f_t|>, and the fraction of contacts whose tangential force lies within a
// tolerance (the source: 5 %) of the Coulomb limit, |f_t| >= (1 - tol) μ |f_n|.
// A frictionless contact (μ = 0) is always at its limit. Pure arithmetic on
// the pair forces a stepper reports (dem::StepperBase::pair_contact_forces).
#include <cstddef>
#include <span>

#include "talus/dem/stepper.hpp"

namespace talus::analysis {

struct ForceNetwork {
  std::size_t contacts = 0;
  double mean_force = 0.0;       // N
  double mean_normal = 0.0;      // N
  double mean_tangential = 0.0;  // N
  double coulomb_fraction = 0.0;
};

// All zero for no contacts. Throws InputError for a tolerance outside [0, 1).
ForceNetwork force_network(std::span<const dem::PairContactForce> pairs,
                           double coulomb_tolerance = 0.05);

}  // namespace talus::analysis
