// The vectorised pair loop of the 2D linear spring-dashpot (dem/linear_pairs.hpp)
// against the scalar path it replaces (pair_force in dem/stepper.cpp with
// LinearSpringDashpot::compute): on random disks and pairs, touching or not,
// sticking and sliding, with one or two materials and with the dashpot allowed
// to pull or not, forces, torques, contact counts and shear history must agree
// bit for bit (the block loop does the same IEEE operations in the same order).
#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <random>
#include <string>

#include "talus/dem/contact/laws.hpp"
#include "talus/dem/contact/linear.hpp"
#include "talus/dem/linear_pairs.hpp"
#include "talus/dem/pair_kinematics.hpp"
#include "verification_cases.hpp"

using namespace talus;
using namespace talus::dem;

namespace {

using Vec2 = Space<2>::Vec;

// The scalar path: the stepper's pair kinematics (dem/pair_kinematics.hpp)
// and the law, added to `out` as Stepper::scatter_pairs does. Counts the sliding, sticking and
// pulling contacts, so the test can check that it covers them.
struct Cover {
  int sliding = 0, sticking = 0, pulling = 0;
};
int64_t scalar_pairs(const Particles<2>& p, NeighbourList<2>& nl,
                     const std::vector<LinearSpringDashpot::Coeffs>& coeffs, int n_mat, double dt,
                     std::size_t k0, std::size_t k1, const ForceTarget<2>& out, Cover& cover) {
  int64_t touching = 0;
  for (std::size_t k = k0; k < k1; ++k) {
    const int i = nl.pairs[k].i, j = nl.pairs[k].j;
    const Vec2 d = p.x[i] - p.x[j];
    const double d2 = d.squaredNorm();
    const double rs = p.r[i] + p.r[j];
    if (d2 >= rs * rs) {
      nl.pair_shear[k] = Vec2::Zero();
      continue;
    }
    const auto pk = pair_kinematics<2, false>(p, i, j, d, d2);
    const auto& kin = pk.kin;
    ContactForce<2> cf;
    ContactHistory<2> h{nl.pair_shear[k], 0.0};
    LinearSpringDashpot::compute(coeffs[p.material[i] * n_mat + p.material[j]], kin, h, dt, cf);
    nl.pair_shear[k] = h.shear;
    const bool slides = h.shear == cf.ft && kin.vt.squaredNorm() > 0.0;
    cover.sliding += slides;
    cover.sticking += !slides;
    cover.pulling += cf.fn <= 0.0;
    const auto r = pair_result(pk, cf);
    out.add(i, j, r.f, r.ti, r.tj);
    ++touching;
  }
  return touching;
}

// Force arrays of one path: particle arrays and a thread buffer, as a
// ForceTarget sees them.
struct Forces {
  std::vector<Vec2> f, f_shared;
  std::vector<double> t, t_shared;
  std::vector<int> c, c_shared;
  explicit Forces(std::size_t n)
      : f(n, Vec2::Zero()),
        f_shared(n, Vec2::Zero()),
        t(n, 0.0),
        t_shared(n, 0.0),
        c(n, 0),
        c_shared(n, 0) {}
  ForceTarget<2> target(int own_lo, int own_hi) {
    return {f.data(), t.data(), c.data(), f_shared.data(), t_shared.data(), c_shared.data(),
            own_lo,   own_hi,   0};
  }
};

template <class T>
bool same_bits(const std::vector<T>& a, const std::vector<T>& b) {
  return a.size() == b.size() && std::memcmp(a.data(), b.data(), a.size() * sizeof(T)) == 0;
}

struct Case {
  int materials;
  bool may_pull;
};

class LinearPairs : public ::testing::TestWithParam<Case> {};

TEST_P(LinearPairs, BlockLoopEqualsScalarLawBitForBit) {
  const Case cs = GetParam();
  std::mt19937_64 rng(42 + cs.materials + 10 * cs.may_pull);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  // 600 disks of radius 1-2 mm (the flume's) in a 4 cm square: about half of
  // the candidate pairs below touch, with overlaps from 0 to a few mm.
  const int n = 600;
  Particles<2> p;
  for (int i = 0; i < n; ++i) {
    const double r = 1e-3 + 1e-3 * u(rng);
    p.add(Vec2(0.04 * u(rng), 0.04 * u(rng)), Vec2(4 * u(rng) - 2, 4 * u(rng) - 2),
          400 * u(rng) - 200, r, 2000 + 1000 * u(rng), cs.materials > 1 ? i % 2 : 0, i);
  }
  // A head-on pair of disks that do not spin, apart from the rest, without
  // shear history: no tangential force at all.
  p.add(Vec2(0.1029, 0.1), Vec2(-1.0, 0.0), 0.0, 1.5e-3, 2500, 0, n);
  p.add(Vec2(0.1, 0.1), Vec2(1.0, 0.0), 0.0, 1.5e-3, 2500, 0, n + 1);
  // Candidate pairs as the neighbour list keeps them: closer than r_i + r_j
  // plus a skin of 1 mm.
  NeighbourList<2> nl;
  std::uniform_int_distribution<int> kind(0, 3);
  for (int i = 0; i < n + 2; ++i)
    for (int j = i + 1; j < n + 2; ++j) {
      const double rs = p.r[i] + p.r[j] + 1e-3;
      if ((p.x[i] - p.x[j]).squaredNorm() >= rs * rs) continue;
      nl.pairs.push_back({i, j});
      // Shear history: none, small (sticking), large (sliding); any direction,
      // so rotating it into the contact plane matters.
      const Vec2 dir(u(rng) - 0.5, u(rng) - 0.5);
      const int k = kind(rng);
      nl.pair_shear.push_back(k == 0 ? Vec2(Vec2::Zero()) : Vec2((k == 1 ? 1.0 : 1e4) * dir));
    }
  nl.pair_shear.back() = Vec2::Zero();  // the head-on pair (the last one)
  nl.pair_roll.assign(nl.pairs.size(), 0.0);
  // Stiffnesses and damping as the flume's sand (1e8 N/m, beta 0.5) and a
  // softer, less damped second material, so that mixed pairs differ.
  const std::vector<MaterialParams> mats = {
      verification::linear_material("sand", 2672, 1e8, 1e8, 0.5, 0.28),
      verification::linear_material("soft", 2672, 3e6, 1e6, 0.2, 0.4)};
  ContactParams cp;
  cp.model = LinearSpringDashpot::name;
  cp.dashpot_may_pull = cs.may_pull;
  const int m = cs.materials;
  std::vector<LinearSpringDashpot::Coeffs> coeffs;
  for (int a = 0; a < m; ++a)
    for (int b = 0; b < m; ++b)
      coeffs.push_back(
          LinearSpringDashpot::make(cp, mats[a], mats[b], pair_coefficients(cp, mats[a], mats[b])));
  const double dt = 3.5e-6;  // the flume's step

  // Two chunks, as two threads would share the pairs; particles outside
  // [own_lo, own_hi] go to the shared buffer.
  const std::size_t np = nl.pairs.size(), half = np / 2;
  const int own_lo = n / 4, own_hi = 3 * n / 4;
  NeighbourList<2> nl_ref = nl;
  Forces ref(n + 2), blk(n + 2);
  Cover cover;
  const int64_t touch_ref =
      scalar_pairs(p, nl_ref, coeffs, m, dt, 0, half, ref.target(own_lo, own_hi), cover) +
      scalar_pairs(p, nl_ref, coeffs, m, dt, half, np, ref.target(own_lo, own_hi), cover);
  const LinearPairsInput in{&p, &nl, coeffs.data(), m, dt};
  const int64_t touch_blk = linear_scatter_pairs(in, 0, half, blk.target(own_lo, own_hi)) +
                            linear_scatter_pairs(in, half, np, blk.target(own_lo, own_hi));

  // The random set covers what the law distinguishes.
  EXPECT_GT(touch_ref, 1000);
  EXPECT_LT(touch_ref, static_cast<int64_t>(np));
  EXPECT_GT(cover.sliding, 100);
  EXPECT_GT(cover.sticking, 100);
  EXPECT_GT(cover.pulling, 10);

  EXPECT_EQ(touch_blk, touch_ref);
  EXPECT_TRUE(same_bits(blk.f, ref.f));
  EXPECT_TRUE(same_bits(blk.f_shared, ref.f_shared));
  EXPECT_TRUE(same_bits(blk.t, ref.t));
  EXPECT_TRUE(same_bits(blk.t_shared, ref.t_shared));
  EXPECT_EQ(blk.c, ref.c);
  EXPECT_EQ(blk.c_shared, ref.c_shared);
  EXPECT_TRUE(same_bits(nl.pair_shear, nl_ref.pair_shear));
  // The head-on pair (particles n, n + 1, both in the shared buffer): no
  // tangential force, no torque, in both paths.
  EXPECT_EQ(blk.f_shared[n].y(), 0.0);
  EXPECT_EQ(blk.t_shared[n], 0.0);
  EXPECT_NE(blk.f_shared[n].x(), 0.0);  // they do touch
  // Only the instruction set chosen at run time is exercised (AVX-512 on the
  // machines this was written on); the other two compile from the same body.
  const std::string isa = linear_pairs_isa();
  EXPECT_TRUE(isa == "avx512f" || isa == "avx2" || isa == "sse2") << isa;
}

INSTANTIATE_TEST_SUITE_P(Materials, LinearPairs,
                         ::testing::Values(Case{1, true}, Case{1, false}, Case{2, true},
                                           Case{2, false}),
                         [](const auto& info) {
                           return std::to_string(info.param.materials) + "materials_" +
                                  (info.param.may_pull ? "pull" : "nopull");
                         });

}  // namespace
