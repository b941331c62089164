#pragma once
// The 3D column collapse of the peer benchmark (../shared/peers/README.md §1),
// built in code so the DEM tests do not depend on the scenario parser.
#include "talus/dem/contact/laws.hpp"
#include "talus/dem/params.hpp"

namespace talus::dem::cases {

inline DemScenario peer_column(int nx, int ny, int nz) {
  const double a = 0.00201, d = 0.002;
  DemScenario sc;
  sc.name = "peer_column";
  sc.run.dimension = 3;
  sc.run.time_step = 5e-6;
  sc.run.gravity = Vec3(0, 0, -9.81);
  sc.run.skin = 0.0002;
  sc.run.domain_min = Vec3::Zero();
  sc.run.domain_max = Vec3(6 * nx * a, ny * a, 1.5 * nz * a);
  sc.contact.model = HertzMindlin::name;
  MaterialParams m;
  m.name = "glass";
  m.density = 2500;
  m.youngs_modulus = 1e7;
  m.poisson_ratio = 0.3;
  m.restitution = 0.5;
  m.friction = 0.5;
  sc.materials.push_back(m);
  auto plane = [&](const char* name, Vec3 point, Vec3 normal) {
    WallParams w;
    w.name = name;
    w.kind = WallKind::Plane;
    w.material = "glass";
    w.point = point;
    w.normal = normal;
    sc.walls.push_back(w);
  };
  plane("floor", Vec3::Zero(), Vec3::UnitZ());
  plane("back", Vec3::Zero(), Vec3::UnitX());
  plane("side0", Vec3::Zero(), Vec3::UnitY());
  plane("side1", Vec3(0, ny * a, 0), -Vec3::UnitY());
  ParticleSourceParams src;
  src.kind = SourceKind::Lattice;
  src.material = "glass";
  src.box_min = Vec3::Zero();
  src.box_max = Vec3(nx * a, ny * a, nz * a);
  src.spacing = a;
  src.radius = d / 2;
  src.jitter = "peer";
  sc.sources.push_back(src);
  return sc;
}

}  // namespace talus::dem::cases
