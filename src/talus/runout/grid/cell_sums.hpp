#pragma once
// Sums over a grid solver's cells, in cell order (the same bits every run).
#include <vector>

namespace talus::runout {

inline double cell_sum(const std::vector<double>& q) {
  double sum = 0.0;
  for (double x : q) sum += x;
  return sum;
}

}  // namespace talus::runout
