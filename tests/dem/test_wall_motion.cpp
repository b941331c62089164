// Moving walls and the neighbour list: a wall that travels more than the skin
// since the last build must trigger a rebuild, whatever the direction.
#include <gtest/gtest.h>

#include "support/dem_loop.hpp"
#include "talus/core/error.hpp"
#include "talus/dem/builder.hpp"
#include "talus/dem/contact/laws.hpp"
#include "talus/geometry/stl.hpp"
#include "verification_cases.hpp"

using namespace talus;
using namespace talus::dem;
using namespace talus::dem::verification;

// A floor vibrating z = A sin(2 pi f t + 90 deg) starts at its top (+A) and
// sinks to -A at t = 1/(2f), travelling 20 skins. A sphere hanging (no
// gravity) below the floor's lowest position by less than its radius, far out
// of the neighbour list at t = 0, must be found and hit on the way down.
TEST(WallMotion, VibratingWallFindsParticlesOnEitherSide) {
  const double r = 1e-3, amplitude = 2e-3, frequency = 5.0;
  DemScenario sc = scenario(3, HertzMindlin::name, 2e-6, Vec3::Zero());
  sc.materials = {hertz_material("glass", 2500, 1e7, 0.3, 0.5, 0.5), rigid_material("steel")};
  WallParams floor = floor_wall<3>("steel");
  floor.motion.amplitude = amplitude;
  floor.motion.frequency = frequency;
  floor.motion.phase = M_PI / 2;
  floor.motion.direction = Vec3::UnitZ();
  sc.walls.push_back(floor);
  // Centre 0.5 r below the lowest floor position minus r: overlap 0.5 r at t = 0.1 s.
  add_balls(sc, {ball(Vec3(0, 0, -amplitude - 0.5 * r), Vec3::Zero(), r, "glass")});
  auto run = build_dem<3>(sc, {});
  run::DemControl c;
  c.duration = 0.5 / frequency;  // the energy check stays on: the wall's work is in its budget
  test::run_dem<3>(*run, c);
  const auto& p = run->system.particles;
  // The floor moves at up to 2 pi f A = 0.063 m/s; the struck sphere leaves downwards.
  EXPECT_LT(p.v[0].z(), -0.01);
  EXPECT_LT(p.x[0].z(), -amplitude - 0.5 * r);
}

// A floor rising at u strikes a sphere at rest (no gravity, no damping): the
// sphere leaves at 2u (an elastic bounce off an infinitely heavy wall), so the
// wall has done the work 1/2 m (2u)^2 = 2 m u^2 on it. Wall::work integrates
// -force . v over the steps; velocity Verlet conserves the collision's energy
// to O(dt^2) (~200 steps per Hertz contact here), hence 1e-3 relative.
TEST(WallWork, RisingFloorDoesTheWorkOfAnElasticBounce) {
  const double r = 1e-3, u = 0.5;
  DemScenario sc = scenario(3, HertzMindlin::name, 1e-6, Vec3::Zero());
  sc.materials = {hertz_material("glass", 2500, 1e7, 0.3, 1.0, 0.0), rigid_material("steel")};
  WallParams floor = floor_wall<3>("steel");
  floor.motion.velocity = Vec3(0, 0, u);
  sc.walls.push_back(floor);
  add_balls(sc, {ball(Vec3(0, 0, 1.2 * r), Vec3::Zero(), r, "glass")});
  auto run = build_dem<3>(sc, {});
  run::DemControl c;
  c.duration = 2e-3;  // contact at 0.4 ms, lasting ~0.2 ms
  test::run_dem<3>(*run, c);
  const auto& s = run->system;
  const double m = s.particles.m[0];
  EXPECT_NEAR(s.particles.v[0].z(), 2 * u, 1e-3 * 2 * u);
  EXPECT_NEAR(s.walls[0].work, 2 * m * u * u, 1e-3 * 2 * m * u * u);
}

// A wall fast enough to push particles through itself within one contact is
// refused before the run: at 1000 m/s a sphere of 1 mm would be pressed ~20 mm
// into the floor (v sqrt(m/k) with the Hertz stiffness at that speed).
TEST(WallWork, WallTooFastForTheContactsIsRefused) {
  const double r = 1e-3;
  DemScenario sc = scenario(3, HertzMindlin::name, 0.0, Vec3(0, 0, -9.81));
  sc.materials = {hertz_material("glass", 2500, 1e7, 0.3, 0.5, 0.5), rigid_material("steel")};
  WallParams floor = floor_wall<3>("steel");
  floor.motion.velocity = Vec3(0, 0, 1000);
  sc.walls.push_back(floor);
  add_balls(sc, {ball(Vec3(0, 0, 1.2 * r), Vec3::Zero(), r, "glass")});
  try {
    build_dem<3>(sc, {});
    FAIL() << "a wall at 1000 m/s was accepted";
  } catch (const InputError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("walls.0.motion"), std::string::npos) << what;
    EXPECT_NE(what.find("pass through"), std::string::npos) << what;
  }
  // At 1 m/s the same floor is accepted.
  sc.walls[0].motion.velocity = Vec3(0, 0, 1);
  EXPECT_NO_THROW(build_dem<3>(sc, {}));
}

// A floor given as an STL mesh of 800 small triangles acts like the plane it
// tiles: the same rebound, and the neighbour list offers the sphere only the
// few triangles near it (the primitives are binned into the cell grid).
TEST(MeshWall, TiledFloorBouncesLikeAPlaneAndFindsOnlyNearbyTriangles) {
  const double r = 1e-3, cell = 0.01;
  std::vector<geometry::Primitive> tris;
  for (int i = 0; i < 20; ++i)
    for (int j = 0; j < 20; ++j) {
      const Vec3 a(i * cell - 0.1, j * cell - 0.1, 0),
          b = a + Vec3(cell, 0, 0), c = a + Vec3(cell, cell, 0), d = a + Vec3(0, cell, 0);
      geometry::Primitive t1, t2;
      ASSERT_TRUE(geometry::make_triangle(a, b, c, t1));
      ASSERT_TRUE(geometry::make_triangle(a, c, d, t2));
      tris.push_back(t1);
      tris.push_back(t2);
    }
  const std::string stl = ::testing::TempDir() + "/tiled_floor.stl";
  geometry::write_stl(stl, tris, true);

  auto rebound = [&](bool mesh, std::size_t* candidates, Vec3 at = Vec3(0.0033, 0.0071, 0)) {
    DemScenario sc = scenario(3, HertzMindlin::name, 1e-6, Vec3::Zero());
    sc.materials = {hertz_material("glass", 2500, 1e7, 0.3, 0.5, 0.5), rigid_material("steel")};
    if (mesh) {
      WallParams w;
      w.name = "floor";
      w.kind = WallKind::Mesh;
      w.material = "steel";
      w.file = stl;
      sc.walls.push_back(w);
    } else {
      sc.walls.push_back(floor_wall<3>("steel"));
    }
    // At `at`: by default inside one triangle, far from its edges compared with
    // the contact radius (~0.1 mm).
    add_balls(sc, {ball(at + Vec3(0, 0, 1.05 * r), Vec3(0, 0, -0.1), r, "glass")});
    auto run = build_dem<3>(sc, {});
    run::DemControl c;
    c.duration = 2e-3;
    test::run_dem<3>(*run, c);
    if (candidates) {
      const auto& nl = run->system.neighbours;
      *candidates = static_cast<std::size_t>(nl.wall_start[1] - nl.wall_start[0]);
    }
    return run->system.particles.v[0].z();
  };
  std::size_t candidates = 0;
  const double on_plane = rebound(false, nullptr), on_mesh = rebound(true, &candidates);
  EXPECT_GT(on_plane, 0.04);  // it did bounce (e = 0.5 of 0.1 m/s)
  // 1e-12 m/s: the plane and the triangle give the same contact up to the
  // round-off of the closest-point arithmetic (~1e-16 relative over 2000 steps).
  EXPECT_NEAR(on_mesh, on_plane, 1e-12);
  EXPECT_GE(candidates, 1u);
  EXPECT_LE(candidates, 8u);  // of 800
  // Straight above a vertex shared by six triangles, the middle of an edge
  // shared by two and the middle of a diagonal: one contact each, so the same
  // rebound as on the plane (counted per triangle it would be 6 or 2 times
  // stiffer, and rebound differently).
  const std::pair<Vec3, std::size_t> points[] = {
      {Vec3(0, 0, 0), 6}, {Vec3(0.005, 0, 0), 2}, {Vec3(0.005, 0.005, 0), 2}};
  for (const auto& [at, sharing] : points) {
    std::size_t near = 0;
    EXPECT_NEAR(rebound(true, &near, at), rebound(false, nullptr, at), 1e-12) << at.transpose();
    EXPECT_GE(near, sharing) << at.transpose();  // every triangle sharing the point was a candidate
  }
}

// Settling happens before t = 0 with every wall in place, even a gate removed
// at t = 0 (Kuen's variant I): the packing must still be behind the gate when
// the run starts, and the gate must be gone after it.
TEST(Settling, GateRemovedAtStartHoldsThePackingWhileItSettles) {
  const double gate_x = 0.03;
  DemScenario sc = scenario(2, LinearSpringDashpot::name, 0.0, Vec3(0, -9.81, 0));
  sc.materials = {linear_material("sand", 2672, 1e6, 1e6, 0.5, 0.3),
                  linear_material("steel", 1.0, 1e6, 1e6, 0.5, 0.4)};
  sc.walls.push_back(floor_wall<2>("steel"));
  WallParams back = flat_wall<2>("back", "steel", Vec3::Zero(), Vec3::UnitX());
  WallParams gate = flat_wall<2>("gate", "steel", Vec3(gate_x, 0, 0), -Vec3::UnitX());
  gate.motion.remove_at = 0.0;
  sc.walls.push_back(back);
  sc.walls.push_back(gate);
  ParticleSourceParams fill;
  fill.kind = SourceKind::RandomFill;
  fill.material = "sand";
  fill.box_min = Vec3(0, 0, 0);
  fill.box_max = Vec3(gate_x, 0.06, 0);
  fill.radius_min = 1e-3;
  fill.radius_max = 1.5e-3;
  fill.porosity = 0.25;
  fill.settle.enabled = true;
  fill.settle.max_time = 0.3;
  sc.sources.push_back(fill);
  auto run = build_dem<2>(sc, {});
  const auto& p = run->system.particles;
  ASSERT_GT(p.size(), 50u);
  EXPECT_GT(run->system.settle_time, 0.05);
  for (std::size_t i = 0; i < p.size(); ++i) EXPECT_LT(p.x[i].x() + p.r[i], gate_x + 1e-4);
  // After the release the column spreads past the gate's former place.
  run::DemControl c;
  c.duration = 0.3;
  test::run_dem<2>(*run, c);
  EXPECT_GT(front_x(run->system.particles), gate_x + 0.01);
}
