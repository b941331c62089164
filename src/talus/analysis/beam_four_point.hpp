#pragma once
// The granular beam in 4-point bending (Götz 2024 §5.3 and appendix B,
// spec/membranes-and-jamming.md, dem::BeamParams with test = FourPoint):
// Euler–Bernoulli's stress and strain of the midspan from the rods' force F
// and the midspan deflection Δz,
//   σ = F L / (h² t),  ε = 108 h Δz / (23 L²),
// the modulus E_b of the fit σ = E_b ε for ε <= 0.002 and the yield strength
// Y_b where the second derivative of the smoothed σ(ε) turns from negative to
// positive.
//
// The observer records, at each series time, into <out>/beam.csv: time, the
// rods' travel and their mean force since the previous row, the mean z of the
// measured bottom-centre particles, Δz (from bending_start on), ε, σ, the
// supports' reaction z, the kinetic energy of grains and membrane and the
// grains' force network (analysis/force_network.hpp: contacts, <F>, <f_n>,
// <|f_t|>, the fraction within 5 % of the Coulomb limit). L, h and
// t are the beam's as it stands at bending_start: the span between the
// supports' centroids and the section between opposite faces (the vacuum
// shrinks it; the summary gives E_b and Y_b with the rest size too, as the
// source computes them).
#include <filesystem>
#include <memory>
#include <nlohmann/json.hpp>
#include <span>
#include <vector>

#include "talus/dem/builder.hpp"
#include "talus/io/csv_writer.hpp"

namespace talus::analysis {

double four_point_stress(double force, double span, double height, double thickness);
double four_point_strain(double deflection, double span, double height);

struct SmallStrainFit {
  double modulus = 0.0;  // E_b (Pa): least squares of σ = E ε through the origin
  int points = 0;        // samples with 0 < ε <= the limit
  double r2 = 0.0;       // 1 - Σ(σ - E ε)² / Σ(σ - mean σ)²
};
// Throws InputError for fewer than 3 samples in (0, strain_limit].
SmallStrainFit fit_small_strain(std::span<const double> strain, std::span<const double> stress,
                                double strain_limit);

struct YieldPoint {
  bool found = false;
  double strain = 0.0, stress = 0.0;  // on the smoothed curve
};
// The source's recipe: σ(ε) smoothed by a Gaussian of standard deviation
// `width` (strain; Gaussian-weighted means of the samples at the points of a
// uniform grid), differentiated, smoothed again, differentiated again; the yield point is the first
// grid point, further than 2 widths from either end of the curve, where the second derivative turns
// from negative to positive.
YieldPoint yield_from_curvature(std::span<const double> strain, std::span<const double> stress,
                                double width);

// The source's limit of the linear part of σ(ε) (§5.3.2).
inline constexpr double kFourPointLinearStrain = 0.002;

// What a σ(ε) curve yields, as the summary and `talus analyse beam` report it:
// largest_strain, largest_stress, strain_at_largest_stress; youngs_modulus,
// fit_points, fit_r2 of fit_small_strain up to linear_strain (fit_error when
// it throws); yield_found, yield_strength, yield_strain of
// yield_from_curvature. Needs one sample or more.
nlohmann::json four_point_curve(std::span<const double> strain, std::span<const double> stress,
                                double linear_strain, double yield_smoothing);

class FourPointObserver final {
 public:
  // Throws InputError when the scenario has no four-point [beam] or no
  // membrane has the rig.
  FourPointObserver(std::filesystem::path out, const dem::DemScenario& sc,
                    const dem::DemSystem<3>& s);
  void on_series(const dem::DemRun<3>& run);
  // E_b, Y_b, the largest strain and stress, and the geometry used.
  nlohmann::json finish() const;

 private:
  std::filesystem::path out_;
  dem::BeamParams b_;
  int membrane_ = -1;
  std::unique_ptr<io::CsvSeries> csv_;
  // The membrane's rest size: the source's L_b, t_b, h_b (x, y, z).
  Vec3 nominal_ = Vec3::Zero();
  // At the first row from bending_start on: the midspan's z, the span
  // between the supports' centroids, width and height between opposite faces.
  bool started_ = false;
  double z0_ = 0.0, span_ = 0.0, width_ = 0.0, height_ = 0.0;
  std::vector<double> strain_, stress_;
  double last_time_ = 0.0, last_impulse_ = 0.0;
};

}  // namespace talus::analysis
