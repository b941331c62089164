// Loading a scenario file, and the top level of the DEM scenario: [run],
// [contact], [output] and the checks that span several tables.
#include "talus/scenario/scenario.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <climits>
#include <filesystem>
#include <fstream>
#include <system_error>

#include "talus/core/error.hpp"
#include "talus/dem/contact/laws.hpp"
#include "talus/dem/membrane/contact.hpp"
#include "talus/scenario/declared_keys.hpp"
#include "talus/scenario/scenario_detail.hpp"

namespace talus::io {
namespace {

using detail::between;
using detail::DemContext;
using detail::non_negative;
using detail::number_in;
using detail::positive;
using detail::required_number_in;

const EnumNames<int> kMethods = {{"dem", 0}, {"runout", 1}, {"mpm", 2}, {"compare", 3}};
const std::vector<std::string_view> kTopLevelKeys = {
    "method", "name",          "description", "run",       "contact",   "materials",
    "flume",  "dam_break",     "walls",       "particles", "membranes", "triaxial",
    "output", "hollow_sphere", "gripper",     "beam"};

dem::RunParams read_run(TomlReader& r, DemContext& ctx) {
  dem::RunParams run;
  const auto dimension = r.required_integer("dimension");
  r.expect(dimension == 2 || dimension == 3, "dimension", "2 or 3");
  run.dimension = ctx.dimension = static_cast<int>(dimension);
  run.duration = required_number_in(r, "duration", positive());
  if (r.is_string("time_step")) {
    r.required_enum<int>("time_step", {{"auto", 0}});
  } else {
    const bool number = !r.has("time_step") || r.is_number("time_step");
    r.expect(number, "time_step", "a positive number (s) or \"auto\"");
    run.time_step = r.number("time_step", 0.0);
    if (r.has("time_step")) run.time_step_source = r.where("time_step");
    r.expect(run.time_step >= 0.0 && (run.time_step > 0.0 || !r.has("time_step")), "time_step",
             "a positive number (s) or \"auto\"");
  }
  run.safety_factor =
      number_in(r, "safety_factor", run.safety_factor, between(0.0, 1.0, true, false));
  const Vec3 down = ctx.dimension == 2 ? Vec3(0.0, -9.81, 0.0) : Vec3(0.0, 0.0, -9.81);
  run.gravity = detail::point_or(r, "gravity", ctx, down);
  // No domain: particles are never removed (an empty box, see dem/system.hpp).
  if (r.has("domain")) detail::read_box(r, "domain", ctx, run.domain_min, run.domain_max);
  run.skin = number_in(r, "skin", 0.0, non_negative());
  const auto seed = r.integer("seed", run.seed);
  r.expect(seed >= 0 && seed <= UINT_MAX, "seed", "an integer in [0, 4294967295]");
  run.seed = static_cast<unsigned>(seed);
  run.ke_blowup_factor = number_in(r, "ke_blowup_factor", run.ke_blowup_factor, non_negative());
  run.backend = r.enumeration("backend", detail::kBackends, run.backend);
  r.finish();
  return run;
}

// Everything in [contact] except the pairs, which need the material names.
dem::ContactParams read_contact(TomlReader& r) {
  dem::ContactParams c;
  const auto law = r.enumeration("model", detail::law_names<dem::ContactLaws>(),
                                 dem::ContactLaws::index_of(c.model));
  c.model = dem::ContactLaws::names[law];
  c.rolling = r.enumeration("rolling", detail::kRollingModels, c.rolling);
  c.friction_rule = r.enumeration("friction_rule", detail::kPairRules, c.friction_rule);
  c.lock_rotation = r.boolean("lock_rotation", c.lock_rotation);
  c.local_damping = number_in(r, "local_damping", c.local_damping, between(0.0, 1.0, false, true));
  c.dashpot_may_pull = r.boolean("dashpot_may_pull", c.dashpot_may_pull);
  c.tangential_damping = number_in(r, "tangential_damping", c.tangential_damping, non_negative());
  c.kuen_wall_depth = number_in(r, "kuen_wall_depth", c.kuen_wall_depth, positive());
  c.kuen_particle_factor =
      number_in(r, "kuen_particle_factor", c.kuen_particle_factor, between(0.0, 1.0, false, false));
  c.kuen_reference_step =
      number_in(r, "kuen_reference_step", c.kuen_reference_step, non_negative());
  c.epsd_stiffness_factor =
      number_in(r, "epsd_stiffness_factor", c.epsd_stiffness_factor, positive());
  c.epsd_damping_ratio = number_in(r, "epsd_damping_ratio", c.epsd_damping_ratio, non_negative());
  return c;
}

dem::OutputParams read_output(TomlReader& r) {
  dem::OutputParams o;
  o.snapshot_interval = number_in(r, "snapshot_interval", 0.0, non_negative());
  o.series_interval = number_in(r, "series_interval", 0.0, non_negative());
  o.checkpoint_interval = number_in(r, "checkpoint_interval", 0.0, non_negative());
  o.write_snapshots = r.boolean("snapshots", o.write_snapshots);
  r.finish();
  return o;
}

// Particles need a mass: every material they use must have a density.
void check_densities(const dem::DemScenario& s, std::vector<TomlReader>& material_readers) {
  for (const auto& source : s.sources) {
    std::vector<std::string> used = {source.material};
    for (const auto& p : source.particles) used.push_back(p.material);
    for (std::size_t i = 0; i < s.materials.size(); ++i) {
      const bool is_used = std::find(used.begin(), used.end(), s.materials[i].name) != used.end();
      if (is_used && s.materials[i].density <= 0.0) {
        material_readers[i].fail("density",
                                 fmt::format("missing: material '{}' is used by particles, which "
                                             "need a density (expected a positive number, kg/m^3)",
                                             s.materials[i].name));
      }
    }
  }
}

toml::table parse_toml(std::string_view text, const std::string& path) {
  try {
    return toml::parse(text, path);
  } catch (const toml::parse_error& e) {
    throw InputError(fmt::format("{}:{}:{}: TOML syntax error: {}", path, e.source().begin.line,
                                 e.source().begin.column, e.description()));
  }
}

// Scenario files are small; a device, a pipe or a huge file would be read
// until memory runs out (/dev/zero) or for ever.
constexpr std::uintmax_t kMaxScenarioBytes = 16u << 20;

// Why path cannot be read as a scenario file ("is a folder"), or "".
std::string scenario_file_problem(const std::filesystem::path& path) {
  namespace fs = std::filesystem;
  std::error_code ec;
  const fs::file_status status = fs::status(path, ec);
  if (status.type() == fs::file_type::not_found) return "does not exist";
  if (ec) return fmt::format("cannot be read ({})", ec.message());
  if (status.type() == fs::file_type::directory) return "is a folder, not a scenario file";
  if (status.type() != fs::file_type::regular)
    return "is not a regular file (a device, a pipe or a socket), not a scenario file";
  const std::uintmax_t size = fs::file_size(path, ec);
  if (!ec && size > kMaxScenarioBytes)
    return fmt::format("has {} bytes; a scenario file may have at most 16 MiB", size);
  return "";
}

std::string read_text(const std::string& path) {
  if (const std::string problem = scenario_file_problem(path); !problem.empty())
    throw InputError(fmt::format("{}: {}", path, problem));
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(fmt::format("{}: cannot open the scenario file", path));
  // The limit holds while reading too, should the file have grown since.
  std::string text;
  char chunk[1 << 16];
  while (in.read(chunk, sizeof chunk) || in.gcount() > 0) {
    text.append(chunk, static_cast<std::size_t>(in.gcount()));
    if (text.size() > kMaxScenarioBytes)
      throw InputError(fmt::format("{}: more than the 16 MiB a scenario file may have", path));
  }
  return text;
}

// Tables merge key by key; any other value, arrays of tables included,
// replaces the base's. Values are moved, not copied: a copy would lose its
// source position, and an error in it would then blame --set.
void merge_over(toml::table& base, toml::table&& top) {
  for (auto&& [key, node] : top) {
    toml::node* below = base.get(key);
    if (below && below->is_table() && node.is_table()) {
      merge_over(*below->as_table(), std::move(*node.as_table()));
    } else {
      // A named reference: clang before 16 cannot capture a structured binding.
      const toml::key& name = key;
      node.visit([&](auto&& value) { base.insert_or_assign(name, std::move(value)); });
    }
  }
}

// extends = "base.toml": this file's values over the base scenario's
// (relative to this file's folder; bases may extend further bases).
void resolve_extends(toml::table& table, const std::string& path, int depth) {
  const toml::node* extends = table.get("extends");
  if (!extends) return;
  const int line = static_cast<int>(extends->source().begin.line);
  if (!extends->is_string())
    throw InputError(
        fmt::format("{}:{}: 'extends': expected the path of a base scenario file", path, line));
  if (depth >= 8)
    throw InputError(fmt::format(
        "{}:{}: 'extends': more than 8 levels of base scenarios (a cycle?)", path, line));
  const std::string given = *extends->value<std::string>();
  if (given.empty())
    throw InputError(fmt::format(
        "{}:{}: 'extends': expected the path of a base scenario file, got \"\"", path, line));
  std::filesystem::path base_path = given;
  if (base_path.is_relative()) base_path = std::filesystem::path(path).parent_path() / base_path;
  if (const std::string problem = scenario_file_problem(base_path); !problem.empty())
    throw InputError(fmt::format("{}:{}: 'extends': base scenario {} {}", path, line,
                                 base_path.string(), problem));
  toml::table base = parse_toml(read_text(base_path.string()), base_path.string());
  resolve_extends(base, base_path.string(), depth + 1);
  table.erase("extends");
  merge_over(base, std::move(table));
  table = std::move(base);
}

}  // namespace

ScenarioFile load_scenario_text(std::string_view text, const std::string& path,
                                const std::vector<std::string>& overrides) {
  ScenarioFile file{path, "", parse_toml(text, path)};
  resolve_extends(file.table, path, 0);
  try {
    apply_overrides(file.table, overrides);
  } catch (const InputError& e) {
    throw InputError(fmt::format("{}: {}", path, e.what()));
  }
  TomlReader root(file.table, path);
  root.required_enum("method", kMethods);
  file.method = root.required_string("method");
  return file;
}

ScenarioFile load_scenario_file(const std::string& path,
                                const std::vector<std::string>& overrides) {
  return load_scenario_text(read_text(path), path, overrides);
}

dem::DemScenario parse_dem_scenario(const ScenarioFile& file) {
  TomlReader root(file.table, file.path);
  // Unknown top-level tables first: a misspelt [materails] would otherwise
  // show up as a confusing "missing [[materials]]".
  for (std::string_view key : kTopLevelKeys) root.mark_read(key);
  root.finish();

  dem::DemScenario s;
  const std::string method = root.required_string("method");
  if (method != "dem") root.expect(false, "method", "\"dem\"");
  s.name = root.string("name", std::filesystem::path(file.path).stem().string());
  s.description = root.string("description", "");

  DemContext ctx;
  ctx.folder = std::filesystem::path(file.path).parent_path();
  TomlReader run = root.required_table("run");
  s.run = read_run(run, ctx);

  const toml::table empty;
  TomlReader contact = detail::table_or_empty(root, "contact", empty);
  s.contact = read_contact(contact);

  std::vector<TomlReader> material_readers = root.tables("materials");
  if (material_readers.empty()) {
    root.fail("materials", "missing: at least one [[materials]] table is needed");
  }
  s.materials = detail::read_materials(material_readers, s.contact.model);
  for (const auto& m : s.materials) ctx.material_names.push_back(m.name);
  s.contact.pairs = detail::read_pairs(contact, ctx);
  contact.finish();

  if (auto flume = root.optional_table("flume")) detail::read_flume(*flume, s, ctx);
  if (auto dam = root.optional_table("dam_break")) {
    if (s.flume) dam->fail("dam_break", "a scenario has either [flume] or [dam_break], not both");
    detail::read_dam_break(*dam, s, ctx);
  }
  const std::size_t generated_walls = s.walls.size();
  std::vector<TomlReader> walls = root.tables("walls");
  for (std::size_t i = 0; i < walls.size(); ++i) {
    auto wall = detail::read_wall(walls[i], i, ctx);
    detail::check_unique_name(
        walls[i], s.walls, wall.name, "wall name", "used", [&](std::size_t j) {
          return j < generated_walls ? std::string("by [flume]")
                                     : fmt::format("by line {}", walls[j - generated_walls].line());
        });
    s.walls.push_back(std::move(wall));
  }
  for (const auto& w : s.walls) ctx.wall_names.push_back(w.name);

  std::vector<TomlReader> sources = root.tables("particles");
  if (sources.empty() && s.sources.empty())
    root.fail("particles",
              "missing: at least one [[particles]] table (or a [flume.release] or "
              "[dam_break.release]) is needed");
  for (TomlReader& r : sources) s.sources.push_back(detail::read_source(r, ctx));
  std::vector<TomlReader> membranes = root.tables("membranes");
  // Grain-membrane contacts have one law (membrane/contact.hpp); the run's
  // contact law must be that one, so that no contact silently uses another.
  using MembraneLaw = dem::membrane::ContactLaw;
  if (!membranes.empty() && s.contact.model != MembraneLaw::name)
    membranes[0].fail("material",
                      fmt::format("grain-membrane contacts use the '{}' law: membranes need "
                                  "contact.model = \"{}\" (got \"{}\")",
                                  MembraneLaw::name, MembraneLaw::name, s.contact.model));
  for (std::size_t i = 0; i < membranes.size(); ++i) {
    auto m = detail::read_membrane(membranes[i], i, ctx);
    detail::check_unique_name(
        membranes[i], s.membranes, m.name, "membrane name", "used",
        [&](std::size_t j) { return fmt::format("at line {}", membranes[j].line()); });
    s.membranes.push_back(std::move(m));
  }
  check_densities(s, material_readers);
  if (auto tri = root.optional_table("triaxial")) detail::read_triaxial(*tri, s);
  if (auto hs = root.optional_table("hollow_sphere")) detail::read_hollow_sphere(*hs, s);

  TomlReader output = detail::table_or_empty(root, "output", empty);
  s.output = read_output(output);
  if (auto gr = root.optional_table("gripper")) detail::read_gripper(*gr, s, ctx);
  if (auto bm = root.optional_table("beam")) detail::read_beam(*bm, s);
  root.finish();
  return s;
}

}  // namespace talus::io
