#pragma once
// What a barrier designer reads off a flume run (spec: flume.md "What a flume
// run must report"), measured from particle positions along the flume path:
// the front, the run-up, the deposit surface and where the main deposit starts.
// Pure functions of positions and radii, so the DEM run, the depth-averaged
// models and the tests all measure the same way.
#include <vector>

#include "talus/geometry/flume.hpp"

namespace talus::analysis {

using geometry::Vec2;

// A cloud of grains (2D, per metre of flume width).
struct Grains {
  std::vector<Vec2> x;
  std::vector<double> r;
};

// Where the flow has got to. The front is the `quantile` of the particles'
// path coordinates rather than the single farthest grain, so that a few
// bouncing grains ahead of the flow do not count as the front (the lab front
// was read off video, to +-1 cm).
struct FrontSample {
  double front_s = 0.0;       // path coordinate from the gate foot, m
  Vec2 front = Vec2::Zero();  // path point at front_s
  // Run-up: how far the front has climbed the barrier (0 before it gets
  // there): path distance beyond the end of the arc, and elevation of the
  // barrier surface at the front above the lowest point of the flume.
  double runup_s = 0.0;
  double runup_height = 0.0;
  int on_chute = 0;  // grains upstream of the end of the chute
};

FrontSample measure_front(const geometry::FlumeGeometry& g, const Grains& grains, double quantile);

// The deposit surface along the path in bins of `bin` metres: for each bin the
// thickness normal to the path (from the bed to the top of the highest grain)
// and the surface point, the top of that grain.
struct ProfileBin {
  double s_low = 0.0, s_high = 0.0;  // path coordinates of the bin's ends
  int count = 0;                     // grains whose centre projects into the bin
  double thickness = 0.0;            // m, 0 when empty
  Vec2 surface = Vec2::Zero();       // top of the top grain (bed point at the centre if empty)
};

std::vector<ProfileBin> deposit_profile(const geometry::FlumeGeometry& g, const Grains& grains,
                                        double bin);

// Where the main deposit starts: going upstream from the thickest bin, the
// lower end of the last bin of the unbroken run thicker than min_thickness.
// Grains upstream of it are stranded. Returns the s of the thickest bin's
// lower end when even that bin is thinner than min_thickness.
double deposit_tail(const std::vector<ProfileBin>& profile, double min_thickness);

// Lowest elevation of the flume bed (on the arc): the datum of run-up heights.
double bed_low_point(const geometry::FlumeGeometry& g);

}  // namespace talus::analysis
