#pragma once
// Verlet neighbour list with a skin, built from a linked-cell grid. Each build
// also re-sorts the particles by cell, so neighbours sit close in memory, and
// carries the contact history over to the new list through that permutation.
#include <cstdint>
#include <vector>

#include "talus/dem/contact/kinematics.hpp"
#include "talus/dem/particles.hpp"
#include "talus/geometry/primitive.hpp"

namespace talus::dem {

template <int D>
class NeighbourList {
 public:
  using Vec = typename Space<D>::Vec;
  // Eight bytes a pair: the pair loop streams this list every step, so R* and
  // m* are recomputed per touching contact rather than stored.
  struct Pair {
    int i, j;
  };

  // Particle pairs closer than r_i + r_j + skin. Their history is split by
  // field, parallel to pairs: a law without rolling never touches pair_roll.
  std::vector<Pair> pairs;
  std::vector<Vec> pair_shear;
  std::vector<typename Space<D>::Rot> pair_roll;
  // Per particle (CSR): wall primitives closer than r + skin, with their history.
  std::vector<int> wall_start, wall_prim;
  std::vector<ContactHistory<D>> wall_history;

  int builds = 0;

  // Rebuilds the lists; permutes `p` into cell order (history follows).
  void build(Particles<D>& p, const std::vector<geometry::Primitive>& prims, double skin);

  double skin() const { return skin_; }
  // Checkpoint support: the reference positions of the last build.
  std::vector<Vec>& reference_positions() { return x_ref_; }
  void set_skin(double skin) { skin_ = skin; }

 private:
  void sort_into_cells(Particles<D>& p, double cell);
  void find_pairs(const Particles<D>& p, double cell);
  void find_walls(const Particles<D>& p, const std::vector<geometry::Primitive>& prims);
  void carry_history(const Particles<D>& p);

  // The lists of the previous build, and its pairs grouped by their lower
  // particle index (CSR), to carry contact history over.
  std::vector<Pair> old_pairs_;
  std::vector<Vec> old_pair_shear_;
  std::vector<typename Space<D>::Rot> old_pair_roll_;
  std::vector<ContactHistory<D>> old_wall_history_;
  std::vector<int> old_wall_start_, old_wall_prim_, old_row_start_, old_rows_;
  std::vector<int> order_;  // new index k held old index order_[k]

  std::vector<Vec> x_ref_;
  double skin_ = 0.0;
  double cell_size_ = 0.0;
  Vec lo_;
  int dims_[3] = {1, 1, 1};
  std::vector<int> cell_start_;
};

}  // namespace talus::dem
