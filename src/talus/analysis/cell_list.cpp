#include "talus/analysis/cell_list.hpp"

#include <stdexcept>

namespace talus::analysis {

CellList::CellList(const std::vector<Vec3>& points, double cutoff)
    : points_(points), cutoff_(cutoff), origin_(Vec3::Zero()) {
  if (!(cutoff > 0) || !std::isfinite(cutoff))
    throw std::invalid_argument("CellList: cutoff must be positive and finite");
  Vec3 hi = Vec3::Zero();
  if (!points.empty()) origin_ = hi = points.front();
  for (const Vec3& x : points) {
    if (!x.allFinite()) throw std::invalid_argument("CellList: a point is not finite");
    origin_ = origin_.cwiseMin(x);
    hi = hi.cwiseMax(x);
  }
  if (((hi - origin_) / cutoff).maxCoeff() > 1e15)  // keys stay far from int64 overflow
    throw std::invalid_argument("CellList: the points span more than 1e15 cells");
  keys_.reserve(points.size());
  order_.resize(points.size());
  std::iota(order_.begin(), order_.end(), std::size_t{0});
  std::vector<Key> key(points.size());
  for (std::size_t i = 0; i < points.size(); ++i) key[i] = key_of(points[i]);
  std::sort(order_.begin(), order_.end(), [&](std::size_t a, std::size_t b) {
    return key[a] < key[b] || (key[a] == key[b] && a < b);
  });
  for (std::size_t n : order_) keys_.push_back(key[n]);
}

CellList::Key CellList::key_of(const Vec3& x) const {
  Key k;
  for (int d = 0; d < 3; ++d)
    k[d] = static_cast<int64_t>(std::floor((x[d] - origin_[d]) / cutoff_));
  return k;
}

std::pair<std::size_t, std::size_t> CellList::cell(const Key& k) const {
  const auto range = std::equal_range(keys_.begin(), keys_.end(), k);
  return {static_cast<std::size_t>(range.first - keys_.begin()),
          static_cast<std::size_t>(range.second - keys_.begin())};
}

}  // namespace talus::analysis
