#pragma once
// How a grid's rows are shared among ranks: rank r computes the rows
// [first(r), first(r + 1)), the rows split as evenly as they go (the first
// rows % ranks ranks one row more).
#include <cstddef>
#include <vector>

namespace talus::comm {

struct RowBlocks {
  int rows = 0, ranks = 1;

  int first(int r) const {
    const int base = rows / ranks, extra = rows % ranks;
    return r * base + (r < extra ? r : extra);
  }
  int count(int r) const { return first(r + 1) - first(r); }

  // Each rank's block as counts and offsets of values, `per_row` per row (for
  // Comm::all_gather).
  void layout(std::size_t per_row, std::vector<std::size_t>& counts,
              std::vector<std::size_t>& offsets) const {
    counts.resize(ranks), offsets.resize(ranks);
    for (int r = 0; r < ranks; ++r) {
      counts[r] = static_cast<std::size_t>(count(r)) * per_row;
      offsets[r] = static_cast<std::size_t>(first(r)) * per_row;
    }
  }
};

}  // namespace talus::comm
