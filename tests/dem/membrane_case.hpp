#pragma once
// Grain-membrane contact coefficients of Götz 2024 Table 2, shared by the
// membrane contact and friction tests.
#include "talus/dem/contact/hertz_mindlin.hpp"
#include "talus/dem/contact/pair_coefficients.hpp"

namespace talus::dem::cases {

// Grains E 4.6e10 Pa, nu 0.245; membrane E 1.25 MPa, nu 1/3; A = 7 ns,
// gamma_t = 0.3 (spec/membranes-and-jamming.md). The pair friction mu is the
// test's choice.
inline ViscoelasticHertz::Coeffs goetz_grain_membrane(double mu) {
  MaterialParams grain, membrane;
  grain.youngs_modulus = 4.6e10;
  grain.poisson_ratio = 0.245;
  membrane.youngs_modulus = 1.25e6;
  membrane.poisson_ratio = 1.0 / 3.0;
  return {{effective_youngs(grain, membrane), effective_shear(grain, membrane), mu}, 7e-9, 0.3};
}

}  // namespace talus::dem::cases
