// Writes a small known set of snapshots for tests/io/vtk_readback.py, which
// reads them back with VTK itself (the reader ParaView uses). Every value is a
// simple formula of the particle index i and the time t, repeated in the
// Python test. It lives in tests/io/tools/ so the test_io glob leaves it out.
#include <cstdio>
#include <exception>

#include "talus/io/vtk_writer.hpp"

namespace {

talus::io::ParticleFrame sample_particles(double t) {
  constexpr int kCount = 5;
  talus::io::ParticleFrame frame;
  for (int i = 0; i < kCount; ++i) {
    frame.position.emplace_back(i + t, 2.0 * i, -1.0 * i);
    frame.velocity.emplace_back(t, i, -1.5);
    frame.angular_velocity.emplace_back(0.0, 0.0, 10.0 * i + t);
    frame.radius.push_back(0.01 * (i + 1) + 0.001 * t);
    frame.id.push_back(1000 + i);
    frame.material.push_back(i % 2);
    frame.contacts.push_back(i);
    frame.extra_scalars["layer"].push_back(0.5 * i);
  }
  return frame;
}

talus::io::WallFrame sample_walls() {
  talus::io::WallFrame frame;
  frame.points = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}};
  frame.lines = {{0, 1}, {1, 2}};
  frame.line_wall = {0, 0};
  frame.triangles = {{0, 1, 2}, {0, 2, 3}};
  frame.triangle_wall = {1, 2};
  return frame;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc != 2) {
    std::fprintf(stderr, "usage: %s OUTPUT_DIR\n", argv[0]);
    return 2;
  }
  try {
    talus::io::PvdSeries particles(argv[1], "particles");
    for (double t : {0.0, 0.5, 1.0, 1.5}) particles.add(t, sample_particles(t));
    // As on resume from a checkpoint at t = 1: the frame at 1.5 must go.
    particles.truncate_after(1.0);
    talus::io::PvdSeries walls(argv[1], "walls");
    walls.add(0.0, sample_walls());
  } catch (const std::exception& error) {
    std::fprintf(stderr, "vtk_sample: %s\n", error.what());
    return 1;
  }
  return 0;
}
