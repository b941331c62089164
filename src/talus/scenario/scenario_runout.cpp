// Runout scenario files: [run], [path], [material], [earth_pressure],
// [smoothing], [release], [output]. Every key goes through a TomlReader, so a
// bad or unknown key is reported with file, line and key before anything runs.
#include "talus/scenario/scenario_runout.hpp"

#include <fmt/format.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>
#include <sstream>

#include "talus/core/error.hpp"
#include "talus/io/raster.hpp"
#include "talus/io/raster_resample.hpp"
#include "talus/runout/grid/path_grid.hpp"
#include "talus/scenario/declared_keys.hpp"
#include "talus/scenario/scenario_detail.hpp"
#include "talus/scenario/scenario_grid_rasters.hpp"
#include "talus/scenario/scenario_two_phase.hpp"

namespace talus::io {
namespace {

using detail::between;
using detail::non_negative;
using detail::number_in;
using detail::positive;
using detail::required_number_in;
using grid_rasters::GridRole;
using grid_rasters::mark_domain;
using grid_rasters::read_grid;
using runout::EarthPressureMode;
using runout::PathKind;
using runout::ReleaseKind;

const std::vector<std::string_view> kTopLevelKeys = {
    "method",  "name",   "description", "run",   "path",  "material", "earth_pressure", "smoothing",
    "release", "output", "terrain",     "solid", "fluid", "drag",     "hydrology"};
using runout::GridBoundary;
using runout::RunoutModel;
const EnumNames<RunoutModel> kModels = {
    {"dan", RunoutModel::Dan}, {"fv2d", RunoutModel::Fv2d}, {"two_phase", RunoutModel::TwoPhase}};

bool on_grid(RunoutModel m) { return m != RunoutModel::Dan; }
const EnumNames<GridBoundary> kBoundaries = {{"wall", GridBoundary::Wall},
                                             {"open", GridBoundary::Open}};
const EnumNames<PathKind> kPathKinds = {{"flume", PathKind::Flume}, {"profile", PathKind::Profile}};
const EnumNames<ReleaseKind> kReleaseKinds = {{"flume", ReleaseKind::Flume},
                                              {"polygon", ReleaseKind::Polygon}};
const EnumNames<EarthPressureMode> kPressureModes = {
    {"hungr", EarthPressureMode::Hungr},
    {"savage_hutter", EarthPressureMode::SavageHutter},
    {"constant", EarthPressureMode::Constant}};
const EnumNames<runout::PressureForm> kPressureForms = {
    {"gradient", runout::PressureForm::Gradient}, {"divergence", runout::PressureForm::Divergence}};

void read_run(TomlReader& r, runout::RunoutScenario& s) {
  s.model = r.enumeration("model", kModels, RunoutModel::Dan);
  const bool grid = on_grid(s.model);
  auto& c = s.control;
  c.duration = required_number_in(r, "duration", positive());
  if (r.is_string("time_step")) {
    r.required_enum<int>("time_step", {{"auto", 0}});
    c.time_step = 0.0;
  } else {
    const auto dt = r.optional_number("time_step");
    r.expect(!dt || *dt > 0, "time_step", "a positive number (s) or \"auto\"");
    c.time_step = dt.value_or(0.0);
  }
  if (grid) {
    // The MUSCL scheme keeps depths positive up to 0.5 (fv2d.hpp).
    c.courant = number_in(r, "courant", 0.45, between(0.0, 0.5, true, false));
    s.grid.max_time_step = number_in(r, "max_time_step", s.grid.max_time_step, positive());
    if (s.model == RunoutModel::TwoPhase)
      r.reject({"stop_momentum_fraction"}, "is only used by model 'fv2d'");
    else
      c.stop_momentum_fraction = number_in(r, "stop_momentum_fraction", c.stop_momentum_fraction,
                                           between(0.0, 1.0, false, true));
  } else {
    r.reject({"max_time_step", "stop_momentum_fraction"},
             "is only used by the grid models 'fv2d' and 'two_phase'");
    c.courant = number_in(r, "courant", c.courant, between(0.0, 1.0, true, false));
  }
  s.params.gravity = number_in(r, "gravity", s.params.gravity, positive());
  c.stop_at_rest = r.boolean("stop_at_rest", c.stop_at_rest);
  r.finish();
}

// grid: the scenario's grid when a grid model runs on the path (its cells).
void read_path(TomlReader& r, const detail::DemContext& ctx, runout::PathSpec& p,
               runout::GridSpec* grid = nullptr) {
  p.kind = r.required_enum("type", kPathKinds);
  if (grid) {
    if (p.kind != PathKind::Flume)
      r.fail("type", "a grid model (fv2d, two_phase) on a path takes type 'flume'");
    grid->on_path = true;
    grid->cell_size = required_number_in(r, "cell_size", positive());
    const auto rows = r.integer("rows", static_cast<std::int64_t>(grid->rows));
    r.expect(rows >= 1 && rows <= 1000, "rows", "an integer in [1, 1000]");
    grid->rows = static_cast<std::size_t>(rows);
    grid->front_depth = number_in(r, "front_depth", grid->front_depth, positive());
  } else {
    r.reject({"cell_size", "rows", "front_depth"},
             "is only used by the grid models 'fv2d' and 'two_phase' on a path");
  }
  p.spacing = number_in(r, "spacing", p.spacing, positive());
  if (p.kind == PathKind::Flume) {
    r.reject({"file", "smoothing_length", "barrier_start"},
             "is not used by a path of type 'flume'");
    p.flume = detail::read_flume_shape(r);
    p.width = number_in(r, "width", p.width, positive());
    detail::resolve_flume_shape(r, p.flume);
  } else {
    r.reject({"beta", "arc_radius", "l_star", "barrier_length", "width"},
             "is not used by a path of type 'profile' (the width is the CSV's third column)");
    p.profile_file = detail::required_file(r, "file", ctx);
    p.smoothing_length = number_in(r, "smoothing_length", 0.0, non_negative());
    p.barrier_start = r.optional_number("barrier_start");
    read_profile_csv(p.profile_file, p.profile_points, p.profile_widths);
  }
  r.finish();
}

void read_material(TomlReader& r, runout::DanParams& d) {
  d.density = required_number_in(r, "density", positive());
  const double phi_i = r.required_angle("internal_friction");
  r.expect(phi_i > 0 && phi_i < M_PI / 2, "internal_friction", "an angle in (0, 90) degrees");
  d.pressure.phi_internal = phi_i;
  auto& rh = d.rheology;
  using Laws = runout::RheologyLaws;
  rh.law = r.enumeration("rheology", detail::law_names<Laws>(), std::size_t{0});
  detail::read_law<Laws>(r, rh.law, rh, "rheology", detail::OtherLaws::Refuse);
  d.pressure.tan_phi_basal = rh.tan_friction;
  r.finish();
}

void read_earth_pressure(TomlReader& r, runout::DanParams& d, RunoutModel model) {
  runout::EarthPressure& e = d.pressure;
  const bool grid = on_grid(model);
  const std::string name = detail::name_of(kModels, model);
  if (grid)
    r.reject({"form"},
             fmt::format("is not used by model '{}' (its fluxes are the divergence form)", name));
  else
    d.pressure_form = r.enumeration("form", kPressureForms, d.pressure_form);
  e.mode = r.enumeration("model", kPressureModes,
                         grid ? EarthPressureMode::SavageHutter : EarthPressureMode::Hungr);
  if (grid) {
    if (e.mode == EarthPressureMode::Hungr)
      r.fail("model", fmt::format("the 'hungr' law needs block strains (1D); model '{}' takes "
                                  "'savage_hutter' or 'constant'",
                                  name));
    r.reject({"lambda", "modify_basal_angle", "passive_strain", "initial"},
             fmt::format("is not used by model '{}' (k_a / k_p from the flow's divergence)", name));
  }
  if (e.mode == EarthPressureMode::Constant) {
    r.reject({"lambda", "passive_strain", "initial", "modify_basal_angle"},
             "is not used by the 'constant' model");
    e.constant = required_number_in(r, "k", non_negative());
  } else {
    r.reject({"k"}, "is only used by the 'constant' model");
    e.lambda = number_in(r, "lambda", e.lambda, non_negative());
    e.modify_basal_angle = r.boolean("modify_basal_angle", e.modify_basal_angle);
    if (e.mode == EarthPressureMode::Hungr) {
      e.passive_strain = number_in(r, "passive_strain", e.passive_strain, positive());
      e.constant = number_in(r, "initial", e.constant, positive());
    } else {
      r.reject({"passive_strain", "initial"}, "is only used by the 'hungr' model");
    }
  }
  r.finish();
}

void read_smoothing(TomlReader& r, runout::SmoothingParams& s) {
  s.enabled = r.boolean("enabled", s.enabled);
  s.c_end = number_in(r, "c_end", s.c_end, non_negative());
  s.c_inner = number_in(r, "c_inner", s.c_inner, non_negative());
  s.reference_time_step = number_in(r, "reference_time_step", s.reference_time_step, positive());
  r.finish();
}

void read_release(TomlReader& r, const detail::DemContext& ctx, runout::RunoutScenario& s) {
  const runout::PathSpec& path = s.path;
  runout::ReleaseSpec& rel = s.release;
  rel.kind = r.required_enum("type", kReleaseKinds);
  if (s.grid.on_path) {
    r.reject({"blocks"}, "is only used by model 'dan' (the grid's cells carry the release)");
    if (s.model == RunoutModel::TwoPhase) two_phase_keys::read_release_fractions(r, ctx, s);
  } else {
    const auto blocks = r.integer("blocks", static_cast<std::int64_t>(rel.blocks));
    r.expect(blocks >= 2 && blocks <= 1000000, "blocks", "an integer in [2, 1000000]");
    rel.blocks = static_cast<std::size_t>(blocks);
  }
  if (rel.kind == ReleaseKind::Flume) {
    r.reject({"polygon"}, "is not used by a release of type 'flume'");
    if (path.kind != PathKind::Flume)
      r.fail("type", "a release of type 'flume' needs a path of type 'flume'");
  } else {
    for (const Vec3& v : r.vec3_list("polygon", 2)) rel.polygon.emplace_back(v.x(), v.y());
    r.expect(rel.polygon.size() >= 3, "polygon", "three or more points [x, y]");
  }
  r.finish();
}

void read_terrain(TomlReader& r, const detail::DemContext& ctx, runout::GridSpec& g) {
  g.elevation = read_grid(r, "file", ctx, g.terrain_file, g, GridRole::Terrain);
  mark_domain(r, g);
  if (r.has("obstacles"))
    g.obstacles = read_grid(r, "obstacles", ctx, g.obstacles_file, g, GridRole::OnGrid);
  g.boundary = r.enumeration("boundary", kBoundaries, g.boundary);
  const auto order = r.integer("order", g.order);
  r.expect(order == 1 || order == 2, "order", "1 (first order) or 2 (MUSCL)");
  g.order = static_cast<int>(order);
  g.dry_depth = number_in(r, "dry_depth", g.dry_depth, positive());
  r.finish();
}

void read_grid_release(TomlReader& r, const detail::DemContext& ctx, runout::RunoutScenario& s) {
  runout::GridSpec& g = s.grid;
  r.required_enum<int>("type", {{"raster", 0}});
  g.release_depth = read_grid(r, "file", ctx, g.release_file, g, GridRole::Resampled);
  for (std::size_t c = 0; c < g.inside.size(); ++c)
    if (!g.inside[c] && g.release_depth[c] > 0.0)
      r.fail("file", fmt::format("{}: cell (column {}, row {}) releases {} m where the terrain "
                                 "({}) has no elevation; expected 0 or no-data outside the terrain",
                                 g.release_file, c % g.shape.nx, c / g.shape.nx, g.release_depth[c],
                                 g.terrain_file));
  if (s.model == RunoutModel::TwoPhase) two_phase_keys::read_release_fractions(r, ctx, s);
  r.finish();
}

void read_output(TomlReader& r, runout::RunoutScenario& s) {
  s.control.series_interval = number_in(r, "series_interval", 0.01, positive());
  s.control.checkpoint_interval = number_in(r, "checkpoint_interval", 0.0, non_negative());
  if (on_grid(s.model)) {
    // Snapshot maps are large: none unless asked for.
    s.control.snapshot_interval = number_in(r, "snapshot_interval", 0.0, non_negative());
    if (s.grid.on_path) {
      s.tail_fraction =
          number_in(r, "tail_fraction", s.tail_fraction, between(0.0, 1.0, true, true));
    } else {
      r.reject({"tail_fraction"}, "is only used on a path (the deposit's tail along it)");
    }
    r.finish();
    return;
  }
  s.control.snapshot_interval = number_in(r, "snapshot_interval", 0.1, non_negative());
  s.tail_fraction = number_in(r, "tail_fraction", s.tail_fraction, between(0.0, 1.0, true, true));
  r.finish();
}

double deg(double rad) { return rad * 180.0 / M_PI; }

}  // namespace

void read_profile_csv(const std::string& path, std::vector<Eigen::Vector2d>& points,
                      std::vector<double>& widths) {
  std::ifstream in(path);
  if (!in) throw InputError(fmt::format("{}: cannot open the profile file", path));
  std::string line;
  int line_no = 0;
  bool header = false;
  while (std::getline(in, line)) {
    ++line_no;
    if (!line.empty() && line.back() == '\r') line.pop_back();
    if (line.find_first_not_of(" \t") == std::string::npos || line[0] == '#') continue;
    std::string compact;
    for (char c : line)
      if (c != ' ' && c != '\t') compact += c;
    if (!header) {
      if (compact != "x,y,width")
        throw InputError(fmt::format("{}:{}: expected the header \"x,y,width\", got \"{}\"", path,
                                     line_no, line));
      header = true;
      continue;
    }
    std::stringstream row(compact);
    double v[3];
    std::string cell;
    int count = 0;
    while (std::getline(row, cell, ',')) {
      std::size_t used = 0;
      bool ok = count < 3;
      try {
        if (ok) v[count] = std::stod(cell, &used);
      } catch (const std::exception&) {
        ok = false;
      }
      if (!ok || used != cell.size() || !std::isfinite(v[count]))
        throw InputError(fmt::format("{}:{}: expected three numbers x,y,width, got \"{}\"", path,
                                     line_no, line));
      ++count;
    }
    if (count != 3)
      throw InputError(
          fmt::format("{}:{}: expected three numbers x,y,width, got \"{}\"", path, line_no, line));
    if (!points.empty() && !(v[0] > points.back().x()))
      throw InputError(
          fmt::format("{}:{}: x = {} does not increase along the profile", path, line_no, v[0]));
    if (!(v[2] > 0))
      throw InputError(fmt::format("{}:{}: width {} must be positive", path, line_no, v[2]));
    points.emplace_back(v[0], v[1]);
    widths.push_back(v[2]);
  }
  if (points.size() < 2)
    throw InputError(fmt::format("{}: a profile needs at least two points", path));
}

runout::RunoutScenario parse_runout_scenario(const ScenarioFile& file) {
  {
    // Unknown tables first; a second reader, so that the tables of the other
    // model (marked read here) are still refused by root.reject below.
    TomlReader top(file.table, file.path);
    for (std::string_view key : kTopLevelKeys) top.mark_read(key);
    top.finish();
  }
  TomlReader root(file.table, file.path);
  runout::RunoutScenario s;
  const std::string method = root.required_string("method");
  if (method != "runout") root.expect(false, "method", "\"runout\"");
  s.name = root.string("name", std::filesystem::path(file.path).stem().string());
  s.description = root.string("description", "");
  detail::DemContext ctx;
  ctx.folder = std::filesystem::path(file.path).parent_path();
  const toml::table empty;

  TomlReader run = root.required_table("run");
  read_run(run, s);
  const bool grid = on_grid(s.model), two_phase = s.model == RunoutModel::TwoPhase;
  const std::string model = detail::name_of(kModels, s.model);
  if (grid && root.has("path") && !root.has("terrain")) {
    // A flume path extruded into the grid (grid/path_grid.hpp).
    root.reject({"smoothing"}, fmt::format("is not used by model '{}'", model));
    TomlReader path = root.required_table("path");
    read_path(path, ctx, s.path, &s.grid);
  } else if (grid) {
    root.reject({"path", "smoothing"},
                fmt::format("is not used by model '{}' (the terrain is [terrain])", model));
    TomlReader terrain = root.required_table("terrain");
    read_terrain(terrain, ctx, s.grid);
  } else {
    root.reject({"terrain"},
                "is only used by models 'fv2d' and 'two_phase' (set run.model = \"fv2d\")");
    TomlReader path = root.required_table("path");
    read_path(path, ctx, s.path);
  }
  if (two_phase) {
    root.reject({"material"}, "is not used by model 'two_phase' (it reads [solid] and [fluid])");
    two_phase_keys::read_tables(root, ctx, s);
  } else {
    root.reject({"solid", "fluid", "drag", "hydrology"}, "is only used by model 'two_phase'");
    TomlReader material = root.required_table("material");
    read_material(material, s.params);
  }
  TomlReader pressure = detail::table_or_empty(root, "earth_pressure", empty);
  read_earth_pressure(pressure, s.params, s.model);
  if (two_phase) {
    // The solid's angles are [solid]'s; the law and k are [earth_pressure]'s.
    auto& e = s.two_phase.params.pressure;
    e.mode = s.params.pressure.mode, e.constant = s.params.pressure.constant;
  }
  if (!grid) {
    TomlReader smoothing = detail::table_or_empty(root, "smoothing", empty);
    read_smoothing(smoothing, s.params.smoothing);
  }
  TomlReader release = root.required_table("release");
  if (grid && !s.grid.on_path)
    read_grid_release(release, ctx, s);
  else
    read_release(release, ctx, s);
  TomlReader output = detail::table_or_empty(root, "output", empty);
  read_output(output, s);
  if (s.grid.on_path) {
    try {
      runout::grid_from_path(s);
    } catch (const InputError& e) {
      root.fail("path", e.what());
    }
  }
  root.finish();
  return s;
}

nlohmann::ordered_json runout_scenario_to_json(const runout::RunoutScenario& s) {
  using Json = nlohmann::ordered_json;
  const auto& p = s.params;
  const bool grid = on_grid(s.model), two_phase = s.model == RunoutModel::TwoPhase;
  Json run = {{"model", detail::name_of(kModels, s.model)}, {"duration", s.control.duration}};
  run["time_step"] = s.control.time_step > 0 ? Json(s.control.time_step) : Json("auto");
  run["courant"] = s.control.courant;
  run["gravity"] = p.gravity;
  run["stop_at_rest"] = s.control.stop_at_rest;
  if (grid) {
    run["max_time_step"] = s.grid.max_time_step;
    if (!two_phase) run["stop_momentum_fraction"] = s.control.stop_momentum_fraction;
  }
  Json path = {{"type", detail::name_of(kPathKinds, s.path.kind)}, {"spacing", s.path.spacing}};
  if (s.path.kind == PathKind::Flume) {
    detail::write_flume_shape(path, s.path.flume);
    path["width"] = s.path.width;
  } else {
    path["file"] = s.path.profile_file;
    path["smoothing_length"] = s.path.smoothing_length;
    if (s.path.barrier_start) path["barrier_start"] = *s.path.barrier_start;
  }
  Json material = {{"density", p.density},
                   {"internal_friction", deg(p.pressure.phi_internal)},
                   {"rheology", runout::RheologyLaws::names[p.rheology.law]}};
  detail::write_law<runout::RheologyLaws>(material, p.rheology.law, p.rheology);
  Json pressure = {{"model", detail::name_of(kPressureModes, p.pressure.mode)}};
  if (p.pressure.mode == EarthPressureMode::Constant) {
    pressure["k"] = p.pressure.constant;
  } else {
    pressure["lambda"] = p.pressure.lambda;
    pressure["modify_basal_angle"] = p.pressure.modify_basal_angle;
    if (p.pressure.mode == EarthPressureMode::Hungr) {
      pressure["passive_strain"] = p.pressure.passive_strain;
      pressure["initial"] = p.pressure.constant;
    }
  }
  if (!grid) pressure["form"] = detail::name_of(kPressureForms, p.pressure_form);
  if (grid) {
    if (p.pressure.mode != EarthPressureMode::Constant)
      pressure = {{"model", detail::name_of(kPressureModes, p.pressure.mode)}};
    Json root = {
        {"method", "runout"}, {"name", s.name}, {"description", s.description}, {"run", run}};
    if (s.grid.on_path) {
      path["cell_size"] = s.grid.cell_size;
      path["rows"] = s.grid.rows;
      path["front_depth"] = s.grid.front_depth;
      root["path"] = path;
    } else {
      Json terrain = {{"file", s.grid.terrain_file}};
      if (!s.grid.obstacles_file.empty()) terrain["obstacles"] = s.grid.obstacles_file;
      terrain["boundary"] = detail::name_of(kBoundaries, s.grid.boundary);
      terrain["order"] = s.grid.order;
      terrain["dry_depth"] = s.grid.dry_depth;
      root["terrain"] = terrain;
    }
    if (!two_phase) root["material"] = material;
    root["earth_pressure"] = pressure;
    if (s.grid.on_path) {
      Json release = {{"type", detail::name_of(kReleaseKinds, s.release.kind)}};
      if (s.release.kind == ReleaseKind::Polygon) {
        Json poly = Json::array();
        for (const auto& v : s.release.polygon) poly.push_back({v.x(), v.y()});
        release["polygon"] = poly;
      }
      root["release"] = release;
    } else {
      root["release"] = {{"type", "raster"}, {"file", s.grid.release_file}};
    }
    if (two_phase) two_phase_keys::write(root, s);
    root["output"] = {{"series_interval", s.control.series_interval},
                      {"snapshot_interval", s.control.snapshot_interval},
                      {"checkpoint_interval", s.control.checkpoint_interval}};
    if (s.grid.on_path) root["output"]["tail_fraction"] = s.tail_fraction;
    return root;
  }
  Json smoothing = {{"enabled", p.smoothing.enabled},
                    {"c_end", p.smoothing.c_end},
                    {"c_inner", p.smoothing.c_inner},
                    {"reference_time_step", p.smoothing.reference_time_step}};
  Json release = {{"type", detail::name_of(kReleaseKinds, s.release.kind)},
                  {"blocks", s.release.blocks}};
  if (s.release.kind == ReleaseKind::Polygon) {
    Json poly = Json::array();
    for (const auto& v : s.release.polygon) poly.push_back({v.x(), v.y()});
    release["polygon"] = poly;
  }
  Json output = {{"series_interval", s.control.series_interval},
                 {"snapshot_interval", s.control.snapshot_interval},
                 {"checkpoint_interval", s.control.checkpoint_interval},
                 {"tail_fraction", s.tail_fraction}};
  return Json{{"method", "runout"},
              {"name", s.name},
              {"description", s.description},
              {"run", run},
              {"path", path},
              {"material", material},
              {"earth_pressure", pressure},
              {"smoothing", smoothing},
              {"release", release},
              {"output", output}};
}

std::string runout_scenario_to_toml(const runout::RunoutScenario& s) {
  return detail::json_to_toml(runout_scenario_to_json(s));
}

}  // namespace talus::io
