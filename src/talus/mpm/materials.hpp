#pragma once
// Constitutive models of the material points, one small type each, behind one
// interface chosen by name: every model has
//   static constexpr std::string_view name;          // the file's `model`
//   static constexpr std::array<DeclaredKey<MaterialParams>, N> keys;
//   static Model make(const MaterialParams&);
//   static KeyProblem check(const MaterialParams&);  // across keys, after reading
//   void update(MaterialState&, const Mat3& velocity_gradient, double dt,
//               double volume_change_over_v0) const;
//   double wave_speed() const;   // P-wave speed for the time step
// The scenario reader and writer read the name and keys from here
// (core/declared_keys.hpp); a new model is a new type plus its entry in
// `Material` below. The solver holds them in a std::variant and dispatches
// once per material (std::visit outside the particle loop), never per particle.
// Tension positive; 3x3 tensors also in 2D (plane strain).
#include <array>
#include <limits>
#include <string>
#include <string_view>
#include <variant>

#include "talus/core/declared_keys.hpp"
#include "talus/mpm/tensor.hpp"

namespace talus::mpm {

struct MaterialParams {
  std::string name;
  std::string model = "linear_elastic";  // a name from `Material` below
  double density = 0.0;                  // kg/m^3
  double youngs_modulus = 0.0;           // Pa (solids)
  double poisson_ratio = 0.0;
  double friction_angle = 0.0;   // rad (Drucker-Prager, Mohr-Coulomb)
  double dilatancy_angle = 0.0;  // rad
  double cohesion = 0.0;         // Pa, initial c0
  // Largest mean stress p = I1/3 the material carries (Drucker-Prager); the
  // cone's apex k_c/(3 alpha) when larger or absent.
  double tension_cutoff = std::numeric_limits<double>::infinity();
  // Critical volume strain eps_c of the cohesion loss; 0 = cohesion is kept.
  double critical_volume_strain = 0.0;
  // Crack-band form of the same loss (Bazant & Oh 1983): the opening w_c (m)
  // at which a band one cell wide has lost its cohesion, so that
  // eps_c = w_c / (2 h) on a grid of cell size h and the work of opening a
  // crack does not shrink with the cell. 0 = use critical_volume_strain.
  double critical_opening = 0.0;
  // Length (m) over which the dilation that drives the loss is averaged
  // (nonlocal.hpp); 0 = local.
  double nonlocal_length = 0.0;
  double bulk_modulus = 0.0;  // Pa (fluid)
  double viscosity = 0.0;     // Pa s (fluid)
};

// Per-point state that the models read and write.
struct MaterialState {
  Mat3 stress = Mat3::Zero();
  Mat3 deformation = Mat3::Identity();  // F, for Neo-Hookean
  double plastic_strain = 0.0;          // accumulated equivalent plastic shear strain
  double cohesion = 0.0;                // current c (Pa)
  bool yielding = false;                // on the yield surface after the last step
};

struct ElasticConstants {
  double bulk = 0.0, shear = 0.0;
  static ElasticConstants from(double youngs, double poisson) {
    return {youngs / (3.0 * (1.0 - 2.0 * poisson)), youngs / (2.0 * (1.0 + poisson))};
  }
  double p_modulus() const { return bulk + 4.0 / 3.0 * shear; }
};

// The keys of every solid and of the frictional ones.
using MaterialKey = DeclaredKey<MaterialParams>;
inline constexpr std::array<MaterialKey, 2> kElasticKeys{
    required_key("youngs_modulus", &MaterialParams::youngs_modulus, positive()),
    required_key("poisson_ratio", &MaterialParams::poisson_ratio, between(-1.0, 0.5, true, true))};
inline constexpr std::array<MaterialKey, 6> kFrictionalKeys{
    required_key("friction_angle", &MaterialParams::friction_angle, between(0, 90, false, true),
                 KeyUnit::Degrees),
    optional_key("dilatancy_angle", &MaterialParams::dilatancy_angle, 0.0,
                 between(0, 90, false, true), KeyUnit::Degrees),
    optional_key("cohesion", &MaterialParams::cohesion, 0.0, non_negative()),
    optional_key("critical_volume_strain", &MaterialParams::critical_volume_strain, 0.0,
                 non_negative()),
    optional_key("critical_opening", &MaterialParams::critical_opening, 0.0, non_negative()),
    optional_key("nonlocal_length", &MaterialParams::nonlocal_length, 0.0, non_negative())};
// The checks across the frictional keys.
KeyProblem check_frictional(const MaterialParams& p);

// Hooke's law in rate form with the Jaumann rate (objective rotation first).
struct LinearElastic {
  static constexpr std::string_view name = "linear_elastic";
  static constexpr auto keys = kElasticKeys;
  static LinearElastic make(const MaterialParams& p);
  static KeyProblem check(const MaterialParams&) { return {}; }

  ElasticConstants k;
  double density;
  void update(MaterialState& s, const Mat3& l, double dt, double dv_over_v0) const;
  double wave_speed() const;
};

// Compressible Neo-Hookean, sigma = mu/J (B - I) + lambda ln J / J I, from F.
struct NeoHookean {
  static constexpr std::string_view name = "neo_hookean";
  static constexpr auto keys = kElasticKeys;
  static NeoHookean make(const MaterialParams& p);
  static KeyProblem check(const MaterialParams&) { return {}; }
  ElasticConstants k;
  double density;
  void update(MaterialState& s, const Mat3& l, double dt, double dv_over_v0) const;
  double wave_speed() const;
};

// Drucker-Prager cone fitted to Mohr-Coulomb (Bui et al. 2008, mpm.md):
// f = sqrt(J2) + alpha I1 - k_c, g = sqrt(J2) + 3 I1 sin(psi).
struct DruckerPrager {
  static constexpr std::string_view name = "drucker_prager";
  static constexpr auto keys = join(join(kElasticKeys, kFrictionalKeys),
                                    std::array<MaterialKey, 1>{optional_key(
                                        "tension_cutoff", &MaterialParams::tension_cutoff,
                                        std::numeric_limits<double>::infinity(), non_negative())});
  static DruckerPrager make(const MaterialParams& p);
  static KeyProblem check(const MaterialParams& p);
  ElasticConstants k;
  double density, phi, psi, c0, tension_cutoff, critical_volume_strain;
  static double alpha(double phi);
  static double kc(double phi, double cohesion);
  double yield(const Mat3& stress, double cohesion) const;
  // Elastic predictor, then the closed-form return to the cone (or its apex)
  // with the tension cut-off. Returns the plastic strain increment.
  Mat3 update_returning(MaterialState& s, const Mat3& l, double dt, double dv_over_v0) const;
  void update(MaterialState& s, const Mat3& l, double dt, double dv_over_v0) const {
    update_returning(s, l, dt, dv_over_v0);
  }
  double wave_speed() const;
};

// Mohr-Coulomb with the principal-stress return mapping of de Souza Neto et al.
// (2008, box 8.5): main plane, the two edges and the apex.
// f = (s1 - s3) + (s1 + s3) sin(phi) - 2 c cos(phi), s1 >= s2 >= s3.
struct MohrCoulomb {
  static constexpr std::string_view name = "mohr_coulomb";
  static constexpr auto keys = join(kElasticKeys, kFrictionalKeys);
  static MohrCoulomb make(const MaterialParams& p);
  static KeyProblem check(const MaterialParams& p) { return check_frictional(p); }
  ElasticConstants k;
  double density, phi, psi, c0, critical_volume_strain;
  double yield(const Mat3& stress, double cohesion) const;
  Mat3 update_returning(MaterialState& s, const Mat3& l, double dt, double dv_over_v0) const;
  void update(MaterialState& s, const Mat3& l, double dt, double dv_over_v0) const {
    update_returning(s, l, dt, dv_over_v0);
  }
  double wave_speed() const;
};

// Weakly compressible Newtonian fluid: sigma = -p I + 2 eta dev(D), with the
// pressure from the volume change (rate form, dp = -K tr(dEps)).
struct NewtonianFluid {
  static constexpr std::string_view name = "newtonian_fluid";
  static constexpr std::array<MaterialKey, 2> keys{
      required_key("bulk_modulus", &MaterialParams::bulk_modulus, positive()),
      optional_key("viscosity", &MaterialParams::viscosity, 0.0, non_negative())};
  static NewtonianFluid make(const MaterialParams& p);
  static KeyProblem check(const MaterialParams&) { return {}; }
  double bulk, viscosity, density;
  void update(MaterialState& s, const Mat3& l, double dt, double dv_over_v0) const;
  double wave_speed() const;
};

// The models a scenario may name, in the order messages list them: one entry
// per model.
using MaterialLaws = LawList<MohrCoulomb, DruckerPrager, LinearElastic, NeoHookean, NewtonianFluid>;
using Material = MaterialLaws::Variant;

// The model p.model names (which must be one of MaterialLaws).
Material make_material(const MaterialParams& p);
// The critical volume strain on a grid of cell size h (from critical_opening
// when it is set).
double critical_volume_strain(const MaterialParams& p, double cell_size);
double wave_speed(const Material& m);
double density(const Material& m);
// Initial cohesion c0 (0 for models without one: they do not read it).
double initial_cohesion(const MaterialParams& p);

// Cohesion loss of van den Bout et al. (2021) eq. 26 (mpm.md): while yielding,
// dc = -(c0 / (2 eps_c)) dV / V0 for dilation; permanent, never below 0.
inline void lose_cohesion(MaterialState& s, double c0, double eps_c, double dv_over_v0) {
  if (eps_c > 0.0 && s.cohesion > 0.0 && dv_over_v0 > 0.0)
    s.cohesion = std::max(0.0, s.cohesion - c0 / (2.0 * eps_c) * dv_over_v0);
}

}  // namespace talus::mpm
