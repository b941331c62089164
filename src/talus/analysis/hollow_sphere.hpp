#pragma once
// The hollow sphere of Götz 2024 §4.3 (spec/membranes-and-jamming.md): a
// rigid object of radius R_obj at the centre of a shell of grains closed by
// an outer membrane of radius R_out; the vacuum p_vac acts on the outer
// membrane (inwards) and on the object's membrane (outwards, the air between
// it and the object), and the grains pass on to the object the difference of
// the two membranes' forces. The object is the rigid core of its membrane
// (MembraneSpec::core_radius): it takes the inward force on the particles
// resting on it and never pulls, so where the grains carry the vacuum
// themselves the membrane lifts off and the object feels nothing there.
//
// This observer records, at each series time, into <out>/hollow_sphere.csv:
//   time, p_vac (ramped), p_obj (the object's normal force per area, net of
//   the vacuum's push on its membrane), the object's normal force F_n,
//   the outer membrane's mean radius and the grain-object contacts.
#include <filesystem>
#include <memory>
#include <nlohmann/json.hpp>
#include <vector>

#include "talus/dem/builder.hpp"
#include "talus/io/csv_writer.hpp"

namespace talus::analysis {

// Götz 2024 eq. (33), with the bracket the print lost (the spec's form):
//   p_obj = p_vac 2 (1 - x)(2 nu - 1) / (2 (1 - 2 nu) + x (1 + nu)),
//   x = (R_out / R_obj)^3,
// for a linear elastic shell of Poisson ratio nu bonded to a rigid core.
// Derived here from Lamé's u = A r + B / r^2 with u(R_obj) = 0 and
// sigma_rr(R_out) = -p_vac: the core carries -sigma_rr(R_obj) =
// p_vac 3 x (1 - nu) / (x (1 + nu) + 2 (1 - 2 nu)), of which the membrane
// between them takes p_vac back; the difference is the formula above.
// Limits checked (tests/analysis): nu -> 1/2 gives 0 (an incompressible
// shell on a rigid core cannot move, the pressure stays p_vac everywhere and
// the membrane's p_vac cancels it); x -> 1 gives 0 (no shell); nu = 0,
// x -> infinity gives 2 p_vac (3 p_vac, the stress concentration of a rigid
// inclusion in an infinite body, less p_vac). It does not depend on E.
double continuum_object_pressure(double p_vac, double r_out, double r_obj, double nu);

// Where the parts are in the system, and the constants of the comparison.
struct HollowSphereSetup {
  int object = -1, shell = -1;  // membrane indices
  Vec3 centre = Vec3::Zero();
  double r_object = 0.0, r_shell = 0.0;  // the core's and the shell's radii, m
  double p_vac = 0.0;                    // -shell pressure at full vacuum, Pa
  double ramp_end = 0.0;                 // s, when the vacuum is complete
  double poisson_ratio = 0.0;            // nu of eq. (33)
  // sum_i e_i . (force of a unit pressure on the faces) for the membrane
  // wrapped tightly round the core: the object_pressure calibration.
  double unit_pressure_load = 0.0;
};
// Throws InputError when a named membrane is missing.
HollowSphereSetup make_hollow_sphere_setup(const dem::DemScenario& sc, const dem::DemSystem<3>& s);

// The object's normal force per area: sum_i max(0, -f_i . e_i) over the
// particles resting on the core, e_i the unit radius, divided by
// unit_pressure_load. A uniform pressure q on the faces of the wrapped
// membrane so reads as q exactly, whatever the facets' tilt against the
// radii; the vacuum's push on the object's membrane is in f_i and so comes off.
double object_pressure(const dem::DemSystem<3>& s, const HollowSphereSetup& h);
// Mean distance of the outer membrane's particles from the centre.
double shell_mean_radius(const dem::DemSystem<3>& s, const HollowSphereSetup& h);

class HollowSphereObserver final {
 public:
  // resume = true continues the hollow_sphere.csv of a run resumed at
  // resume_time: the rows up to it are kept and read back for the plateau.
  HollowSphereObserver(std::filesystem::path out, const dem::DemScenario& sc,
                       const dem::DemSystem<3>& s, bool resume = false, double resume_time = 0.0);
  void on_series(const dem::DemRun<3>& run);
  void on_checkpoint(const dem::DemRun<3>& run);
  // p_vac, radii, nu, the continuum value, and p_obj at the end and as the
  // mean over the plateau (the second half of the time after the ramp).
  nlohmann::json finish() const;

 private:
  HollowSphereSetup setup_;
  std::unique_ptr<io::CsvSeries> csv_;
  std::vector<double> time_, p_obj_;
  double last_shell_radius_ = 0.0;
};

}  // namespace talus::analysis
