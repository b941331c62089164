// Laws declare their own keys (core/declared_keys.hpp) and the scenario reader
// takes them from there: for every law of every family (MPM materials, runout
// rheologies, DEM contact laws) a table built from the law's declaration alone
// parses, stores each value in the declared field and units, reads back from
// the resolved file, names the law when a required key is missing and (for
// one-law tables) refuses keys that only other laws declare. Nothing in this
// test names a law's keys: adding a law to a family adds it to these tests.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "scenario_cases.hpp"
#include "talus/dem/contact/laws.hpp"
#include "talus/mpm/materials.hpp"
#include "talus/runout/rheology.hpp"
#include "talus/scenario/declared_keys.hpp"
#include "talus/scenario/scenario.hpp"
#include "talus/scenario/scenario_mpm.hpp"
#include "talus/scenario/scenario_runout.hpp"

namespace talus::io {
namespace {

using cases::edit;
using cases::error_of;

// A number the key accepts, in the file's units: the middle of a finite range,
// else one above its lower end.
template <class P>
double valid_value(const DeclaredKey<P>& key) {
  const Interval& r = key.range;
  if (std::isfinite(r.low) && std::isfinite(r.high)) return 0.5 * (r.low + r.high);
  if (std::isfinite(r.low)) return r.low + 1.0;
  return std::isfinite(r.high) ? r.high - 1.0 : 0.0;
}

// "key = value" lines for the law's required keys.
template <class Law>
std::string required_lines() {
  std::string text;
  for (const auto& key : Law::keys)
    if (key.required) text += fmt::format("{} = {}\n", key.name, valid_value(key));
  return text;
}

// Every value the law declares ended up in its field, in stored units.
template <class Law, class P>
void expect_stored(const P& p) {
  for (const auto& key : Law::keys) {
    if (!key.required) continue;
    EXPECT_DOUBLE_EQ(p.*key.field, detail::to_stored(valid_value(key), key.unit))
        << Law::name << " " << key.name;
  }
}

// A key that another law of the family declares and Law does not ("" if none).
template <class Laws, class Law>
std::string foreign_key() {
  std::string found;
  Laws::for_each([&]<class Other>() {
    for (const auto& key : Other::keys)
      if (found.empty() &&
          !detail::declares(std::span<const typename decltype(Law::keys)::value_type>(Law::keys),
                            key.name))
        found = std::string(key.name);
  });
  return found;
}

TEST(DeclaredLaws, LawListFindsAndVisitsByName) {
  using Laws = mpm::MaterialLaws;
  EXPECT_EQ(Laws::index_of("drucker_prager"), 1u);
  EXPECT_EQ(Laws::index_of("no_such_model"), Laws::size);
  for (std::size_t i = 0; i < Laws::size; ++i)
    EXPECT_EQ(Laws::visit(i, []<class Law>() { return Law::name; }), Laws::names[i]);
}

const std::string kMpm = R"(method = "mpm"
[run]
dimension = 2
duration = 0.5
[grid]
min = [0, 0]
max = [1, 0.5]
cell_size = 0.05
[[materials]]
name = "m"
density = 2000
MODEL
[[bodies]]
material = "m"
box = { min = [0, 0], max = [0.3, 0.2] }
)";

TEST(DeclaredLaws, MpmMaterialsReadTheKeysTheirModelDeclares) {
  mpm::MaterialLaws::for_each([&]<class Law>() {
    const std::string table = fmt::format("model = \"{}\"\n{}", Law::name, required_lines<Law>());
    const std::string text = edit(kMpm, "MODEL\n", table);
    const auto sc = parse_mpm_scenario(load_scenario_text(text, "ok.toml"));
    EXPECT_EQ(sc.materials[0].model, Law::name);
    expect_stored<Law>(sc.materials[0]);
    const auto again =
        parse_mpm_scenario(load_scenario_text(mpm_scenario_to_toml(sc), "resolved.toml"));
    EXPECT_EQ(mpm_scenario_to_json(again).dump(), mpm_scenario_to_json(sc).dump()) << Law::name;
    for (const auto& key : Law::keys) {
      if (!key.required) continue;
      const std::string line = fmt::format("{} = {}\n", key.name, valid_value(key));
      const std::string message = error_of(
          [&] { parse_mpm_scenario(load_scenario_text(edit(text, line, ""), "bad.toml")); });
      EXPECT_NE(message.find(fmt::format("model = \"{}\" needs it", Law::name)), std::string::npos)
          << message;
      EXPECT_NE(message.find(std::string(key.name)), std::string::npos) << message;
    }
    const std::string other = foreign_key<mpm::MaterialLaws, Law>();
    ASSERT_FALSE(other.empty()) << Law::name;
    const std::string message = error_of([&] {
      parse_mpm_scenario(load_scenario_text(
          edit(text, "density = 2000\n", "density = 2000\n" + other + " = 1\n"), "bad.toml"));
    });
    EXPECT_NE(message.find(fmt::format("is not used by model '{}'", Law::name)), std::string::npos)
        << message;
  });
}

const std::string kRunout = R"(method = "runout"
[run]
duration = 1.0
[path]
type = "flume"
beta = 33
arc_radius = 0.1
[material]
density = 1630
internal_friction = 30.9
RHEOLOGY
[release]
type = "flume"
blocks = 20
)";

TEST(DeclaredLaws, RunoutRheologiesReadTheKeysTheyDeclare) {
  runout::RheologyLaws::for_each([&]<class Law>() {
    const std::string table =
        fmt::format("rheology = \"{}\"\n{}", Law::name, required_lines<Law>());
    const std::string text = edit(kRunout, "RHEOLOGY\n", table);
    const auto sc = parse_runout_scenario(load_scenario_text(text, "ok.toml"));
    EXPECT_EQ(runout::RheologyLaws::names[sc.params.rheology.law], Law::name);
    expect_stored<Law>(sc.params.rheology);
    const auto again =
        parse_runout_scenario(load_scenario_text(runout_scenario_to_toml(sc), "resolved.toml"));
    EXPECT_EQ(runout_scenario_to_json(again).dump(), runout_scenario_to_json(sc).dump());
    const std::string other = foreign_key<runout::RheologyLaws, Law>();
    const std::string message = error_of([&] {
      parse_runout_scenario(load_scenario_text(
          edit(text, "density = 1630\n", "density = 1630\n" + other + " = 1\n"), "bad.toml"));
    });
    EXPECT_NE(message.find(fmt::format("is not used by rheology '{}'", Law::name)),
              std::string::npos)
        << message;
  });
}

const std::string kDem = R"(method = "dem"
[run]
dimension = 2
duration = 0.01
time_step = 1e-6
[contact]
model = "LAW"
[[materials]]
name = "m"
density = 2500
friction = 0.5
KEYS
[[particles]]
type = "list"
material = "m"
[[particles.list]]
position = [0, 0]
radius = 0.01
)";

TEST(DeclaredLaws, DemMaterialsReadTheKeysTheContactLawDeclares) {
  dem::ContactLaws::for_each([&]<class Law>() {
    const std::string text =
        edit(edit(kDem, "LAW", std::string(Law::name)), "KEYS\n", required_lines<Law>());
    const auto sc = parse_dem_scenario(load_scenario_text(text, "ok.toml"));
    EXPECT_EQ(sc.contact.model, Law::name);
    expect_stored<Law>(sc.materials[0]);
    const auto again = parse_dem_scenario(load_scenario_text(scenario_to_toml(sc), "again.toml"));
    EXPECT_EQ(scenario_to_json(again).dump(), scenario_to_json(sc).dump()) << Law::name;
    for (const auto& key : Law::keys) {
      if (!key.required) continue;
      const std::string line = fmt::format("{} = {}\n", key.name, valid_value(key));
      const std::string message = error_of(
          [&] { parse_dem_scenario(load_scenario_text(edit(text, line, ""), "bad.toml")); });
      EXPECT_NE(message.find(fmt::format("contact.model = \"{}\" needs it", Law::name)),
                std::string::npos)
          << message;
    }
    // Keys of the other laws are read (so that --set contact.model may switch
    // the law) but change nothing this law uses.
    const std::string other = foreign_key<dem::ContactLaws, Law>();
    const auto with_other = parse_dem_scenario(load_scenario_text(
        edit(text, "friction = 0.5\n", "friction = 0.5\n" + other + " = 0.25\n"), "ok.toml"));
    EXPECT_EQ(scenario_to_json(with_other).dump(), scenario_to_json(sc).dump()) << other;
  });
}

// Membrane contacts have one law; a run naming another is refused, not run
// with two laws.
TEST(DeclaredLaws, MembranesRefuseAContactLawTheyDoNotUse) {
  std::string text = cases::bundled("dem/membrane_sheet_drop.toml");
  text = edit(text, "model = \"viscoelastic_hertz\"", "model = \"hertz_mindlin\"");
  text = edit(text, "friction = 0.3\n", "friction = 0.3\nrestitution = 0.5\n");
  text = edit(text, "friction = 0.5\n", "friction = 0.5\nrestitution = 0.5\n");
  const std::string message = error_of([&] {
    parse_dem_scenario(
        load_scenario_text(text, std::string(TALUS_SOURCE_DIR) + "/scenarios/dem/bad.toml"));
  });
  EXPECT_NE(message.find("grain-membrane contacts use the 'viscoelastic_hertz' law"),
            std::string::npos)
      << message;
}

}  // namespace
}  // namespace talus::io
