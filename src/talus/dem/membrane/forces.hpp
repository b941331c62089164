#pragma once
// Internal forces of a DEM membrane (spec/membranes-and-jamming.md, Götz 2024
// §3.2.1-3.2.4) as kernels over arrays: they read positions and velocities of
// the membrane particles and add to their forces, with no state of their own.
// The loops scatter to shared vertices, so they run on one thread;
// add_internal_forces_tasks computes the per-edge terms on several.
#include <array>
#include <cmath>
#include <span>
#include <vector>

#include "talus/dem/membrane/mesh.hpp"

namespace talus::dem::membrane {

// k_sp = (sqrt 3 / 2) E_m d: spring constant of a triangular lattice with
// hexagonal unit cell that has the in-plane Young's modulus E_m of a sheet of
// thickness d (eq. 16).
inline double spring_constant(double youngs_modulus, double thickness) {
  return 0.5 * std::sqrt(3.0) * youngs_modulus * thickness;
}

// Mass of each membrane particle: rho_m d times its barycentric area (a third
// of each adjacent triangle's rest area), so the particles carry exactly the
// sheet's mass rho_m d A. The source does not say how it assigns masses.
std::vector<double> vertex_masses(const Mesh& mesh, double density, double thickness);

// Rest state per edge: length r0 and sin(theta0 / 2) of the bending element
// (0 for boundary edges, which carry no bending element).
struct RestShape {
  std::vector<double> length;
  std::vector<double> sin_half_angle;
};
RestShape rest_shape(const Mesh& mesh, std::span<const Vec3> x);

// Stretching (eq. 15 with the sign corrected): on i,
//   F_i = -n [k (r - r0) + 2 gamma sqrt(k m_eff) n . (v_i - v_j)],  n = (r_i - r_j)/r,
// and -F_i on j; m_eff = m_i m_j / (m_i + m_j).
void add_stretching_forces(std::span<const Edge> edges, std::span<const double> rest_length,
                           double stiffness, double damping_ratio, std::span<const Vec3> x,
                           std::span<const Vec3> v, std::span<const double> mass,
                           std::span<Vec3> f);

// Bridson, Marino & Fedkiw (2003) bending element of the triangles (1,3,4) and
// (2,4,3) sharing the edge e = r4 - r3 (eqs. 17-25).
struct BendingElement {
  std::array<Vec3, 4> u;  // u_1 .. u_4; their sum is zero
  double theta;           // signed dihedral angle, atan2((n1 x n2) . e, n1 . n2)
  double sin_half;        // sin(theta / 2)
  double edge_length;     // |e|
  double shape_factor;    // |e|^2 / (|n1| + |n2|)
};
// False when a triangle has no area (the element then gives no force).
bool bending_element(const Vec3& r1, const Vec3& r2, const Vec3& r3, const Vec3& r4,
                     BendingElement& out);

// Bending forces on every interior edge (edge.a = r3, edge.b = r4, opp0 = r1,
// opp1 = r2):
//   elastic  F_i = k_el |e|^2 / (|n1| + |n2|) (sin(theta/2) - sin(theta0/2)) u_i
//   damping  F_i = -k_diss |e| (sum_j u_j . v_j) u_i.
// With Bridson's sign of theta, u_i = -d theta / d r_i, so the elastic force
// restores theta0 and sum_j u_j . v_j = -d theta / dt; the damping force's power
// -k_diss |e| (sum_j u_j . v_j)^2 is never positive whichever sign theta has.
void add_bending_forces(std::span<const Edge> edges, std::span<const double> rest_sin_half,
                        double k_elastic, double k_dissipative, std::span<const Vec3> x,
                        std::span<const Vec3> v, std::span<Vec3> f);

// Pressure difference p across the membrane (§3.2.4): each triangle gets
// F = A p n (n its unit right-hand normal, outwards for the generated closed
// meshes), a third to each vertex. p > 0 pushes along the normals (higher
// pressure behind them); a vacuum inside a closed membrane is p < 0.
void add_pressure_forces(std::span<const std::array<int, 3>> triangles, double pressure,
                         std::span<const Vec3> x, std::span<Vec3> f);

// Largest stable step of explicit (leapfrog / velocity Verlet) integration of
// the membrane alone, from per-particle sums: stiffness K_i (springs k_sp, and
// the linearised bending k_el |e|^2/(|n1|+|n2|) |u_i|^2 / 2) and damping C_i
// (2 gamma_sp sqrt(k_sp m_eff), and k_diss |e| |u_i|^2):
//   dt_c = min_i min(2 / sqrt(2 K_i / m_i), m_i / C_i)
// (Gershgorin bound on the stiffness, and the explicit damper's limit). Exact
// for two equal masses on one undamped spring. The bending damper can bind
// first on fine meshes: C_i / m_i grows as 1 / spacing^3.
double critical_time_step(std::span<const Edge> edges, std::span<const double> mass,
                          std::span<const Vec3> x, double stiffness, double damping_ratio,
                          double k_elastic, double k_dissipative);

// Material of a membrane, SI units as in the source (Götz 2024 Table 2).
struct MembraneParams {
  double youngs_modulus = 0;       // E_m [Pa]
  double thickness = 0;            // d [m]
  double density = 0;              // rho_m [kg/m^3]
  double spring_damping = 0;       // gamma_sp [-]
  double bending_elastic = 0;      // k_el
  double bending_dissipative = 0;  // k_diss
  double pressure = 0;             // p, see add_pressure_forces
};

// One membrane: mesh, rest state and the state of its particles. Fixed
// particles (e.g. the gripper's rim) keep their velocity; the integrator skips them.
struct Membrane {
  Mesh mesh;
  MembraneParams params;
  RestShape rest;
  std::vector<double> mass;
  std::vector<Vec3> x, v, f;
  std::vector<char> fixed;
  // Fixed particles that follow a wall's translation (the triaxial plates):
  // index into the run's walls, -1 for none; x = anchor + the wall's displacement.
  std::vector<int> follows;
  std::vector<Vec3> anchor;
};
// Rest state and masses from the mesh as it is; zero velocities.
Membrane make_membrane(Mesh mesh, const MembraneParams& params);
// Adds stretching, bending and pressure forces to m.f (does not clear it).
void add_internal_forces(Membrane& m);
// Per-edge forces of add_internal_forces_tasks, kept between calls.
struct EdgeForces {
  std::vector<Vec3> stretch;
  std::vector<std::array<Vec3, 4>> bend;
  std::vector<char> has_bend;
};
// The same forces, bit for bit: the per-edge work (norms, the bending
// geometry, atan2, sin) runs as OpenMP tasks into `buffer`, which the calling
// thread then adds to m.f in add_internal_forces' order. Inside a parallel
// region the team's waiting threads take the tasks; outside, the caller runs them.
void add_internal_forces_tasks(Membrane& m, EdgeForces& buffer);
double critical_time_step(const Membrane& m);

}  // namespace talus::dem::membrane
