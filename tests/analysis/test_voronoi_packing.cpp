// Local packing fraction from radical Voronoi cells (voro++): touching lattices give their
// packing fractions, the radical plane of two unequal spheres is their tangent plane, the cells
// fill the box, and 2D disks through the periodic slab.
#include <gtest/gtest.h>

#include <cmath>
#include <numeric>
#include <random>

#include "lattices.hpp"
#include "talus/analysis/rdf.hpp"
#include "talus/analysis/voronoi_packing.hpp"
#include "talus/core/error.hpp"

namespace talus::analysis {
namespace {

// voro++ cuts cells with a tolerance of ~1e-11 of the box; 1e-9 leaves margin.
constexpr double kTol = 1e-9;

TEST(VoronoiPacking, SimpleCubicIsPiOverSix) {
  // n^3 touching spheres: every cell is the cube a^3 (the box [-a/2, (n - 1/2) a] cuts the
  // outer cells exactly where their neighbours would), phi = (pi/6 a^3) / a^3. Interior: the
  // (n - 2)^3 grains whose cells do not reach the box.
  const double a = 1e-3;
  const test::Lattice l = test::simple_cubic(5, a);
  const LocalPacking p = voronoi_packing(l.position, l.radius, 3);
  for (std::size_t i = 0; i < l.position.size(); ++i)
    EXPECT_NEAR(p.solid_fraction[i], M_PI / 6, kTol) << i;
  EXPECT_EQ(p.interior, 27u);
  EXPECT_NEAR(p.mean_interior, M_PI / 6, kTol);
  EXPECT_NEAR(p.overall_interior, M_PI / 6, kTol);
  EXPECT_NEAR(p.overall_all, M_PI / 6, kTol);
  // A margin of 1.6 a keeps only the centre grain (the next ones are 1.5 a from the box).
  EXPECT_EQ(voronoi_packing(l.position, l.radius, 3, 1.6 * a).interior, 1u);
}

TEST(VoronoiPacking, FccInteriorIsPiOverThreeRootTwo) {
  // Interior FCC cells are rhombic dodecahedra of volume a^3/4: phi = pi / (3 sqrt 2) = 0.7405.
  const test::Lattice l = test::fcc(4, 1e-3);
  const LocalPacking p = voronoi_packing(l.position, l.radius, 3);
  EXPECT_GT(p.interior, 50u);
  for (std::size_t i = 0; i < l.position.size(); ++i)
    if (!p.boundary[i]) {
      EXPECT_NEAR(p.solid_fraction[i], M_PI / (3 * std::sqrt(2.0)), kTol) << i;
    }
  EXPECT_NEAR(p.mean_interior, 0.74048, 1e-5);
}

TEST(VoronoiPacking, RadicalPlaneOfUnequalSpheresIsTheirTangentPlane) {
  // Radii 1 and 0.5 touching along x (centres 0 and 1.5) in the box [-1, 2] x [-1, 1]^2: the
  // power |x - x_i|^2 - r_i^2 is equal at x = 1 (the tangent point), so the cells are
  // 3 x 2 x 2 split at x = 1: volumes 8 and 4 (a plain Voronoi cut at 0.75 would give 7 and 5).
  const LocalPacking p = voronoi_packing({Vec3(0, 0, 0), Vec3(1.5, 0, 0)}, {1.0, 0.5}, 3);
  EXPECT_NEAR(p.cell_volume[0], 8.0, kTol);
  EXPECT_NEAR(p.cell_volume[1], 4.0, kTol);
  EXPECT_NEAR(p.solid_fraction[0], 4.0 / 3.0 * M_PI / 8.0, kTol);
  EXPECT_EQ(p.interior, 0u);  // both cells reach the box
}

TEST(VoronoiPacking, CellsOfARandomPolydisperseSetFillTheBox) {
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  for (int dim : {2, 3}) {
    std::vector<Vec3> x;
    std::vector<double> r;
    for (int i = 0; i < 500; ++i) {
      x.push_back(Vec3(u(rng), u(rng), dim == 3 ? u(rng) : 0.0));
      r.push_back(0.005 + 0.02 * u(rng));
    }
    const LocalPacking p = voronoi_packing(x, r, dim);
    const auto [lo, hi] = grain_box(x, r, dim);
    const double box = dim == 3 ? (hi - lo).prod() : (hi - lo).head<2>().prod();
    double cells = 0.0;
    for (double v : p.cell_volume)
      if (!std::isnan(v)) cells += v;
    EXPECT_NEAR(cells, box, 1e-9 * box) << dim;
    EXPECT_GT(p.interior, 200u) << dim;  // 500 grains: most are inside
  }
}

TEST(VoronoiPacking, DisksOnSquareAndHexagonalLattices) {
  // 2D through the periodic slab: square lattice phi = pi/4 for every disk (as the cubic
  // case), hexagonal interior pi / (2 sqrt 3) = 0.9069 (cells: hexagons of area sqrt3/2 a^2).
  const double a = 1e-3;
  const test::Lattice sq = test::square(6, a), hex = test::hexagonal(10, 10, a);
  const LocalPacking s = voronoi_packing(sq.position, sq.radius, 2);
  for (double phi : s.solid_fraction) EXPECT_NEAR(phi, M_PI / 4, kTol);
  EXPECT_EQ(s.interior, 16u);
  EXPECT_NEAR(s.cell_volume[0], a * a, kTol * a * a);
  const LocalPacking h = voronoi_packing(hex.position, hex.radius, 2);
  EXPECT_GT(h.interior, 50u);
  for (std::size_t i = 0; i < hex.position.size(); ++i)
    if (!h.boundary[i]) {
      EXPECT_NEAR(h.solid_fraction[i], M_PI / (2 * std::sqrt(3.0)), kTol) << i;
    }
}

TEST(VoronoiPacking, RefusesNegativeMargin) {
  const test::Lattice l = test::simple_cubic(2, 1.0);
  EXPECT_THROW(voronoi_packing(l.position, l.radius, 3, -1.0), InputError);
  EXPECT_THROW(voronoi_packing(l.position, l.radius, 1), InputError);
}

}  // namespace
}  // namespace talus::analysis
