#include "talus/dem/neighbour_list.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "talus/core/error.hpp"

namespace talus::dem {

template <int D>
void NeighbourList<D>::build(Particles<D>& p, const std::vector<geometry::Primitive>& prims,
                             double skin) {
  skin_ = skin;
  // Keep the old lists, indexed by the particle order before this build's
  // re-sort; carry_history finds each new contact's old one through the
  // permutation, in O(1) per contact.
  old_pairs_.swap(pairs);
  old_pair_shear_.swap(pair_shear);
  old_pair_roll_.swap(pair_roll);
  old_wall_start_.swap(wall_start);
  old_wall_prim_.swap(wall_prim);
  old_wall_history_.swap(wall_history);
  const int n_old = static_cast<int>(p.size());
  if (old_wall_start_.size() != static_cast<std::size_t>(n_old) + 1)
    old_wall_start_.assign(n_old + 1, 0);
    // The steps of a build run as OpenMP tasks where they are independent: when
    // the build runs inside `omp single`, the waiting threads take them.
#pragma omp task default(shared)
  {
    old_row_start_.assign(n_old + 1, 0);
    for (const Pair& q : old_pairs_) ++old_row_start_[std::min(q.i, q.j) + 1];
    for (int i = 0; i < n_old; ++i) old_row_start_[i + 1] += old_row_start_[i];
    old_rows_.resize(old_pairs_.size());
    std::vector<int> fill(old_row_start_.begin(), old_row_start_.end() - 1);
    for (std::size_t k = 0; k < old_pairs_.size(); ++k)
      old_rows_[fill[std::min(old_pairs_[k].i, old_pairs_[k].j)]++] = static_cast<int>(k);
  }
  double r_max = 0.0;
  for (double r : p.r) r_max = std::max(r_max, r);
  const double cell = std::max(2.0 * r_max + skin, 1e-12);
  sort_into_cells(p, cell);  // fills order_; waits for the task above
#pragma omp task default(shared)
  find_walls(p, prims);
#pragma omp task default(shared)
  x_ref_ = p.x;
  find_pairs(p, cell);  // waits for the two tasks above
  carry_history(p);
  ++builds;
}

template <int D>
void NeighbourList<D>::sort_into_cells(Particles<D>& p, double cell) {
  const int n = static_cast<int>(p.size());
  Vec lo = Vec::Constant(std::numeric_limits<double>::max());
  Vec hi = Vec::Constant(std::numeric_limits<double>::lowest());
  for (int i = 0; i < n; ++i) {
    if (!p.x[i].allFinite())
      throw RunError("particle " + std::to_string(p.id[i]) +
                     " has a non-finite position: the run became unstable");
    lo = lo.cwiseMin(p.x[i]);
    hi = hi.cwiseMax(p.x[i]);
  }
  if (n == 0) lo = hi = Vec::Zero();
  // Keep the grid bounded for sparse systems: at most ~8 cells per particle.
  double h = cell;
  for (;;) {
    double cells = 1.0;
    for (int d = 0; d < D; ++d) cells *= std::floor((hi[d] - lo[d]) / h) + 1.0;
    if (cells <= 8.0 * n + 64.0) break;
    h *= 1.26;
  }
  lo_ = lo;
  std::size_t total = 1;
  for (int d = 0; d < 3; ++d) {
    dims_[d] = d < D ? static_cast<int>(std::floor((hi[d] - lo[d]) / h)) + 1 : 1;
    total *= dims_[d];
  }
  std::vector<int> cell_of(n);
  cell_start_.assign(total + 1, 0);
  for (int i = 0; i < n; ++i) {
    int c = 0;
    for (int d = D - 1; d >= 0; --d)
      c = c * dims_[d] + std::min(dims_[d] - 1, static_cast<int>((p.x[i][d] - lo[d]) / h));
    cell_of[i] = c;
    ++cell_start_[c + 1];
  }
  for (std::size_t c = 0; c < total; ++c) cell_start_[c + 1] += cell_start_[c];
  std::vector<int> order(n), fill(cell_start_.begin(), cell_start_.end() - 1);
  for (int i = 0; i < n; ++i) order[fill[cell_of[i]]++] = i;
  p.permute(order);
  order_.swap(order);
  cell_size_ = h;
}

template <int D>
void NeighbourList<D>::find_pairs(const Particles<D>& p, double) {
  // Half stencil: each pair of neighbouring cells is visited once.
  std::vector<std::array<int, 3>> stencil;
  for (int dz = (D == 3 ? -1 : 0); dz <= (D == 3 ? 1 : 0); ++dz)
    for (int dy = -1; dy <= 1; ++dy)
      for (int dx = -1; dx <= 1; ++dx) {
        const std::array<int, 3> s{dx, dy, dz};
        // Keep offsets that are lexicographically positive (z, y, x) or zero.
        const bool positive = dz > 0 || (dz == 0 && (dy > 0 || (dy == 0 && dx >= 0)));
        if (positive) stencil.push_back(s);
      }
  // The cells are cut into chunks searched as OpenMP tasks: when the build
  // runs inside `omp single` the waiting threads take them. The chunks are
  // joined in cell order, so the list is the same for any thread count.
  const int total = dims_[0] * dims_[1] * dims_[2];
  const int chunks = std::min(total, 16);
  std::vector<std::vector<Pair>> found(chunks);
  const Vec* x = p.x.data();
  const double* r = p.r.data();
  const int* start = cell_start_.data();
  const double skin = skin_;
  for (int t = 0; t < chunks; ++t) {
#pragma omp task default(shared) firstprivate(t)
    {
      auto& out = found[t];
      std::size_t m = 0;  // pairs found; out is kept larger and cut at the end
      const int c0 = static_cast<int>(static_cast<int64_t>(total) * t / chunks);
      const int c1 = static_cast<int>(static_cast<int64_t>(total) * (t + 1) / chunks);
      int lo[27], hi[27];
      for (int c = c0; c < c1; ++c) {
        if (start[c] == start[c + 1]) continue;  // most cells of a spreading flow are empty
        const int cx = c % dims_[0], cy = (c / dims_[0]) % dims_[1], cz = c / (dims_[0] * dims_[1]);
        // The particle ranges of the stencil's cells inside the grid; the
        // first entry is the cell itself, searched from i + 1.
        int ranges = 0, candidates = 0;
        for (const auto& s : stencil) {
          const int nx = cx + s[0], ny = cy + s[1], nz = cz + s[2];
          if (nx < 0 || ny < 0 || nz < 0 || nx >= dims_[0] || ny >= dims_[1] || nz >= dims_[2])
            continue;
          const int nc = (nz * dims_[1] + ny) * dims_[0] + nx;
          lo[ranges] = start[nc];
          hi[ranges] = start[nc + 1];
          candidates += hi[ranges] - lo[ranges];
          ++ranges;
        }
        for (int i = start[c]; i < start[c + 1]; ++i) {
          if (out.size() < m + candidates) out.resize(2 * (m + candidates) + 64);
          Pair* o = out.data();
          const Vec xi = x[i];
          const double ri = r[i];
          for (int q = 0; q < ranges; ++q) {
            // Every candidate is written; only a neighbour advances m (the
            // test is close to random, a branch would mispredict).
            for (int j = q == 0 ? i + 1 : lo[q]; j < hi[q]; ++j) {
              const double cut = ri + r[j] + skin;
              o[m] = {i, j};
              m += (xi - x[j]).squaredNorm() < cut * cut ? 1 : 0;
            }
          }
        }
      }
      out.resize(m);
    }
  }
#pragma omp taskwait
  pairs.clear();
  for (const auto& f : found) pairs.insert(pairs.end(), f.begin(), f.end());
}

template <int D>
void NeighbourList<D>::find_walls(const Particles<D>& p,
                                  const std::vector<geometry::Primitive>& prims) {
  // Each primitive visits only the cells its box (grown by r_max + skin)
  // overlaps, so a mesh of many small triangles costs what it covers, not
  // particles x triangles. Candidates are collected per primitive, then grouped
  // by particle with a stable counting sort: per particle they stay in
  // primitive order, as the contact history expects.
  const int n = static_cast<int>(p.size());
  double r_max = 0.0;
  for (double r : p.r) r_max = std::max(r_max, r);
  std::vector<std::pair<int, int>> found;  // (particle, primitive)
  for (std::size_t k = 0; k < prims.size(); ++k) {
    Vec3 lo, hi;
    geometry::bounds(prims[k], lo, hi);
    int c0[3] = {0, 0, 0}, c1[3] = {0, 0, 0};
    for (int d = 0; d < D; ++d) {
      const double grow = r_max + skin_;
      const double a = (lo[d] - grow - lo_[d]) / cell_size_,
                   b = (hi[d] + grow - lo_[d]) / cell_size_;
      c0[d] =
          std::isfinite(a) ? static_cast<int>(std::clamp(std::floor(a), 0.0, dims_[d] - 1.0)) : 0;
      c1[d] = std::isfinite(b) ? static_cast<int>(std::clamp(std::floor(b), 0.0, dims_[d] - 1.0))
                               : dims_[d] - 1;
      if (b < 0.0 || a > dims_[d]) c1[d] = c0[d] - 1;  // entirely outside the grid
    }
    // A long slanted segment or a plane has a box of many cells, most of them
    // far from it: a cell whose centre is farther than r_max + skin plus half
    // its diagonal holds no candidate (the distance to a primitive changes no
    // faster than the point moves), and is skipped after one test. Not for the
    // one-sided cylinder, whose test fails beyond its surface at any distance.
    const bool prune = prims[k].kind != geometry::PrimitiveKind::Cylinder;
    const double cell_reach = r_max + skin_ + (0.5 * std::sqrt(double(D)) + 1e-3) * cell_size_;
    for (int cz = c0[2]; cz <= c1[2]; ++cz)
      for (int cy = c0[1]; cy <= c1[1]; ++cy)
        for (int cx = c0[0]; cx <= c1[0]; ++cx) {
          const int c = (cz * dims_[1] + cy) * dims_[0] + cx;
          if (cell_start_[c] == cell_start_[c + 1]) continue;
          if (prune) {
            const int cell_index[3] = {cx, cy, cz};
            Vec centre;
            for (int d = 0; d < D; ++d) centre[d] = lo_[d] + (cell_index[d] + 0.5) * cell_size_;
            geometry::Closest<D> near;
            if (!geometry::closest_point<D>(prims[k], centre, cell_reach, near)) continue;
          }
          for (int i = cell_start_[c]; i < cell_start_[c + 1]; ++i) {
            geometry::Closest<D> hit;
            if (geometry::closest_point<D>(prims[k], p.x[i], p.r[i] + skin_, hit))
              found.push_back({i, static_cast<int>(k)});
          }
        }
  }
  wall_start.assign(n + 1, 0);
  for (const auto& f : found) ++wall_start[f.first + 1];
  for (int i = 0; i < n; ++i) wall_start[i + 1] += wall_start[i];
  wall_prim.resize(found.size());
  std::vector<int> fill(wall_start.begin(), wall_start.end() - 1);
  for (const auto& f : found) wall_prim[fill[f.first]++] = f.second;
}

template <int D>
void NeighbourList<D>::carry_history(const Particles<D>&) {
  pair_shear.resize(pairs.size());
  pair_roll.resize(pairs.size());
  wall_history.assign(wall_prim.size(), ContactHistory<D>{});
  // Chunks of pairs (and the walls) as OpenMP tasks, like the pair search:
  // each new contact is looked up on its own, so any split gives the same lists.
  const std::size_t np = pairs.size();
  const int chunks = 8;
  for (int t = 0; t < chunks; ++t) {
#pragma omp task default(shared) firstprivate(t)
    {
      const std::size_t k0 = np * t / chunks, k1 = np * (t + 1) / chunks;
      for (std::size_t k = k0; k < k1; ++k) {
        pair_shear[k] = zero_of<Vec>();
        pair_roll[k] = Space<D>::rot_zero();
        const int oi = order_[pairs[k].i], oj = order_[pairs[k].j];
        const int lo = std::min(oi, oj), hi = std::max(oi, oj);
        for (int q = old_row_start_[lo]; q < old_row_start_[lo + 1]; ++q) {
          const Pair& old = old_pairs_[old_rows_[q]];
          if (old.i + old.j - lo != hi) continue;
          // The spring is relative motion of i against j: swapping them flips it.
          const double sign = old.i != oi ? -1.0 : 1.0;
          pair_shear[k] = sign * old_pair_shear_[old_rows_[q]];
          pair_roll[k] = sign * old_pair_roll_[old_rows_[q]];
          break;
        }
      }
    }
  }
#pragma omp task default(shared)
  for (std::size_t i = 0; i + 1 < wall_start.size(); ++i) {
    const int oi = order_[i];
    for (int k = wall_start[i]; k < wall_start[i + 1]; ++k)
      for (int q = old_wall_start_[oi]; q < old_wall_start_[oi + 1]; ++q)
        if (old_wall_prim_[q] == wall_prim[k]) {
          wall_history[k] = old_wall_history_[q];
          break;
        }
  }
#pragma omp taskwait
}

template class NeighbourList<2>;
template class NeighbourList<3>;

}  // namespace talus::dem
