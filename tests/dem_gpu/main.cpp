// test_dem_gpu's main: with TALUS_TEST_BACKEND=gpu and no usable GPU every
// test is skipped, saying why.
#include <gtest/gtest.h>

#include <cstdio>

#include "dem_gpu/test_backend.hpp"

namespace {

class NeedsDevice : public ::testing::Environment {
 public:
  void SetUp() override {
    const auto d = talus::dem::gpu::device();
    if (!d.usable) GTEST_SKIP() << "GPU backend tests skipped: " << d.description;
    std::printf("[gpu] running on %s\n", d.description.c_str());
  }
};

}  // namespace

int main(int argc, char** argv) {
  ::testing::InitGoogleTest(&argc, argv);
  if (talus::dem::test::on_device()) ::testing::AddGlobalTestEnvironment(new NeedsDevice);
  return RUN_ALL_TESTS();
}
