// TomlReader (src/talus/io/toml_reader.hpp), the generic layer under the
// scenario parser: accessors, unknown-key tracking, messages, overrides.
#include <gtest/gtest.h>

#include <cmath>

#include "scenario_cases.hpp"
#include "talus/core/error.hpp"
#include "talus/io/toml_reader.hpp"

namespace talus::io {
namespace {

toml::table parse_text(std::string_view text) {
  return toml::parse(text, std::string_view("t.toml"));
}

using cases::error_of;

const std::string_view kText = R"(title = "t"
n = 3
x = 2.5
flag = true
v2 = [1, 2]
v3 = [1, 2.5, -3]
angle = 180
kind = "beta"
[sub]
y = 1
[[items]]
a = 1
[[items]]
a = 2
)";

TEST(TomlReader, AccessorsConvertAndFillDefaults) {
  const toml::table table = parse_text(kText);
  TomlReader r(table, "t.toml");
  EXPECT_EQ(r.required_string("title"), "t");
  EXPECT_DOUBLE_EQ(r.required_number("n"), 3.0);  // an integer accepted as a number
  EXPECT_EQ(r.required_integer("n"), 3);
  EXPECT_DOUBLE_EQ(r.number("x", 0.0), 2.5);
  EXPECT_DOUBLE_EQ(r.number("absent", 7.0), 7.0);
  EXPECT_FALSE(r.optional_number("also_absent").has_value());
  EXPECT_TRUE(r.boolean("flag", false));
  const Vec3 v2 = r.required_vec3("v2");
  EXPECT_EQ(v2, Vec3(1, 2, 0));  // two numbers: z = 0
  EXPECT_EQ(r.required_vec3("v3"), Vec3(1, 2.5, -3));
  EXPECT_NEAR(r.required_angle("angle"), M_PI, 1e-15);  // 180 degrees
  enum class Kind { Alpha, Beta };
  const EnumNames<Kind> kinds = {{"alpha", Kind::Alpha}, {"beta", Kind::Beta}};
  EXPECT_EQ(r.required_enum("kind", kinds), Kind::Beta);
  EXPECT_EQ(r.enumeration("no_kind", kinds, Kind::Alpha), Kind::Alpha);
  TomlReader sub = r.required_table("sub");
  EXPECT_DOUBLE_EQ(sub.required_number("y"), 1.0);
  sub.finish();
  const std::vector<TomlReader> items = r.tables("items");
  ASSERT_EQ(items.size(), 2u);
  EXPECT_EQ(items[1].label(), "[[items]]");
  EXPECT_EQ(items[1].line(), 13);  // the second [[items]] header
  EXPECT_NO_THROW(r.finish());
}

TEST(TomlReader, UnreadKeysAreReportedWithTheirLine) {
  const toml::table table = parse_text(kText);
  TomlReader r(table, "t.toml");
  r.required_string("title");
  r.required_number("x");
  r.number("flog", 0.0);  // asked for, but the file says "flag"
  // The first unread key in file order is n (line 2); nothing close to it.
  EXPECT_NE(error_of([&] { r.finish(); })
                .find("t.toml:2: 'n': unknown key (known keys here: flog, "
                      "title, x)"),
            std::string::npos);
  for (auto key : {"n", "v2", "v3", "angle", "kind", "sub", "items"}) r.mark_read(key);
  EXPECT_EQ(error_of([&] { r.finish(); }), "t.toml:4: 'flag': unknown key; did you mean 'flog'?");
}

TEST(TomlReader, WrongTypesNameLineKeyAndValue) {
  const toml::table table = parse_text(kText);
  TomlReader r(table, "t.toml");
  EXPECT_EQ(error_of([&] { r.required_number("title"); }),
            "t.toml:1: 'title': expected a number, got \"t\"");
  EXPECT_EQ(error_of([&] { r.required_integer("x"); }),
            "t.toml:3: 'x': expected an integer, got 2.5");
  EXPECT_EQ(error_of([&] { r.boolean("n", false); }),
            "t.toml:2: 'n': expected true or false, got 3");
  EXPECT_EQ(error_of([&] { r.required_vec3("x"); }),
            "t.toml:3: 'x': expected [x, y] or [x, y, z], got 2.5");
  const EnumNames<int> names = {{"alpha", 0}, {"gamma", 1}};
  EXPECT_EQ(error_of([&] { r.required_enum("kind", names); }),
            "t.toml:8: 'kind': expected one of \"alpha\" or \"gamma\", got \"beta\"");
  TomlReader sub = r.required_table("sub");
  EXPECT_EQ(error_of([&] { sub.required_number("z"); }),
            "t.toml:9: [sub] 'z': missing (expected a number)");  // the table's header line
  EXPECT_EQ(error_of([&] { r.tables("sub"); }),
            "t.toml:9: 'sub': expected an array of tables ([[sub]]), got a table");
}

TEST(TomlReader, MissingKeyPointsAtALikelyTypo) {
  const toml::table table = parse_text("[run]\nduraton = 1\nradius_max = 2\n");
  TomlReader run(table, "t.toml");
  TomlReader r = run.required_table("run");
  EXPECT_EQ(error_of([&] { r.required_number("duration"); }),
            "t.toml:2: [run] 'duraton': unknown key; did you mean 'duration'? ('duration' is "
            "required)");
  // Two edits away: radius_max is a real key, not a typo of radius_min.
  EXPECT_EQ(error_of([&] { r.required_number("radius_min"); }),
            "t.toml:1: [run] 'radius_min': missing (expected a number)");
}

TEST(TomlReader, RejectNamesTheKeyThatDoesNotApply) {
  const toml::table table = parse_text("type = \"a\"\nradius = 1\n");
  TomlReader r(table, "t.toml");
  r.required_string("type");
  EXPECT_EQ(error_of([&] {
              r.reject({"radius", "length"}, "not used by type \"a\"");
            }),
            "t.toml:2: 'radius': not used by type \"a\"");
}

TEST(TomlReader, ClosestNameFindsTyposOnly) {
  const std::vector<std::string> names = {"density", "friction", "poisson_ratio", "restitution"};
  EXPECT_EQ(closest_name("desnity", names), "density");  // swapped letters: one edit
  EXPECT_EQ(closest_name("frictoin", names), "friction");
  EXPECT_EQ(closest_name("poisson", names), "poisson_ratio");  // prefix of a longer name
  EXPECT_EQ(closest_name("colour", names), "");
  EXPECT_EQ(closest_name("x", names), "");
}

TEST(TomlReader, OverridesParseValuesAsTomlAndFallBackToStrings) {
  toml::table table = toml::parse("[run]\nduration = 1.0\n[[m]]\nf = 0.5\n[[m]]\nf = 0.6\n");
  apply_overrides(table,
                  {"run.duration=2", "run.model=linear model", "run.g=[0, -9.81]", "run.flag=true",
                   "run.box={min = [0, 0], max = [1, 1]}", "m.1.f=0.7", "new.key=\"quoted\""});
  EXPECT_EQ(table.at_path("run.duration").value<std::int64_t>(), 2);
  EXPECT_EQ(table.at_path("run.model").value<std::string>(), "linear model");
  EXPECT_DOUBLE_EQ(*table.at_path("run.g[1]").value<double>(), -9.81);
  EXPECT_EQ(table.at_path("run.flag").value<bool>(), true);
  EXPECT_EQ(table.at_path("run.box.max[0]").value<std::int64_t>(), 1);
  EXPECT_DOUBLE_EQ(*table.at_path("m[1].f").value<double>(), 0.7);
  EXPECT_DOUBLE_EQ(*table.at_path("m[0].f").value<double>(), 0.5);
  EXPECT_EQ(table.at_path("new.key").value<std::string>(), "quoted");
  // Values from --set carry no line: messages say where they came from.
  EXPECT_EQ(table.at_path("run.box.min").node()->source().begin.line, 0u);
  TomlReader root(table, "f.toml");
  TomlReader run = root.required_table("run");
  EXPECT_EQ(error_of([&] { run.required_string("duration"); }),
            "f.toml: --set run.duration: expected a string, got 2");
}

// Found by the scenario fuzzer (tests/fuzz/regressions/set_value_not_utf8):
// a value TOML cannot hold would reach the run's scenario.toml.
TEST(TomlReader, OverridesThatAreNotUtf8AreRefused) {
  toml::table table;
  EXPECT_EQ(error_of([&] { apply_overrides(table, {"name=caf\xE9"}); }),
            "--set: the value is not valid UTF-8 text");
  EXPECT_THROW(apply_overrides(table, {"name=\xC0\xAF"}), InputError);      // overlong '/'
  EXPECT_THROW(apply_overrides(table, {"name=\xED\xA0\x80"}), InputError);  // a surrogate
  apply_overrides(table, {"name=caf\xC3\xA9 \xF0\x9F\x8C\x8B"});            // "café 🌋"
  EXPECT_EQ(table["name"].value<std::string>(), "caf\xC3\xA9 \xF0\x9F\x8C\x8B");
}

}  // namespace
}  // namespace talus::io
