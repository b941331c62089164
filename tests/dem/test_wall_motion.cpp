// Moving walls and the neighbour list: a wall that travels more than the skin
// since the last build must trigger a rebuild, whatever the direction.
#include <gtest/gtest.h>

#include "talus/dem/builder.hpp"
#include "talus/dem/driver.hpp"
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
  DemScenario sc = scenario(3, ContactModel::HertzMindlin, 2e-6, Vec3::Zero());
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
  RunControl c;
  c.duration = 0.5 / frequency;
  c.ke_blowup_factor = 0.0;  // the wall feeds energy in
  run_dem<3>(*run, c, {}, true);
  const auto& p = run->system.particles;
  // The floor moves at up to 2 pi f A = 0.063 m/s; the struck sphere leaves downwards.
  EXPECT_LT(p.v[0].z(), -0.01);
  EXPECT_LT(p.x[0].z(), -amplitude - 0.5 * r);
}
