#pragma once
// Pairs of points closer than a cutoff, by a cell list: points binned into cubes of side
// `cutoff`, each pair found by looking at the 27 cells around a point. The cells are not
// stored as a dense grid (a long flume with small grains would need billions of cells): the
// points are sorted by cell key and a cell is found by binary search, so memory is O(N) and
// time O(N log N + pairs). For analyses after a run, not for the solver's hot loop.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <numeric>
#include <vector>

#include "talus/core/space.hpp"

namespace talus::analysis {

class CellList {
 public:
  // cutoff > 0 and finite points (std::invalid_argument otherwise; callers check their input).
  CellList(const std::vector<Vec3>& points, double cutoff);

  // Calls f(i, j, distance) once for every pair i < j with |x_i - x_j| < cutoff.
  template <class F>
  void for_each_pair(F&& f) const;

  // Calls f(j, distance) for every point j != i with |x_j - x_i| < cutoff.
  template <class F>
  void for_each_neighbour(std::size_t i, F&& f) const;

 private:
  using Key = std::array<int64_t, 3>;
  Key key_of(const Vec3& x) const;
  // Range [first, last) in order_ of the points in the cell with this key.
  std::pair<std::size_t, std::size_t> cell(const Key& k) const;

  const std::vector<Vec3>& points_;
  double cutoff_;
  Vec3 origin_;
  std::vector<Key> keys_;           // key of order_[n], sorted
  std::vector<std::size_t> order_;  // point indices sorted by key
};

template <class F>
void CellList::for_each_neighbour(std::size_t i, F&& f) const {
  const Key k = key_of(points_[i]);
  const double c2 = cutoff_ * cutoff_;
  for (int64_t a = -1; a <= 1; ++a)
    for (int64_t b = -1; b <= 1; ++b)
      for (int64_t c = -1; c <= 1; ++c) {
        const auto [first, last] = cell({k[0] + a, k[1] + b, k[2] + c});
        for (std::size_t n = first; n < last; ++n) {
          const std::size_t j = order_[n];
          if (j == i) continue;
          const double d2 = (points_[j] - points_[i]).squaredNorm();
          if (d2 < c2) f(j, std::sqrt(d2));
        }
      }
}

template <class F>
void CellList::for_each_pair(F&& f) const {
  for (std::size_t i = 0; i < points_.size(); ++i)
    for_each_neighbour(i, [&](std::size_t j, double d) {
      if (j > i) f(i, j, d);
    });
}

}  // namespace talus::analysis
