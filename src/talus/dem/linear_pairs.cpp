#include "talus/dem/linear_pairs.hpp"

#include <cmath>

#include "talus/dem/pair_blocks.hpp"

namespace talus::dem {

namespace {

using pair_blocks::kBlock;

using Vec2 = Space<2>::Vec;

// Structure of arrays of one block: inputs gathered from the particles and the
// pair list, results scattered back. Coefficients are per lane, as the
// material pair may change from pair to pair.
struct alignas(64) Block {
  double dx[kBlock], dy[kBlock], d2[kBlock];  // x_i - x_j
  double ri[kBlock], rj[kBlock], mi[kBlock], mj[kBlock];
  double vx[kBlock], vy[kBlock], wi[kBlock], wj[kBlock];  // v_i - v_j; omega_i, omega_j
  double sx[kBlock], sy[kBlock];                          // shear force: in, then out
  double kn[kBlock], ks[kBlock], beta[kBlock], mu[kBlock];
  double no_pull[kBlock];  // 1 where the dashpot may not pull (!may_pull)
  double fx[kBlock], fy[kBlock], ti[kBlock], tj[kBlock];  // force on i; torques
  int i[kBlock], j[kBlock];
  std::size_t k[kBlock];
  int n = 0;

  // The lane hooks of pair_blocks::flush.
  void gather(int l, const Particles<2>& p) {
    const int pi = i[l], pj = j[l];
    mi[l] = p.m[pi];
    mj[l] = p.m[pj];
    const Vec2 vrel = p.v[pi] - p.v[pj];
    vx[l] = vrel.x();
    vy[l] = vrel.y();
    wi[l] = p.w[pi];
    wj[l] = p.w[pj];
  }
  void put(int l, int pi, int pj, std::size_t pk, const Vec2& d, double dd, double r_i, double r_j,
           const Vec2& s) {
    i[l] = pi;
    j[l] = pj;
    k[l] = pk;
    dx[l] = d.x();
    dy[l] = d.y();
    d2[l] = dd;
    ri[l] = r_i;
    rj[l] = r_j;
    sx[l] = s.x();
    sy[l] = s.y();
  }
  void set_coeffs(int l, const LinearSpringDashpot::Coeffs& c) {
    kn[l] = c.kn;
    ks[l] = c.ks;
    beta[l] = c.beta;
    mu[l] = c.mu;
    no_pull[l] = c.may_pull ? 0.0 : 1.0;
  }
  void scatter(int l, const ForceTarget<2>& out, std::vector<Vec2>& shear) const {
    out.add(i[l], j[l], Vec2(fx[l], fy[l]), ti[l], tj[l]);
    shear[k[l]] = Vec2(sx[l], sy[l]);
  }
};

// pair_force + LinearSpringDashpot::compute of stepper.cpp in 2D, lane by
// lane; the comments name the scalar expressions each line reproduces.
TALUS_HOT void block_body(Block& b, double dt) {
  const int n = b.n;
#pragma omp simd
  for (int l = 0; l < n; ++l) {
    const double dist = std::sqrt(b.d2[l]);
    const double inv = 1.0 / dist;
    const double nx = b.dx[l] * inv, ny = b.dy[l] * inv;
    const double overlap = (b.ri[l] + b.rj[l]) - dist;
    const double ci = b.ri[l] - 0.5 * overlap, cj = b.rj[l] - 0.5 * overlap;
    const double m_eff = b.mi[l] * b.mj[l] / (b.mi[l] + b.mj[l]);
    // vn = vrel.n; vt = vrel - vn n - cross(ci w_i + cj w_j, n), with
    // Space<2>::cross(w, n) = (-w n_y, w n_x)
    const double vn = b.vx[l] * nx + b.vy[l] * ny;
    const double warm = ci * b.wi[l] + cj * b.wj[l];
    const double vtx = (b.vx[l] - vn * nx) - (-warm * ny);
    const double vty = (b.vy[l] - vn * ny) - warm * nx;
    // LinearSpringDashpot::compute: 2.0 * beta * sqrt(...) is (2.0 * beta) * sqrt(...)
    const double two_beta = 2.0 * b.beta[l];
    const double cn = two_beta * std::sqrt(m_eff * b.kn[l]);
    double fn = b.kn[l] * overlap - cn * vn;
    fn = (b.no_pull[l] != 0.0 && fn < 0.0) ? 0.0 : fn;  // std::max(fn, 0.0)
    // rotate_into_plane: s - (s.n) n, rescaled to the old length (unless 0)
    double sx = b.sx[l], sy = b.sy[l];
    const double len2 = sx * sx + sy * sy;
    const double sn = sx * nx + sy * ny;
    const double px = sx - sn * nx, py = sy - sn * ny;
    const double p2 = px * px + py * py;
    const double keep = std::sqrt(len2 / p2);  // used only where p2 > 0
    const bool rotate = len2 != 0.0;
    const bool rescale = p2 > 0.0;
    sx = rotate ? (rescale ? px * keep : px) : sx;
    sy = rotate ? (rescale ? py * keep : py) : sy;
    // shear -= (ks dt) vt, capped by Coulomb
    const double ks_dt = b.ks[l] * dt;
    sx = sx - ks_dt * vtx;
    sy = sy - ks_dt * vty;
    const double cap = b.mu[l] * std::abs(fn);
    const double s2 = sx * sx + sy * sy;
    const bool sliding = s2 > cap * cap;
    const double scale = cap / std::sqrt(s2);  // used only while sliding
    sx = sliding ? sx * scale : sx;
    sy = sliding ? sy * scale : sy;
    const double ct = two_beta * std::sqrt(m_eff * b.ks[l]);
    const double ftx = sliding ? sx : sx - ct * vtx;
    const double fty = sliding ? sy : sy - ct * vty;
    b.sx[l] = sx;
    b.sy[l] = sy;
    // f = fn n + ft; tq = -cross(n, ft); ti = ci tq + roll (0), tj = cj tq - roll
    b.fx[l] = fn * nx + ftx;
    b.fy[l] = fn * ny + fty;
    const double tq = -(nx * fty - ny * ftx);
    b.ti[l] = ci * tq + 0.0;  // + 0.0 as the scalar path: turns -0 into +0
    b.tj[l] = cj * tq - 0.0;
  }
}

using Kernel = pair_blocks::Kernel<Block, block_body>;
using BlockFn = Kernel::Fn;

}  // namespace

const char* linear_pairs_isa() { return Kernel::chosen().name; }

int64_t linear_scatter_pairs(const LinearPairsInput& in, std::size_t k0, std::size_t k1,
                             const ForceTarget<2>& out) {
  const BlockFn fn = Kernel::chosen().fn;
  thread_local Block b;
  b.n = 0;
  if (in.n_materials == 1)
    for (int l = 0; l < kBlock; ++l) b.set_coeffs(l, in.coeffs[0]);
  return pair_blocks::scatter_touching(b, in, k0, k1, fn, out);
}

}  // namespace talus::dem
