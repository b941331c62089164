#include "talus/analysis/contacts.hpp"

#include <algorithm>
#include <stdexcept>
#include <utility>

#include "talus/analysis/cell_list.hpp"

namespace talus::analysis {

namespace {

std::vector<std::pair<std::size_t, std::size_t>> touching_pairs(const std::vector<Vec3>& x,
                                                                const std::vector<double>& r,
                                                                double gap) {
  if (x.size() != r.size()) throw std::invalid_argument("contacts: positions and radii differ");
  std::vector<std::pair<std::size_t, std::size_t>> pairs;
  if (x.empty()) return pairs;
  const double r_max = *std::max_element(r.begin(), r.end());
  // Any touching pair is closer than 2 r_max + gap; the cell list finds all such pairs.
  const double reach = 2 * r_max + gap;
  if (!(reach > 0)) return pairs;  // point grains with gap <= 0 never touch
  const CellList cells(x, reach);
  cells.for_each_pair([&](std::size_t i, std::size_t j, double d) {
    if (d - r[i] - r[j] < gap) pairs.emplace_back(i, j);
  });
  return pairs;
}

// Contacts of each of n grains from the pairs in contact: shared by contact_counts and
// contact_number, which needs the pairs as well and so must not search for them twice.
std::vector<int> counts_of(const std::vector<std::pair<std::size_t, std::size_t>>& pairs,
                           std::size_t n) {
  std::vector<int> count(n, 0);
  for (const auto& [i, j] : pairs) ++count[i], ++count[j];
  return count;
}

}  // namespace

std::vector<int> contact_counts(const std::vector<Vec3>& position,
                                const std::vector<double>& radius, double gap) {
  return counts_of(touching_pairs(position, radius, gap), position.size());
}

ContactNumber contact_number(const std::vector<Vec3>& position, const std::vector<double>& radius,
                             int min_contacts, double gap) {
  const auto pairs = touching_pairs(position, radius, gap);
  ContactNumber z;
  z.grains = position.size();
  z.contacts = pairs.size();
  z.z = z.grains ? 2.0 * static_cast<double>(z.contacts) / z.grains : 0.0;

  std::vector<int> count = counts_of(pairs, position.size());
  // 0: kept, 1: removed in an earlier round, 2: removed in this round.
  std::vector<char> rattler(position.size(), 0);
  // Rounds of removal until no grain below the threshold is left (each round removes at least
  // one grain, so at most N rounds; usually two or three).
  for (bool removed = true; removed;) {
    removed = false;
    for (std::size_t i = 0; i < count.size(); ++i)
      if (!rattler[i] && count[i] < min_contacts) rattler[i] = 2, removed = true;
    for (const auto& [i, j] : pairs) {  // a contact with a grain removed now is lost by its partner
      if (rattler[i] == 2 && !rattler[j]) --count[j];
      if (rattler[j] == 2 && !rattler[i]) --count[i];
    }
    for (char& c : rattler) c = c ? 1 : 0;
  }
  std::size_t kept_contacts = 0;
  for (const auto& [i, j] : pairs) kept_contacts += !rattler[i] && !rattler[j];
  z.rattlers = static_cast<std::size_t>(std::count(rattler.begin(), rattler.end(), 1));
  const std::size_t kept = z.grains - z.rattlers;
  z.z_no_rattlers = kept ? 2.0 * static_cast<double>(kept_contacts) / kept : 0.0;
  return z;
}

}  // namespace talus::analysis
