// Reading and writing MPM scenarios.
#include "talus/scenario/scenario_mpm.hpp"

#include <fmt/format.h>

#include <filesystem>

#include "talus/geometry/oriented_box.hpp"
#include "talus/scenario/declared_keys.hpp"
#include "talus/scenario/scenario_detail.hpp"
#include "talus/scenario/scenario_mpm_membranes.hpp"

namespace talus::io {
namespace {

using detail::between;
using detail::DemContext;
using detail::non_negative;
using detail::number_in;
using detail::positive;
using detail::required_number_in;
using mpm::BoundaryKind;

const EnumNames<mpm::ShapeKind> kShapes = {{"gimp", mpm::ShapeKind::Gimp},
                                           {"linear", mpm::ShapeKind::Linear},
                                           {"cubic_bspline", mpm::ShapeKind::CubicBSpline}};
const EnumNames<mpm::Scheme> kSchemes = {{"musl", mpm::Scheme::Musl}, {"usl", mpm::Scheme::Usl}};
const EnumNames<BoundaryKind> kFaces = {
    {"roller", BoundaryKind::Roller}, {"fixed", BoundaryKind::Fixed}, {"free", BoundaryKind::Free}};
const EnumNames<int> kInitialStress = {{"none", 0}, {"geostatic", 1}};
const char* kFaceKeys[] = {"x_min", "x_max", "y_min", "y_max", "z_min", "z_max"};

const EnumNames<mpm::Transfer> kTransfers = {{"flip_pic", mpm::Transfer::FlipPic},
                                             {"apic", mpm::Transfer::Apic}};

// transfer, flip and volumetric_smoothing of [run] (after shape).
void read_transfer(TomlReader& r, mpm::SolverParams& p) {
  p.transfer = r.enumeration("transfer", kTransfers, p.transfer);
  if (p.transfer == mpm::Transfer::Apic) {
    r.reject({"flip"}, "is only used with transfer = \"flip_pic\"");
    r.expect(p.shape != mpm::ShapeKind::Linear, "transfer",
             "\"flip_pic\" with shape = \"linear\" (APIC needs \"gimp\" or \"cubic_bspline\": "
             "the linear hat's inertia tensor vanishes at the nodes)");
  } else {
    p.flip = number_in(r, "flip", p.flip, between(0.0, 1.0, false, false));
  }
  p.volumetric_smoothing = r.boolean("volumetric_smoothing", p.volumetric_smoothing);
}

void read_run(TomlReader& r, mpm::MpmScenario& s, DemContext& ctx) {
  const auto dimension = r.required_integer("dimension");
  r.expect(dimension == 2 || dimension == 3, "dimension", "2 or 3");
  s.dimension = ctx.dimension = static_cast<int>(dimension);
  s.duration = required_number_in(r, "duration", positive());
  s.ke_blowup_factor = number_in(r, "ke_blowup_factor", s.ke_blowup_factor, non_negative());
  auto& p = s.solver;
  if (r.is_string("time_step")) {
    r.required_enum<int>("time_step", {{"auto", 0}});
  } else {
    p.fixed_time_step = number_in(r, "time_step", 0.0, positive());
  }
  p.cfl = number_in(r, "cfl", p.cfl, between(0.0, 1.0, true, false));
  const Vec3 down = ctx.dimension == 2 ? Vec3(0.0, -9.81, 0.0) : Vec3(0.0, 0.0, -9.81);
  p.gravity = detail::point_or(r, "gravity", ctx, down);
  p.shape = r.enumeration("shape", kShapes, p.shape);
  p.scheme = r.enumeration("scheme", kSchemes, p.scheme);
  read_transfer(r, p);
  p.local_damping = number_in(r, "local_damping", p.local_damping, between(0.0, 1.0, false, true));
  if (auto bed = r.optional_table("plan_view")) {
    r.expect(s.dimension == 2, "plan_view",
             "no plan_view in dimension = 3 (a 3D run has its bed as a rigid body)");
    p.basal_friction = required_number_in(*bed, "basal_friction", non_negative());
    p.bed_normal_gravity = required_number_in(*bed, "normal_gravity", positive());
    bed->finish();
  }
  if (auto water = r.optional_table("water")) {
    auto& w = p.water;
    w.level = water->required_number("level");
    w.density = number_in(*water, "density", w.density, positive());
    w.drag_coefficient = required_number_in(*water, "drag_coefficient", non_negative());
    w.added_mass_coefficient = required_number_in(*water, "added_mass_coefficient", non_negative());
    water->finish();
  }
  r.finish();
}

void read_grid(TomlReader& r, mpm::MpmScenario& s, const DemContext& ctx) {
  s.grid.lo = detail::required_point(r, "min", ctx);
  s.grid.hi = detail::required_point(r, "max", ctx);
  for (int d = 0; d < ctx.dimension; ++d)
    if (!(s.grid.hi[d] > s.grid.lo[d])) r.fail("max", "expected every coordinate above min's");
  s.grid.cell_size = required_number_in(r, "cell_size", positive());
  s.grid.faces.fill(BoundaryKind::Roller);
  if (auto b = r.optional_table("boundaries")) {
    for (int f = 0; f < 2 * ctx.dimension; ++f) {
      const char* key = kFaceKeys[f];
      if (b->has(key) && !b->is_string(key)) {
        // A Coulomb wall: { friction = mu }.
        b->expect(b->table().get(key)->is_table(), key,
                  "\"roller\", \"fixed\", \"free\" or { friction = mu }");
        auto t = b->optional_table(key);
        s.grid.faces[f] = BoundaryKind::Friction;
        s.grid.friction[f] = required_number_in(*t, "friction", non_negative());
        t->finish();
        // The B-spline's ghost nodes fold part of the wall's reaction onto the
        // nodes inside, so the face nodes' normal impulse is not the weight
        // (a block decelerates at 0.83 or 1.64 mu g; docs/validation/mpm.md).
        b->expect(s.solver.shape != mpm::ShapeKind::CubicBSpline, key,
                  "\"roller\", \"fixed\" or \"free\" with shape = \"cubic_bspline\" (a "
                  "friction face needs \"gimp\" or \"linear\")");
        continue;
      }
      if (b->is_string(key) && b->optional_string(key) == "friction")
        b->fail(key, "a Coulomb wall is written { friction = mu } (mu >= 0)");
      s.grid.faces[f] = b->enumeration(key, kFaces, BoundaryKind::Roller);
    }
    b->finish();
  }
  r.finish();
}

// A material: its model's keys as the model declares them (mpm/materials.hpp).
mpm::MaterialParams read_material(TomlReader& r) {
  using Laws = mpm::MaterialLaws;
  mpm::MaterialParams m;
  m.name = r.required_string("name");
  const std::size_t law = r.required_enum("model", detail::law_names<Laws>());
  m.model = Laws::names[law];
  m.density = required_number_in(r, "density", positive());
  detail::read_law<Laws>(r, law, m, "model", detail::OtherLaws::Refuse);
  r.finish();
  return m;
}

// points_per_cell of a body: an integer in [1, 8].
int read_points_per_cell(TomlReader& r, int fallback) {
  const auto per_cell = r.integer("points_per_cell", fallback);
  r.expect(per_cell >= 1 && per_cell <= 8, "points_per_cell", "an integer in [1, 8]");
  return static_cast<int>(per_cell);
}

// Fails at "box" unless [min, max] lies inside the [grid].
void check_box_in_grid(TomlReader& r, const mpm::MpmScenario& s, const DemContext& ctx,
                       const Vec3& min, const Vec3& max) {
  for (int d = 0; d < ctx.dimension; ++d)
    if (min[d] < s.grid.lo[d] || max[d] > s.grid.hi[d])
      r.fail("box", "expected a box inside the [grid] (min to max)");
}

// Fails at "box" unless the body's box, turned by its angle about the hinge,
// lies inside the [grid].
void check_turned_box_in_grid(TomlReader& r, const mpm::MpmScenario& s, const DemContext& ctx,
                              const mpm::RigidBodyParams& b) {
  // A 2D body's axis stays z, so the 3D rotation is the builder's in both.
  const Eigen::Matrix3d q = mpm::rigid_rotation<3>(b);
  for (int corner = 0; corner < (1 << ctx.dimension); ++corner) {
    Vec3 c = b.min;
    for (int d = 0; d < ctx.dimension; ++d)
      if (corner >> d & 1) c[d] = b.max[d];
    const Vec3 y = b.motion.hinge + q * (c - b.motion.hinge);
    for (int d = 0; d < ctx.dimension; ++d)
      if (y[d] < s.grid.lo[d] - 1e-12 || y[d] > s.grid.hi[d] + 1e-12)
        r.fail("box",
               b.angle == 0.0
                   ? "expected a box inside the [grid] (min to max)"
                   : "expected a box inside the [grid] once turned by angle about the hinge");
  }
}

// Fails at "box" when the rigid body, turned, overlaps a material body: the
// first contact step would push the material out at whatever speed the
// overlap asks for. Touching (a block resting on a plate) is fine.
void check_clear_of_bodies(TomlReader& r, const mpm::MpmScenario& s, const DemContext& ctx,
                           const mpm::RigidBodyParams& b) {
  auto flat = [&](Vec3 v, double z) {  // a 2D box gets a depth so that z never separates
    if (ctx.dimension == 2) v.z() = z;
    return v;
  };
  const auto rigid = geometry::OrientedBox::turned(flat(b.min, -1.0), flat(b.max, 1.0),
                                                   mpm::rigid_rotation<3>(b), b.motion.hinge);
  for (std::size_t i = 0; i < s.bodies.size(); ++i) {
    const auto& body = s.bodies[i];
    const auto material = geometry::OrientedBox::turned(flat(body.min, -1.0), flat(body.max, 1.0),
                                                        Eigen::Matrix3d::Identity(), Vec3::Zero());
    const double depth = geometry::overlap_depth(rigid, material);
    if (depth > 1e-9)
      r.fail("box", fmt::format("expected a rigid body clear of the material: it overlaps "
                                "[[bodies]] #{} by {:.4g} m{}, so material would start inside it",
                                i + 1, depth, b.angle == 0.0 ? "" : " once turned"));
  }
}

mpm::BodyParams read_body(TomlReader& r, const mpm::MpmScenario& s, const DemContext& ctx) {
  mpm::BodyParams b;
  b.material = r.required_string("material");
  bool found = false;
  for (std::size_t i = 0; i < s.materials.size(); ++i)
    if (s.materials[i].name == b.material) b.material_index = static_cast<int>(i), found = true;
  if (!found) detail::check_material(r, "material", b.material, ctx);
  detail::read_box(r, "box", ctx, b.min, b.max);
  b.per_cell = read_points_per_cell(r, b.per_cell);
  b.velocity = detail::point_or(r, "velocity", ctx, Vec3::Zero());
  b.geostatic = r.enumeration("initial_stress", kInitialStress, 0) == 1;
  if (b.geostatic) {
    // k0 = 0 is a value (nu = 0 resolves to it), so "not given" is -1.
    b.k0 = r.has("k0") ? number_in(r, "k0", 0.0, non_negative()) : -1.0;
  } else {
    r.reject({"k0"}, "is only used with initial_stress = \"geostatic\"");
  }
  check_box_in_grid(r, s, ctx, b.min, b.max);
  r.finish();
  return b;
}

const EnumNames<mpm::RigidContact> kContacts = {{"friction", mpm::RigidContact::Friction},
                                                {"stick", mpm::RigidContact::Stick}};

// Boundary particles with prescribed motion. Angles in degrees, angular
// velocities in degrees per second (a number about z in 2D, a vector in 3D).
mpm::RigidBodyParams read_rigid_body(TomlReader& r, const mpm::MpmScenario& s,
                                     const DemContext& ctx) {
  mpm::RigidBodyParams b;
  detail::read_box(r, "box", ctx, b.min, b.max);
  b.per_cell = read_points_per_cell(r, b.per_cell);
  b.contact = r.enumeration("contact", kContacts, b.contact);
  if (b.contact == mpm::RigidContact::Friction)
    b.friction = number_in(r, "friction", 0.0, non_negative());
  else
    r.reject({"friction"}, "is only used with contact = \"friction\"");
  if (auto m = r.optional_table("motion")) {
    b.motion.velocity = detail::point_or(*m, "velocity", ctx, Vec3::Zero());
    if (ctx.dimension == 2) {
      b.motion.angular_velocity = Vec3(0.0, 0.0, deg2rad(m->number("angular_velocity", 0.0)));
    } else {
      b.motion.angular_velocity = m->vec3("angular_velocity", Vec3::Zero()).unaryExpr(&deg2rad);
    }
    b.motion.hinge = detail::point_or(*m, "hinge", ctx, Vec3::Zero());
    b.motion.start = number_in(*m, "start", 0.0, non_negative());
    b.motion.stop = number_in(*m, "stop", b.motion.stop, positive());
    m->expect(b.motion.stop > b.motion.start, "stop", "a time after start");
    m->finish();
  }
  b.angle = r.angle("angle", 0.0);
  if (ctx.dimension == 3) {
    b.axis = r.vec3("axis", Vec3::UnitZ());
    r.expect(b.axis.norm() > 0.0, "axis", "a non-zero vector [x, y, z]");
    b.axis = detail::unit(b.axis);
  } else {
    r.reject({"axis"}, "is only used in 3D (a 2D body turns about z)");
  }
  check_turned_box_in_grid(r, s, ctx, b);
  check_clear_of_bodies(r, s, ctx, b);
  r.finish();
  return b;
}

// [[membranes]] (scenario_mpm_membranes.cpp), names unique.
void read_membranes(TomlReader& root, mpm::MpmScenario& s, const DemContext& ctx) {
  std::vector<TomlReader> tables = root.tables("membranes");
  for (std::size_t i = 0; i < tables.size(); ++i) {
    auto m = detail::read_mpm_membrane(tables[i], i + 1, s, ctx);
    detail::check_unique_name(
        tables[i], s.membranes, m.name, "membrane", "defined",
        [&](std::size_t j) { return fmt::format("at line {}", tables[j].line()); });
    s.membranes.push_back(std::move(m));
  }
}

// [flume]: the flume's bed as a rigid friction wall, the release triangle
// filled with points of release.material (mpm/flume.hpp).
mpm::MpmFlumeParams read_flume(TomlReader& r, const mpm::MpmScenario& s, const DemContext& ctx) {
  mpm::MpmFlumeParams f;
  detail::require_2d_flume(r, ctx);
  f.shape = detail::read_flume_shape(r);
  f.wall_friction = r.required_angle("wall_friction");
  r.expect(f.wall_friction >= 0.0 && f.wall_friction < M_PI / 2, "wall_friction",
           "an angle in [0, 90) degrees");
  const auto layers = r.integer("wall_layers", f.wall_layers);
  r.expect(layers >= 1 && layers <= 8, "wall_layers", "an integer in [1, 8]");
  f.wall_layers = static_cast<int>(layers);
  f.measures = detail::read_flume_measures(r);
  detail::resolve_flume_shape(r, f.shape);
  if (auto release = r.optional_table("release")) {
    f.release_material = release->required_string("material");
    for (std::size_t i = 0; i < s.materials.size(); ++i)
      if (s.materials[i].name == f.release_material) f.release_material_index = static_cast<int>(i);
    if (f.release_material_index < 0)
      detail::check_material(*release, "material", f.release_material, ctx);
    f.release_per_cell = read_points_per_cell(*release, f.release_per_cell);
    release->finish();
  }
  r.finish();
  return f;
}

}  // namespace

mpm::MpmScenario parse_mpm_scenario(const ScenarioFile& file) {
  TomlReader root(file.table, file.path);
  for (std::string_view key : {"method", "name", "description", "run", "grid", "materials",
                               "bodies", "rigid_bodies", "membranes", "flume", "output"})
    root.mark_read(key);
  root.finish();
  mpm::MpmScenario s;
  if (root.required_string("method") != "mpm") root.expect(false, "method", "\"mpm\"");
  s.name = root.string("name", std::filesystem::path(file.path).stem().string());
  s.description = root.string("description", "");
  DemContext ctx;
  ctx.folder = std::filesystem::path(file.path).parent_path();
  TomlReader run = root.required_table("run");
  read_run(run, s, ctx);
  TomlReader grid = root.required_table("grid");
  read_grid(grid, s, ctx);
  std::vector<TomlReader> materials = root.tables("materials");
  if (materials.empty()) root.fail("materials", "missing: at least one [[materials]] table");
  for (std::size_t i = 0; i < materials.size(); ++i) {
    auto m = read_material(materials[i]);
    detail::check_unique_name(
        materials[i], s.materials, m.name, "material", "defined",
        [&](std::size_t j) { return fmt::format("at line {}", materials[j].line()); });
    ctx.material_names.push_back(m.name);
    s.materials.push_back(std::move(m));
  }
  if (auto flume = root.optional_table("flume")) s.flume = read_flume(*flume, s, ctx);
  std::vector<TomlReader> bodies = root.tables("bodies");
  if (bodies.empty() && !(s.flume && s.flume->release_material_index >= 0))
    root.fail("bodies", "missing: at least one [[bodies]] table (or a [flume.release])");
  for (auto& b : bodies) s.bodies.push_back(read_body(b, s, ctx));
  for (auto& b : root.tables("rigid_bodies")) s.rigid_bodies.push_back(read_rigid_body(b, s, ctx));
  read_membranes(root, s, ctx);
  if (auto out = root.optional_table("output")) {
    s.output.series_interval = number_in(*out, "series_interval", 0.0, non_negative());
    s.output.snapshot_interval = number_in(*out, "snapshot_interval", 0.0, non_negative());
    s.output.checkpoint_interval = number_in(*out, "checkpoint_interval", 0.0, non_negative());
    s.output.snapshots = out->boolean("snapshots", true);
    out->finish();
  }
  root.finish();
  return s;
}

namespace {
nlohmann::ordered_json flume_to_json(const mpm::MpmFlumeParams& f) {
  nlohmann::ordered_json j;
  detail::write_flume_shape(j, f.shape);
  j["wall_friction"] = rad2deg(f.wall_friction);
  j["wall_layers"] = f.wall_layers;
  detail::write_flume_measures(j, f.measures);
  if (f.release_material_index >= 0)
    j["release"] = {{"material", f.release_material}, {"points_per_cell", f.release_per_cell}};
  return j;
}
}  // namespace

nlohmann::ordered_json mpm_scenario_to_json(const mpm::MpmScenario& s) {
  using J = nlohmann::ordered_json;
  const int dim = s.dimension;
  auto point = [dim](const Vec3& v) {
    J a = J::array();
    for (int d = 0; d < dim; ++d) a.push_back(v[d]);
    return a;
  };
  const auto& p = s.solver;
  J run = {{"dimension", dim}, {"duration", s.duration}};
  run["time_step"] = p.fixed_time_step > 0.0 ? J(p.fixed_time_step) : J("auto");
  run["cfl"] = p.cfl;
  run["ke_blowup_factor"] = s.ke_blowup_factor;
  run["gravity"] = point(p.gravity);
  run["shape"] = detail::name_of(kShapes, p.shape);
  run["scheme"] = detail::name_of(kSchemes, p.scheme);
  run["transfer"] = detail::name_of(kTransfers, p.transfer);
  if (p.transfer == mpm::Transfer::FlipPic) run["flip"] = p.flip;
  run["volumetric_smoothing"] = p.volumetric_smoothing;
  run["local_damping"] = p.local_damping;
  if (p.bed_normal_gravity > 0.0)
    run["plan_view"] = {{"basal_friction", p.basal_friction},
                        {"normal_gravity", p.bed_normal_gravity}};
  if (p.water.present())
    run["water"] = {{"level", p.water.level},
                    {"density", p.water.density},
                    {"drag_coefficient", p.water.drag_coefficient},
                    {"added_mass_coefficient", p.water.added_mass_coefficient}};
  J faces = J::object();
  for (int f = 0; f < 2 * dim; ++f)
    faces[kFaceKeys[f]] = s.grid.faces[f] == BoundaryKind::Friction
                              ? J{{"friction", s.grid.friction[f]}}
                              : J(detail::name_of(kFaces, s.grid.faces[f]));
  J grid = {{"min", point(s.grid.lo)},
            {"max", point(s.grid.hi)},
            {"cell_size", s.grid.cell_size},
            {"boundaries", faces}};
  J materials = J::array();
  for (const auto& m : s.materials) {
    J j = {{"name", m.name}, {"model", m.model}, {"density", m.density}};
    detail::write_law<mpm::MaterialLaws>(j, mpm::MaterialLaws::index_of(m.model), m);
    materials.push_back(j);
  }
  J bodies = J::array();
  for (const auto& b : s.bodies) {
    J j = {{"material", b.material},
           {"box", {{"min", point(b.min)}, {"max", point(b.max)}}},
           {"points_per_cell", b.per_cell},
           {"velocity", point(b.velocity)},
           {"initial_stress", b.geostatic ? "geostatic" : "none"}};
    if (b.geostatic) j["k0"] = mpm::resolved_k0(b, s.materials[b.material_index]);
    bodies.push_back(j);
  }
  J rigid = J::array();
  for (const auto& b : s.rigid_bodies) {
    const auto& m = b.motion;
    J motion = {{"velocity", point(m.velocity)}};
    if (dim == 2)
      motion["angular_velocity"] = rad2deg(m.angular_velocity.z());
    else
      motion["angular_velocity"] = point(m.angular_velocity.unaryExpr(&rad2deg));
    motion["hinge"] = point(m.hinge);
    motion["start"] = m.start;
    if (std::isfinite(m.stop)) motion["stop"] = m.stop;
    J j = {{"box", {{"min", point(b.min)}, {"max", point(b.max)}}},
           {"points_per_cell", b.per_cell},
           {"contact", detail::name_of(kContacts, b.contact)}};
    if (b.contact == mpm::RigidContact::Friction) j["friction"] = b.friction;
    j["angle"] = rad2deg(b.angle);
    if (dim == 3) j["axis"] = point(b.axis);
    j["motion"] = motion;
    rigid.push_back(j);
  }
  J output = {{"series_interval", s.output.series_interval},
              {"snapshot_interval", s.output.snapshot_interval},
              {"checkpoint_interval", s.output.checkpoint_interval},
              {"snapshots", s.output.snapshots}};
  J out = {{"method", "mpm"}, {"name", s.name}, {"description", s.description},
           {"run", run},      {"grid", grid},   {"materials", materials}};
  if (!bodies.empty()) out["bodies"] = bodies;
  if (!rigid.empty()) out["rigid_bodies"] = rigid;
  if (!s.membranes.empty()) {
    J membranes = J::array();
    for (const auto& m : s.membranes) membranes.push_back(detail::mpm_membrane_table(m, dim));
    out["membranes"] = membranes;
  }
  if (s.flume) out["flume"] = flume_to_json(*s.flume);
  out["output"] = output;
  return out;
}

std::string mpm_scenario_to_toml(const mpm::MpmScenario& s) {
  return detail::json_to_toml(mpm_scenario_to_json(s));
}

}  // namespace talus::io
