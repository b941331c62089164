// [[materials]] and [[contact.pairs]]: material properties, checked against
// what the chosen contact model needs.
#include <fmt/format.h>

#include <cmath>

#include "talus/dem/contact/laws.hpp"
#include "talus/scenario/declared_keys.hpp"
#include "talus/scenario/scenario_detail.hpp"

namespace talus::io::detail {
namespace {

// A Coulomb coefficient given either directly or as an angle in degrees.
std::optional<double> read_friction(TomlReader& r, std::string_view key,
                                    std::string_view angle_key) {
  const auto mu = optional_number_in(r, key, non_negative());
  const auto phi = optional_number_in(r, angle_key, between(0.0, 90.0, false, true));
  if (mu && phi) {
    r.fail(angle_key, fmt::format("give either '{}' or '{}', not both", key, angle_key));
  }
  if (phi) return std::tan(deg2rad(*phi));
  return mu;
}

// The keys every material has, then those of the contact law (which declares
// them); other laws' keys are read too when present, so that a --set may
// switch the law.
dem::MaterialParams read_material(TomlReader& r, const std::string& contact_model) {
  using Laws = dem::ContactLaws;
  dem::MaterialParams m;
  m.name = r.required_string("name");
  r.expect(!m.name.empty(), "name", "a non-empty name");
  // Density is needed only by materials that particles use; the caller checks.
  m.density = number_in(r, "density", 0.0, positive());
  const auto friction = read_friction(r, "friction", "friction_angle");
  if (!friction) {
    r.missing("friction", "missing (expected 'friction' >= 0 or 'friction_angle' in degrees)");
  }
  m.friction = *friction;
  m.rolling_friction = number_in(r, "rolling_friction", 0.0, non_negative());
  read_law<Laws>(r, Laws::index_of(contact_model), m, "contact.model", OtherLaws::Accept);
  r.finish();
  return m;
}

}  // namespace

std::vector<dem::MaterialParams> read_materials(std::vector<TomlReader>& readers,
                                                const std::string& contact_model) {
  std::vector<dem::MaterialParams> materials;
  for (std::size_t i = 0; i < readers.size(); ++i) {
    auto m = read_material(readers[i], contact_model);
    check_unique_name(readers[i], materials, m.name, "material", "defined",
                      [&](std::size_t j) { return fmt::format("at line {}", readers[j].line()); });
    materials.push_back(std::move(m));
  }
  return materials;
}

std::vector<dem::PairOverride> read_pairs(TomlReader& contact, const DemContext& ctx) {
  std::vector<dem::PairOverride> pairs;
  for (TomlReader& r : contact.tables("pairs")) {
    dem::PairOverride pair;
    const std::vector<std::string> names = r.string_list("materials");
    if (!r.has("materials")) r.missing("materials", "missing (expected [\"name_a\", \"name_b\"])");
    r.expect(names.size() == 2, "materials", "two material names [\"name_a\", \"name_b\"]");
    check_material(r, "materials", names[0], ctx);
    check_material(r, "materials", names[1], ctx);
    pair.material_a = names[0];
    pair.material_b = names[1];
    pair.friction = read_friction(r, "friction", "friction_angle");
    pair.rolling_friction = optional_number_in(r, "rolling_friction", non_negative());
    pair.restitution = optional_number_in(r, "restitution", between(0.0, 1.0, true, false));
    if (!pair.friction && !pair.rolling_friction && !pair.restitution) {
      r.fail("materials",
             "expected at least one of 'friction', 'friction_angle', 'rolling_friction', "
             "'restitution' for this pair");
    }
    for (const dem::PairOverride& other : pairs) {
      const bool same =
          (other.material_a == pair.material_a && other.material_b == pair.material_b) ||
          (other.material_a == pair.material_b && other.material_b == pair.material_a);
      if (same) {
        r.fail("materials",
               fmt::format("the pair '{}'-'{}' is given twice", pair.material_a, pair.material_b));
      }
    }
    r.finish();
    pairs.push_back(pair);
  }
  return pairs;
}

}  // namespace talus::io::detail
