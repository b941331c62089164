#include "talus/dem/hertz_pairs.hpp"

#include <cmath>

#include "talus/dem/pair_blocks.hpp"

namespace talus::dem {

namespace {

using pair_blocks::kBlock;

// Structure of arrays of one block: inputs gathered from the particles and the
// pair list, results scattered back. Coefficients are per lane, as the
// material pair may change from pair to pair.
struct alignas(64) Block {
  double dx[kBlock], dy[kBlock], dz[kBlock], d2[kBlock];  // x_i - x_j
  double ri[kBlock], rj[kBlock], mi[kBlock], mj[kBlock];
  double vx[kBlock], vy[kBlock], vz[kBlock];  // v_i - v_j
  double wix[kBlock], wiy[kBlock], wiz[kBlock], wjx[kBlock], wjy[kBlock], wjz[kBlock];
  double sx[kBlock], sy[kBlock], sz[kBlock];  // shear displacement: in, then out
  double e_star[kBlock], g_star[kBlock], mu[kBlock], damp_n[kBlock], t_ratio[kBlock];
  double fx[kBlock], fy[kBlock], fz[kBlock];  // force on i
  double tix[kBlock], tiy[kBlock], tiz[kBlock], tjx[kBlock], tjy[kBlock], tjz[kBlock];
  int i[kBlock], j[kBlock];
  std::size_t k[kBlock];
  int n = 0;

  // The lane hooks of pair_blocks::flush.
  void gather(int l, const Particles<3>& p) {
    const int pi = i[l], pj = j[l];
    mi[l] = p.m[pi];
    mj[l] = p.m[pj];
    const Vec3 vrel = p.v[pi] - p.v[pj];
    vx[l] = vrel.x();
    vy[l] = vrel.y();
    vz[l] = vrel.z();
    wix[l] = p.w[pi].x();
    wiy[l] = p.w[pi].y();
    wiz[l] = p.w[pi].z();
    wjx[l] = p.w[pj].x();
    wjy[l] = p.w[pj].y();
    wjz[l] = p.w[pj].z();
  }
  void set_coeffs(int l, const HertzMindlin::Coeffs& c) {
    e_star[l] = c.h.e_star;
    g_star[l] = c.h.g_star;
    mu[l] = c.h.mu;
    damp_n[l] = c.damp_n;
    t_ratio[l] = c.tangential_ratio;
  }
  void scatter(int l, const ForceTarget<3>& out, std::vector<Vec3>& shear) const {
    out.add(i[l], j[l], Vec3(fx[l], fy[l], fz[l]), Vec3(tix[l], tiy[l], tiz[l]),
            Vec3(tjx[l], tjy[l], tjz[l]));
    shear[k[l]] = Vec3(sx[l], sy[l], sz[l]);
  }
};

// pair_force + HertzMindlin::compute of stepper.cpp, lane by lane; the
// comments name the scalar expressions each line reproduces.
TALUS_HOT void block_body(Block& b, double dt) {
  const int n = b.n;
#pragma omp simd
  for (int l = 0; l < n; ++l) {
    const double dist = std::sqrt(b.d2[l]);
    const double inv = 1.0 / dist;
    const double nx = b.dx[l] * inv, ny = b.dy[l] * inv, nz = b.dz[l] * inv;
    const double overlap = (b.ri[l] + b.rj[l]) - dist;
    const double ci = b.ri[l] - 0.5 * overlap, cj = b.rj[l] - 0.5 * overlap;
    const double r_eff = b.ri[l] * b.rj[l] / (b.ri[l] + b.rj[l]);
    const double m_eff = b.mi[l] * b.mj[l] / (b.mi[l] + b.mj[l]);
    // vn = vrel.n; vt = vrel - vn n - (ci w_i + cj w_j) x n
    const double vn = (b.vx[l] * nx + b.vy[l] * ny) + b.vz[l] * nz;
    const double wx = ci * b.wix[l] + cj * b.wjx[l];
    const double wy = ci * b.wiy[l] + cj * b.wjy[l];
    const double wz = ci * b.wiz[l] + cj * b.wjz[l];
    const double vtx = (b.vx[l] - vn * nx) - (wy * nz - wz * ny);
    const double vty = (b.vy[l] - vn * ny) - (wz * nx - wx * nz);
    const double vtz = (b.vz[l] - vn * nz) - (wx * ny - wy * nx);
    // HertzMindlin::compute
    const double sqrt_rd = std::sqrt(r_eff * overlap);
    const double st = 8.0 * b.g_star[l] * sqrt_rd;
    const double kn = (4.0 / 3.0) * b.e_star[l] * sqrt_rd;
    const double gn = b.damp_n[l] * std::sqrt(m_eff * sqrt_rd);
    const double gt = gn * b.t_ratio[l];
    const double fn = kn * overlap - gn * vn;
    double sx = b.sx[l] + vtx * dt, sy = b.sy[l] + vty * dt, sz = b.sz[l] + vtz * dt;
    const double sn = (sx * nx + sy * ny) + sz * nz;
    sx = sx - sn * nx;
    sy = sy - sn * ny;
    sz = sz - sn * nz;
    const double cap = b.mu[l] * std::abs(fn);
    const double spring2 = st * st * ((sx * sx + sy * sy) + sz * sz);
    const bool sliding = spring2 > cap * cap;
    const double scale = cap / std::sqrt(spring2);  // used only while sliding
    sx = sliding ? sx * scale : sx;
    sy = sliding ? sy * scale : sy;
    sz = sliding ? sz * scale : sz;
    const double ftx = sliding ? -st * sx : -st * sx - gt * vtx;
    const double fty = sliding ? -st * sy : -st * sy - gt * vty;
    const double ftz = sliding ? -st * sz : -st * sz - gt * vtz;
    b.sx[l] = sx;
    b.sy[l] = sy;
    b.sz[l] = sz;
    // f = fn n + ft; torque tq = -n x ft at lever arms ci, cj
    b.fx[l] = fn * nx + ftx;
    b.fy[l] = fn * ny + fty;
    b.fz[l] = fn * nz + ftz;
    const double tqx = -(ny * ftz - nz * fty);
    const double tqy = -(nz * ftx - nx * ftz);
    const double tqz = -(nx * fty - ny * ftx);
    b.tix[l] = ci * tqx;
    b.tiy[l] = ci * tqy;
    b.tiz[l] = ci * tqz;
    b.tjx[l] = cj * tqx;
    b.tjy[l] = cj * tqy;
    b.tjz[l] = cj * tqz;
  }
}

using Kernel = pair_blocks::Kernel<Block, block_body>;
using BlockFn = Kernel::Fn;

}  // namespace

const char* hertz_pairs_isa() { return Kernel::chosen().name; }

int64_t hertz_scatter_pairs(const HertzPairsInput& in, std::size_t k0, std::size_t k1,
                            const ForceTarget<3>& out) {
  const auto& p = *in.particles;
  auto& nl = *in.neighbours;
  const auto& pairs = nl.pairs;
  auto& shear = nl.pair_shear;
  const BlockFn fn = Kernel::chosen().fn;
  // On the stack (its arrays are written before they are read): as a
  // thread_local, position-independent code (the Python module links these
  // libraries) kept its address in a register the loop needed, and the step
  // took 15 % longer (bench/peer_talus.sh).
  Block b;
  b.n = 0;
  if (in.n_materials == 1)
    for (int l = 0; l < kBlock; ++l) b.set_coeffs(l, in.coeffs[0]);
  // Whether a pair touches is close to random from one pair to the next, so
  // the filter has no branch: every pair is written into the next free slot,
  // which only a touching pair keeps. Its shear moves into the block and the
  // list's entry is zeroed (a pair that does not touch has no history); the
  // block writes the new shear back.
  int64_t touching = 0;
  for (std::size_t k = k0; k < k1; ++k) {
    const int i = pairs[k].i, j = pairs[k].j;
    const Vec3 d = p.x[i] - p.x[j];
    const double d2 = d.squaredNorm();
    const double rs = p.r[i] + p.r[j];
    const int l = b.n;
    b.i[l] = i;
    b.j[l] = j;
    b.k[l] = k;
    b.dx[l] = d.x();
    b.dy[l] = d.y();
    b.dz[l] = d.z();
    b.d2[l] = d2;
    b.ri[l] = p.r[i];
    b.rj[l] = p.r[j];
    b.sx[l] = shear[k].x();
    b.sy[l] = shear[k].y();
    b.sz[l] = shear[k].z();
    shear[k] = zero_of<Vec3>();
    const int touches = d2 >= rs * rs ? 0 : 1;  // as the scalar path (NaN counts as touching)
    b.n += touches;
    touching += touches;
    if (b.n == kBlock) pair_blocks::flush(b, in, fn, out);
  }
  if (b.n > 0) pair_blocks::flush(b, in, fn, out);
  return touching;
}

}  // namespace talus::dem
