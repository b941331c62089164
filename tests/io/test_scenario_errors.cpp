// Bad scenario files give an InputError that names the file, the line and the
// key. Each case edits a small valid scenario; the expected line is the one
// marked "# <-" in the edited text (0: no line, e.g. a missing top-level key).
#include <gtest/gtest.h>

#include "scenario_cases.hpp"
#include "talus/core/error.hpp"
#include "talus/scenario/scenario.hpp"

namespace talus::io {
namespace {

const std::string kBase3d = R"(method = "dem"
[run]
dimension = 3
duration = 0.1
domain = { min = [0, 0, 0], max = [1, 1, 1] }
[contact]
model = "hertz_mindlin"
[[materials]]
name = "glass"
density = 2500
youngs_modulus = 1e7
restitution = 0.9
friction = 0.5
[[walls]]
type = "plane"
material = "glass"
point = [0, 0, 0]
normal = [0, 0, 1]
[[particles]]
type = "list"
material = "glass"
[[particles.list]]
position = [0.5, 0.5, 0.5]
radius = 0.01
)";

const std::string kBase2d = R"(method = "dem"
[run]
dimension = 2
duration = 0.1
domain = { min = [0, 0], max = [1, 1] }
[contact]
model = "linear"
[[materials]]
name = "sand"
density = 2672
friction = 0.3
normal_stiffness = 1e6
damping_ratio = 0.3
[[walls]]
type = "segment"
material = "sand"
a = [0, 0]
b = [1, 0]
[[particles]]
type = "list"
material = "sand"
[[particles.list]]
position = [0.5, 0.5]
radius = 0.01
)";

const std::string kFill3d = R"([[particles]]
type = "random_fill"
material = "glass"
box = { min = [0, 0, 0], max = [1, 1, 1] }
radius_min = 0.01
radius_max = 0.02
porosity = 0.4
)";

using cases::BadCase;
using cases::edit;

// The particle list of the 3D base replaced by another source.
std::string with_source(const std::string& source) {
  const auto at = kBase3d.find("[[particles]]");
  return kBase3d.substr(0, at) + source;
}

class BadScenario : public testing::TestWithParam<BadCase> {};

TEST_P(BadScenario, InputErrorNamesFileLineAndKey) { cases::expect_input_error(GetParam()); }

const std::string kDensity = "density = 2500";

INSTANTIATE_TEST_SUITE_P(
    Scenario, BadScenario,
    testing::Values(
        BadCase{"negative_density", edit(kBase3d, kDensity, "density = -3 # <-"), "density",
                "[[materials]] 'density': expected a positive number, got -3"},
        BadCase{"zero_density", edit(kBase3d, kDensity, "density = 0 # <-"), "density",
                "expected a positive number, got 0"},
        BadCase{"density_as_text", edit(kBase3d, kDensity, "density = \"heavy\" # <-"), "density",
                "expected a positive number, got \"heavy\""},
        BadCase{"density_missing_for_particles",
                edit(kBase3d,
                     "[[materials]]\nname = \"glass\"\n"
                     "density = 2500\n",
                     "[[materials]] # <-\nname = \"glass\"\n"),
                "density", "used by particles"},
        BadCase{"typo_in_required_key", edit(kBase3d, "friction = 0.5", "frictoin = 0.5 # <-"),
                "frictoin", "did you mean 'friction'?"},
        BadCase{"typo_in_run", edit(kBase3d, "duration = 0.1", "duraton = 0.1 # <-"), "duraton",
                "did you mean 'duration'?"},
        BadCase{"typo_in_optional_key",
                edit(kBase3d, "model = \"hertz_mindlin\"",
                     "model = \"hertz_mindlin\"\nroling = \"epsd\" # <-"),
                "roling", "unknown key; did you mean 'rolling'?"},
        BadCase{"unknown_table", kBase3d + "[outptu] # <-\nsnapshots = true\n", "outptu",
                "did you mean 'output'?"},
        BadCase{"unknown_key_without_suggestion",
                edit(kBase3d, "[[walls]]", "[[walls]]\ncolour = \"red\" # <-"), "colour",
                "unknown key (known keys here:"},
        BadCase{"missing_duration",
                edit(edit(kBase3d, "duration = 0.1\n", ""), "[run]", "[run] # <-"), "duration",
                "[run] 'duration': missing (expected a positive number)"},
        BadCase{"missing_method", edit(kBase3d, "method = \"dem\"\n", ""), "method", "missing"},
        BadCase{"unknown_method", edit(kBase3d, "method = \"dem\"", "method = \"sph\" # <-"),
                "method",
                "expected one of \"dem\", \"runout\", \"mpm\" or \"compare\", got \"sph\""},
        BadCase{"syntax_error", edit(kBase3d, "duration = 0.1", "duration = 0.1 0.2 # <-"), "",
                "TOML syntax error"},
        BadCase{"dimension_4", edit(kBase3d, "dimension = 3", "dimension = 4 # <-"), "dimension",
                "expected 2 or 3, got 4"},
        BadCase{"bad_time_step", edit(kBase3d, "[run]", "[run]\ntime_step = \"fast\" # <-"),
                "time_step", "\"auto\""},
        BadCase{"unknown_contact_model",
                edit(kBase3d, "model = \"hertz_mindlin\"", "model = \"hertz\" # <-"), "model",
                "expected one of \"linear\", \"hertz_mindlin\" or \"viscoelastic_hertz\", got "
                "\"hertz\"; did you mean \"hertz_mindlin\"?"},
        BadCase{"negative_kuen_reference_step",
                edit(kBase2d, "model = \"linear\"",
                     "model = \"linear\"\nkuen_reference_step = -1e-6 # <-"),
                "kuen_reference_step", "expected a number >= 0, got -1e-06"},
        BadCase{"undefined_wall_material",
                edit(kBase3d, "type = \"plane\"\nmaterial = \"glass\"",
                     "type = \"plane\"\nmaterial = \"glas\" # <-"),
                "material", "no material named 'glas'; did you mean 'glass'?"},
        BadCase{"undefined_pair_material",
                edit(kBase3d, "[[materials]]",
                     "[[contact.pairs]]\nmaterials = [\"glass\", \"steel\"] # <-\nfriction = 0.1\n"
                     "[[materials]]"),
                "materials", "no material named 'steel'"},
        BadCase{
            "duplicate_material",
            edit(kBase3d, "[[walls]]",
                 "[[materials]]\nname = \"glass\" # <-\nyoungs_modulus = 1e7\nrestitution = 0.5\n"
                 "friction = 0.1\n[[walls]]"),
            "name", "defined twice (first at line 8)"},
        BadCase{"both_frictions",
                edit(kBase3d, "friction = 0.5", "friction = 0.5\nfriction_angle = 30 # <-"),
                "friction_angle", "not both"},
        BadCase{"friction_angle_90", edit(kBase3d, "friction = 0.5", "friction_angle = 90 # <-"),
                "friction_angle", "expected a number in [0, 90), got 90"},
        BadCase{"hertz_poisson",
                edit(kBase3d, kDensity, "density = 2500\npoisson_ratio = 0.5 # <-"),
                "poisson_ratio", "expected a number in (-1, 0.5), got 0.5"},
        BadCase{
            "hertz_needs_restitution",
            edit(edit(kBase3d, "restitution = 0.9\n", ""), "[[materials]]", "[[materials]] # <-"),
            "restitution", "contact.model = \"hertz_mindlin\" needs it"},
        BadCase{"viscoelastic_needs_youngs",
                edit(edit(edit(kBase3d, "youngs_modulus = 1e7\n", ""), "[[materials]]",
                          "[[materials]] # <-"),
                     "\"hertz_mindlin\"", "\"viscoelastic_hertz\""),
                "youngs_modulus", "contact.model = \"viscoelastic_hertz\" needs it"},
        BadCase{"negative_dissipation",
                edit(kBase3d, kDensity, "density = 2500\ndissipation = -1e-9 # <-"), "dissipation",
                "expected a number >= 0, got -1e-09"},
        BadCase{"linear_needs_stiffness",
                edit(edit(kBase2d, "normal_stiffness = 1e6\n", ""), "[[materials]]",
                     "[[materials]] # <-"),
                "normal_stiffness", "contact.model = \"linear\" needs it"},
        BadCase{"linear_damping_ratio_1",
                edit(kBase2d, "damping_ratio = 0.3", "damping_ratio = 1 # <-"), "damping_ratio",
                "expected a number in [0, 1), got 1"},
        BadCase{"segment_in_3d", edit(kBase3d, "type = \"plane\"", "type = \"segment\" # <-"),
                "type", "\"segment\" walls need run.dimension = 2"},
        BadCase{"plane_in_2d", edit(kBase2d, "type = \"segment\"", "type = \"plane\" # <-"), "type",
                "\"plane\" walls need run.dimension = 3"},
        BadCase{"z_in_2d", edit(kBase2d, "b = [1, 0]", "b = [1, 0, 0.5] # <-"), "b",
                "expected [x, y] in a 2D run"},
        BadCase{"vector_of_4", edit(kBase3d, "point = [0, 0, 0]", "point = [0, 0, 0, 1] # <-"),
                "point", "expected [x, y] or [x, y, z], got [0, 0, 0, 1]"},
        BadCase{"key_of_other_wall_type",
                edit(kBase3d, "normal = [0, 0, 1]", "normal = [0, 0, 1]\nradius = 1 # <-"),
                "radius", "not used by walls of type \"plane\""},
        BadCase{"motion_stop_before_start",
                edit(kBase3d, "normal = [0, 0, 1]",
                     "normal = [0, 0, 1]\nmotion = { start = 1.0, stop = 0.5 } # <-"),
                "stop", "[walls.motion] 'stop': expected a time after start = 1 s, got 0.5"},
        BadCase{
            "missing_mesh_file",
            edit(kBase3d,
                 "type = \"plane\"\nmaterial = \"glass\"\npoint = [0, 0, 0]\nnormal = [0, 0, 1]",
                 "type = \"mesh\"\nmaterial = \"glass\"\nfile = \"nope.stl\" # <-"),
            "file", "no such file"},
        BadCase{"negative_particle_radius", edit(kBase3d, "radius = 0.01", "radius = -0.01 # <-"),
                "radius", "[[particles.list]] 'radius': expected a positive number, got -0.01"},
        BadCase{"radius_min_above_max",
                with_source(edit(kFill3d, "radius_min = 0.01", "radius_min = 0.03 # <-")),
                "radius_min", "radius_min = 0.03 is larger than radius_max = 0.02"},
        BadCase{"porosity_above_1",
                with_source(edit(kFill3d, "porosity = 0.4", "porosity = 1.2 # <-")), "porosity",
                "expected a number in (0, 1), got 1.2"},
        BadCase{"zero_count",
                with_source(edit(kFill3d, "porosity = 0.4", "porosity = 0.4\ncount = 0 # <-")),
                "count", "expected a positive integer, got 0"},
        BadCase{"fill_without_porosity",
                with_source(edit(edit(kFill3d, "porosity = 0.4\n", "count = 10\n"), "[[particles]]",
                                 "[[particles]] # <-")),
                "porosity", "missing (expected a number in (0, 1))"},
        BadCase{"polygon_in_3d",
                with_source(edit(kFill3d, "box = { min = [0, 0, 0], max = [1, 1, 1] }",
                                 "polygon = [[0, 0], [1, 0], [0, 1]] # <-")),
                "polygon", "polygons are for 2D runs"},
        BadCase{"unknown_source_type", with_source("[[particles]]\ntype = \"pour\" # <-\n"), "type",
                "expected one of \"list\", \"lattice\", \"random_fill\", \"grow\" or \"file\""},
        BadCase{"domain_min_above_max",
                edit(kBase3d, "domain = { min = [0, 0, 0], max = [1, 1, 1] }",
                     "domain = { min = [0, 0, 0], max = [1, 0, 1] } # <-"),
                "max", "[run.domain] 'max': expected max > min in every coordinate"}),
    [](const testing::TestParamInfo<BadCase>& info) { return info.param.name; });

TEST(BadScenario, BaseScenariosAreValid) {
  // The cases above must fail because of their edit, not because of the base.
  EXPECT_NO_THROW(parse_dem_scenario(load_scenario_text(kBase3d, "base3d.toml")));
  EXPECT_NO_THROW(parse_dem_scenario(load_scenario_text(kBase2d, "base2d.toml")));
  EXPECT_NO_THROW(parse_dem_scenario(load_scenario_text(with_source(kFill3d), "fill.toml")));
}

TEST(BadScenario, MissingFileIsAnInputError) {
  EXPECT_THROW(load_scenario_file("/nonexistent/scenario.toml", {}), InputError);
}

}  // namespace
}  // namespace talus::io
