// DEM checkpoints (dem/checkpoint.cpp): a file of an older format version is
// refused with a message that says so, and the membranes' contact springs
// survive the save/restore round trip in the order the next step reads them.
// The whole-run check (kill, resume, same bytes) is tests/app/test_resume*.sh.
#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include "talus/core/error.hpp"
#include "talus/dem/checkpoint.hpp"
#include "talus/io/archive.hpp"

using namespace talus;
using namespace talus::dem;

TEST(DemCheckpoint, OlderVersionIsRefusedClearly) {
  const auto path = std::filesystem::temp_directory_path() / "talus_old_checkpoint.bin";
  io::ArchiveWriter w;
  w.put("talus-dem-checkpoint");
  w.put(int32_t{3});  // the format before membranes and servo state
  w.save(path);
  DemSystem<3> s;
  std::string message;
  try {
    load_checkpoint(s, path);
  } catch (const InputError& e) {
    message = e.what();
  }
  std::filesystem::remove(path);
  EXPECT_NE(message.find("checkpoint format version 3"), std::string::npos) << message;
  EXPECT_NE(message.find("rerun from the start"), std::string::npos) << message;
}

// Springs stored in several lanes, saved and restored into a fresh memory:
// the next step finds the same springs for the same contacts.
TEST(DemCheckpoint, MembraneSpringsRoundTrip) {
  using membrane::ContactMemory;
  using membrane::Feature;
  using membrane::TriangleContact;
  ContactMemory a;
  a.begin_step(3);
  auto contact = [](int feature, double x) {
    TriangleContact c;
    c.kind = Feature::Face;
    c.feature = feature;
    c.triangle = feature;
    c.point = Vec3(x, 0, 0);
    return c;
  };
  for (int g = 0; g < 6; ++g) {
    ContactHistory<3> h;
    h.shear = Vec3(g, 2 * g, 0.5);
    a.store(g, contact(g + 10, 0.1 * g), h, g % 3);
  }
  ContactMemory b;
  b.restore(a.saved());
  EXPECT_EQ(b.size(), 6u);
  a.begin_step(3);
  b.begin_step(3);
  for (int g = 0; g < 6; ++g) {
    const TriangleContact c[1] = {contact(g + 10, 0.1 * g)};
    const Vec3 sa = a.springs(g, c, 1.0)[0].shear;
    const Vec3 sb = b.springs(g, c, 1.0)[0].shear;
    EXPECT_EQ(sa, sb);
    EXPECT_EQ(sb, Vec3(g, 2 * g, 0.5));
  }
}
