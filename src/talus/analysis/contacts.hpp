#pragma once
// Contact number from the geometry of one snapshot (Götz 2024 §1.2, §5.3.1: "die
// durchschnittliche Anzahl der Kontakte pro Partikel"). Two grains touch when the gap between
// their surfaces, |x_i - x_j| - r_i - r_j, is below `gap` (default 0: they overlap, as the DEM
// counts a contact). Grain-grain contacts only: walls and membranes are not in the particle
// snapshot. Pure geometry: no files, no solver.
#include <cstddef>
#include <vector>

#include "talus/core/space.hpp"

namespace talus::analysis {

// Number of grain-grain contacts of each grain. Uses a cell list (O(N log N)).
std::vector<int> contact_counts(const std::vector<Vec3>& position,
                                const std::vector<double>& radius, double gap = 0.0);

struct ContactNumber {
  std::size_t grains = 0;
  std::size_t contacts = 0;  // pairs in contact
  double z = 0.0;            // 2 contacts / grains: the source's z, over all grains
  // Rattlers: grains with fewer than min_contacts contacts, removed one round after the other
  // (removing a rattler takes a contact from its neighbours, which may make them rattlers too),
  // the usual definition of the mechanical contact number of jammed packings.
  std::size_t rattlers = 0;
  double z_no_rattlers = 0.0;  // 2 contacts among the others / their number (0 if none left)
};

// From the per-grain counts and the pairs in contact. min_contacts: D + 1 is the usual
// threshold (a grain needs D + 1 contacts to be held in place: 3 disks, 4 spheres).
ContactNumber contact_number(const std::vector<Vec3>& position, const std::vector<double>& radius,
                             int min_contacts, double gap = 0.0);

}  // namespace talus::analysis
