#pragma once
// Membranes in MPM (mpm.md "Membranes in MPM"; Hamad et al. 2012/2014): a thin
// tension-only sheet (a geotextile) that moves with the background grid like
// the material points. By default it shares its velocity field with the soil
// (no slip); with a soil friction it moves in a field of its own, in Coulomb
// contact with the soil's (field_contact.hpp), so sand slips along it.
// Two models, chosen by name:
//  - York et al. (1999): a single line of material points; the stress acts
//    along the tangent t only, sigma = E eps_tt t (x) t, no compression; the
//    tangent and the stretch of each point follow the velocity gradient of
//    the grid, like any material line element (dl = L dl dt).
//  - The coupled FE membrane (Hamad): a chain of 2-node cables whose nodes move
//    like material points; each cable's tension comes from its own nodes,
//    T = J max(eps, 0), eps = l / l0 - 1, J = E t, and the nodal forces are
//    mapped to the grid. In 3D the FE membrane is a surface of 3-node
//    tension-only triangles instead (membrane_triangle.hpp): a sheet, or a
//    closed box or sphere surface (a bag), meshed by membrane_surface.cpp.
// In 2D everything is per metre of depth: J in N/m, the mass in kg per m of
// line per m of depth (kg/m^2, areal_mass), tension T in N/m. In 3D J is in
// N/m, the mass per area in kg/m^2 (areal_mass) and T is per unit width, N/m.
// York's model is 2D only.
#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "talus/core/space.hpp"
#include "talus/mpm/membrane_triangle.hpp"

namespace talus::mpm {

enum class MembraneModel { FiniteElement, York };

// Which ends of an open membrane are held in place (Edges: the whole boundary
// of a 3D sheet).
enum class MembraneFixed { None, First, Last, Both, Edges };

// What a membrane is drawn as: a polyline (2D), or in 3D a sheet (the
// bilinear surface of 4 corners), the surface of a box, or a sphere.
enum class MembraneShape { Polyline, Sheet, Box, Sphere };

// A membrane as read from a scenario: a polyline (closed or not) resampled to
// nodes `spacing` apart along each edge, or a 3D surface meshed into
// triangles with edges about `spacing` long.
struct MembraneParams {
  std::string name;
  MembraneModel model = MembraneModel::FiniteElement;
  MembraneShape shape = MembraneShape::Polyline;
  std::vector<Vec3> points;  // the polyline, or the sheet's 4 corners in order
  Vec3 box_min = Vec3::Zero(), box_max = Vec3::Zero();  // Box
  Vec3 centre = Vec3::Zero();                           // Sphere
  double radius = 0.0;
  double poisson_ratio = 0.0;  // of the 3D triangles
  bool closed = false;
  double spacing = 0.0;     // m along the polyline; <= 0: half a cell
  double stiffness = 0.0;   // J = E t, N/m
  double areal_mass = 0.0;  // kg/m^2 (2D: per m of line and m of depth)
  MembraneFixed fixed = MembraneFixed::None;
  // Slack (folds, Hamad's "extra material at the bag bottom"): the rest length
  // of the cables whose midpoints lie in the box is (1 + slack) times their
  // length as drawn, so they carry no tension until stretched by that much
  // (3D: the triangles whose centroids lie in it, scaled alike).
  double slack = 0.0;
  bool slack_everywhere = true;  // else only inside [slack_min, slack_max]
  Vec3 slack_min = Vec3::Zero(), slack_max = Vec3::Zero();
  Vec3 velocity = Vec3::Zero();
  // Scenario key `friction`: < 0 (absent) the membrane shares the soil's
  // velocity field; >= 0 its own field, Coulomb mu against the soil.
  double soil_friction = -1.0;
};

template <int D>
struct Membrane {
  using Vec = typename Space<D>::Vec;
  using Mat = Eigen::Matrix<double, D, D>;

  std::string name;
  MembraneModel model = MembraneModel::FiniteElement;
  bool closed = false;
  double stiffness = 0.0;       // J, N/m
  double areal_mass = 0.0;      // mu, kg/m^2 (2D: per m of line and m of depth)
  double poisson_ratio = 0.0;   // 3D surfaces
  double soil_friction = -1.0;  // MembraneParams::soil_friction
  bool own_field() const { return soil_friction >= 0.0; }

  // Nodes (FE) or material points (York).
  std::vector<Vec> x, v;
  std::vector<double> mass;
  std::vector<char> fixed;  // held in place
  // FE: rest length of cable k, from node k to node k + 1 (mod n if closed).
  // York: rest length each point stands for (half of each neighbouring cable).
  std::vector<double> rest_length;
  // York only: unit tangent, stretch (current / rest length of the point's
  // line element) and the velocity gradient of the last step.
  std::vector<Vec> tangent;
  std::vector<double> stretch;
  std::vector<Mat> velocity_gradient;
  // 3D FE surfaces: the triangles' nodes, rest shapes and rest areas (slack
  // included). Empty for cables and York lines.
  std::vector<std::array<uint32_t, 3>> triangles;
  std::vector<Eigen::Matrix2d> rest_inverse;
  std::vector<double> rest_area;

  std::size_t size() const { return x.size(); }
  bool surface() const { return !triangles.empty(); }
  // Number of tension carriers: cables (FE), points (York) or triangles.
  std::size_t carriers() const;
  // Strain and tension J max(eps, 0) of carrier k; for a triangle its larger
  // principal strain and tension (membrane_triangle.hpp).
  double strain(std::size_t k) const;
  double tension(std::size_t k) const;
  double max_tension() const;
  // Mean tension weighted by rest length (triangles: rest area).
  double mean_tension() const;
  // FE: the forces of the cables or triangles on their nodes, added to f
  // (size()).
  void add_cable_forces(std::vector<Vec>& f) const;
  // York: advances tangent and stretch with the velocity gradient over dt.
  void update_york_strain(double dt);
  // Speed of tension waves along the membrane, sqrt(J / mu) (surfaces:
  // sqrt(J / ((1 - nu^2) mu)), the in-plane P wave).
  double wave_speed() const;
  double total_mass() const;
  // Unit normals at the nodes (points): in 2D the line's right-hand normal,
  // outward for a closed line whichever way it was drawn; in 3D the mean of
  // the triangles' normals around the node, outward for a closed surface.
  // An open membrane's normal has no preferred side (the contact orients it).
  void node_normals(std::vector<Vec>& n) const;
};

// Nodes (FE) or points (York) of a membrane: the polyline resampled to the
// spacing, rest lengths with the slack, masses from areal_mass; in 3D
// the meshed surface (build_surface_membrane). Throws InputError for a
// polyline of zero length or a spacing that leaves an edge without a node.
template <int D>
Membrane<D> build_membrane(const MembraneParams& p, double cell_size);

// A 3D FE surface (shape Sheet, Box or Sphere), membrane_surface.cpp.
Membrane<3> build_surface_membrane(const MembraneParams& p, double cell_size);

}  // namespace talus::mpm
