// The resolved DEM scenario written back as a scenario file (and as JSON for
// summary.json). Every value is written, defaults included, so the output
// says exactly what ran; infinite times ("never") are left out. Built as an
// ordered JSON object so that the keys keep the order of the documentation.
#include <cmath>

#include "talus/dem/contact/laws.hpp"
#include "talus/scenario/declared_keys.hpp"
#include "talus/scenario/scenario.hpp"
#include "talus/scenario/scenario_detail.hpp"

namespace talus::io {
namespace {

using detail::name_of;
using Json = nlohmann::ordered_json;

class Writer {
 public:
  explicit Writer(int dimension) : dim_(dimension) {}

  // Points as [x, y] in 2D, [x, y, z] in 3D.
  Json vec(const Vec3& v) const {
    Json a = Json::array();
    for (int i = 0; i < dim_; ++i) a.push_back(v[i]);
    return a;
  }
  // Angular velocities: a number about z in 2D.
  void spin(Json& t, const std::string& key, const Vec3& w) const {
    if (dim_ == 2)
      t[key] = w.z();
    else
      t[key] = vec(w);
  }
  static void finite(Json& t, const std::string& key, double value) {
    if (std::isfinite(value)) t[key] = value;
  }
  Json box(const Vec3& min, const Vec3& max) const {
    Json b{{"min", vec(min)}, {"max", vec(max)}};
    return b;
  }

  Json run(const dem::RunParams& r) const {
    Json t{{"dimension", r.dimension}, {"duration", r.duration}};
    if (r.time_step > 0.0)
      t["time_step"] = r.time_step;
    else
      t["time_step"] = "auto";
    t["safety_factor"] = r.safety_factor;
    t["gravity"] = vec(r.gravity);
    if (r.domain_max != r.domain_min) t["domain"] = box(r.domain_min, r.domain_max);
    t["skin"] = r.skin;
    t["seed"] = static_cast<std::int64_t>(r.seed);
    t["ke_blowup_factor"] = r.ke_blowup_factor;
    t["backend"] = name_of(detail::kBackends, r.backend);
    return t;
  }

  static Json contact(const dem::ContactParams& c) {
    Json t{{"model", c.model},
           {"rolling", name_of(detail::kRollingModels, c.rolling)},
           {"friction_rule", name_of(detail::kPairRules, c.friction_rule)},
           {"lock_rotation", c.lock_rotation},
           {"local_damping", c.local_damping},
           {"dashpot_may_pull", c.dashpot_may_pull},
           {"tangential_damping", c.tangential_damping},
           {"kuen_wall_depth", c.kuen_wall_depth},
           {"kuen_particle_factor", c.kuen_particle_factor},
           {"kuen_reference_step", c.kuen_reference_step},
           {"epsd_stiffness_factor", c.epsd_stiffness_factor},
           {"epsd_damping_ratio", c.epsd_damping_ratio}};
    Json pairs = Json::array();
    for (const auto& p : c.pairs) {
      Json pt{{"materials", Json::array({p.material_a, p.material_b})}};
      if (p.friction) pt["friction"] = *p.friction;
      if (p.rolling_friction) pt["rolling_friction"] = *p.rolling_friction;
      if (p.restitution) pt["restitution"] = *p.restitution;
      pairs.push_back(std::move(pt));
    }
    if (!pairs.empty()) t["pairs"] = std::move(pairs);
    return t;
  }

  // The keys every material has, then those the contact law declares.
  static Json material(const dem::MaterialParams& m, const std::string& contact_model) {
    Json t{{"name", m.name}};
    // Zero means "not given": only materials that particles use need one.
    if (m.density > 0.0) t["density"] = m.density;
    t["friction"] = m.friction;
    t["rolling_friction"] = m.rolling_friction;
    detail::write_law<dem::ContactLaws>(t, dem::ContactLaws::index_of(contact_model), m);
    return t;
  }

  // False for a wall that never moves: all of [walls.motion] at its defaults.
  bool moves(const dem::WallMotionParams& m) const {
    const Vec3 up = dim_ == 2 ? Vec3::UnitY() : Vec3::UnitZ();
    return !(m.velocity.isZero(0.0) && m.angular_velocity.isZero(0.0) && m.pivot.isZero(0.0) &&
             m.move_start == 0.0 && m.move_stop == dem::kNever && m.amplitude == 0.0 &&
             m.frequency == 0.0 && m.phase == 0.0 && m.direction == up &&
             m.remove_at == dem::kNever && m.servo_pressure == 0.0);
  }
  // Degrees rounded to 1e-9 so that 241 is not written as 241.00000000000003.
  static double degrees(double radians) { return detail::degrees_for_file(radians); }

  Json motion(const dem::WallMotionParams& m) const {
    Json t{{"velocity", vec(m.velocity)}, {"start", m.move_start}};
    finite(t, "stop", m.move_stop);
    spin(t, "angular_velocity", m.angular_velocity);
    t["pivot"] = vec(m.pivot);
    t["amplitude"] = m.amplitude;
    t["frequency"] = m.frequency;
    t["phase"] = degrees(m.phase);
    t["direction"] = vec(m.direction);
    finite(t, "remove_at", m.remove_at);
    if (m.servo_pressure > 0)
      t["servo"] = Json{{"pressure", m.servo_pressure},
                        {"area", m.servo_area},
                        {"speed", m.servo_speed},
                        {"stop", m.servo_stop}};
    return t;
  }

  Json wall(const dem::WallParams& w) const {
    Json t{
        {"name", w.name}, {"type", name_of(detail::kWallKinds, w.kind)}, {"material", w.material}};
    using dem::WallKind;
    switch (w.kind) {
      case WallKind::Segment:
        t["a"] = vec(w.a);
        t["b"] = vec(w.b);
        break;
      case WallKind::Arc:
        t["center"] = vec(w.center);
        t["radius"] = w.radius;
        t["angle_start"] = degrees(w.angle_start);
        t["angle_end"] = degrees(w.angle_end);
        break;
      case WallKind::Plane:
        t["point"] = vec(w.point);
        t["normal"] = vec(w.normal);
        break;
      case WallKind::Triangle: {
        Json vertices = Json::array();
        for (const Vec3& v : w.vertices) vertices.push_back(vec(v));
        t["vertices"] = std::move(vertices);
        break;
      }
      case WallKind::Mesh:
        t["file"] = w.file;
        t["scale"] = w.scale;
        t["offset"] = vec(w.offset);
        break;
      case WallKind::Cylinder:
        t["point"] = vec(w.point);
        t["axis"] = vec(w.axis);
        t["radius"] = w.radius;
        t["inside"] = w.inside;
        finite(t, "length", w.length);
        break;
    }
    if (moves(w.motion)) t["motion"] = motion(w.motion);
    return t;
  }

  Json source(const dem::ParticleSourceParams& s) const {
    Json t{{"type", name_of(detail::kSourceKinds, s.kind)}};
    if (!s.material.empty()) t["material"] = s.material;
    using dem::SourceKind;
    const bool fill = s.kind == SourceKind::RandomFill || s.kind == SourceKind::Grow;
    if (s.kind == SourceKind::List) {
      Json list = Json::array();
      for (const auto& p : s.particles) {
        Json pt{{"position", vec(p.position)}, {"velocity", vec(p.velocity)}};
        spin(pt, "angular_velocity", p.angular_velocity);
        pt["radius"] = p.radius;
        pt["material"] = p.material;
        list.push_back(std::move(pt));
      }
      t["list"] = std::move(list);
    }
    if (fill && s.shell_outer_radius > 0) {
      t["shell"] = Json{{"center", vec(0.5 * (s.box_min + s.box_max))},
                        {"inner_radius", s.shell_inner_radius},
                        {"outer_radius", s.shell_outer_radius}};
    } else if (fill && s.cylinder_radius > 0) {
      t["cylinder"] =
          Json{{"center", vec(Vec3(0.5 * (s.box_min.x() + s.box_max.x()),
                                   0.5 * (s.box_min.y() + s.box_max.y()), s.box_min.z()))},
               {"radius", s.cylinder_radius},
               {"height", s.box_max.z() - s.box_min.z()}};
    } else if (s.kind == SourceKind::Lattice || (fill && s.polygon.empty())) {
      t["box"] = box(s.box_min, s.box_max);
      if (s.edge_radius > 0) t["edge_radius"] = s.edge_radius;
    }
    if (fill && !s.polygon.empty()) {
      Json polygon = Json::array();
      for (const Vec3& p : s.polygon) polygon.push_back(vec(p));
      t["polygon"] = std::move(polygon);
    }
    if (s.kind == SourceKind::Lattice) {
      t["spacing"] = s.spacing;
      t["radius"] = s.radius;
      t["jitter"] = s.jitter;
    }
    if (fill) {
      t["radius_min"] = s.radius_min;
      t["radius_max"] = s.radius_max;
      if (s.kind == SourceKind::RandomFill) t["porosity"] = s.porosity;
      if (s.kind == SourceKind::Grow) t["packing_fraction"] = s.packing_fraction;
      if (s.count) t["count"] = *s.count;
      t["shrink"] = s.shrink;
    }
    if (s.kind == SourceKind::File) t["file"] = s.file;
    if (s.settle.enabled) {
      Json settle{{"ke_ratio", s.settle.ke_ratio}, {"max_time", s.settle.max_time}};
      t["settle"] = std::move(settle);
    }
    return t;
  }

  // [flume] with its generated fill as [flume.release].
  static Json flume(const dem::FlumeParams& f, const dem::DemScenario& s) {
    Json t;
    detail::write_flume_shape(t, f.shape);
    t["wall_material"] = f.wall_material;
    t["gate"] = f.lift_gate ? "lift" : "remove";
    t["gate_speed"] = f.gate_speed;
    t["gate_open"] = f.gate_open;
    t["layers"] = f.layers;
    detail::write_flume_measures(t, f.measures);
    add_release(t, s);
    return t;
  }

  static Json dam_break(const dem::DamBreakParams& d, const dem::DemScenario& s) {
    Json t{{"width", d.width},
           {"height", d.height},
           {"floor_length", d.floor_length},
           {"wall_material", d.wall_material},
           {"gate_open", d.gate_open},
           {"segment_length", d.segment_length},
           {"segments", d.segments},
           {"profile_bin", d.profile_bin},
           {"toe_thickness", d.toe_thickness}};
    add_release(t, s);
    return t;
  }

  // The generated fill as the "release" sub-table.
  static void add_release(Json& t, const dem::DemScenario& s) {
    for (const auto& src : s.sources) {
      if (!src.generated) continue;
      Json r{{"material", src.material},
             {"radius_min", src.radius_min},
             {"radius_max", src.radius_max},
             {"porosity", src.porosity},
             {"shrink", src.shrink}};
      if (src.count) r["count"] = *src.count;
      r["settle"] = src.settle.enabled
                        ? Json{{"ke_ratio", src.settle.ke_ratio}, {"max_time", src.settle.max_time}}
                        : Json(false);
      t["release"] = std::move(r);
    }
  }

  static Json output(const dem::OutputParams& o) {
    return Json{{"snapshot_interval", o.snapshot_interval},
                {"series_interval", o.series_interval},
                {"checkpoint_interval", o.checkpoint_interval},
                {"snapshots", o.write_snapshots}};
  }

 private:
  int dim_;
};

Json scenario_table(const dem::DemScenario& s) {
  const Writer w(s.run.dimension);
  Json doc{{"method", "dem"}, {"name", s.name}, {"description", s.description}};
  doc["run"] = w.run(s.run);
  doc["contact"] = Writer::contact(s.contact);
  Json materials = Json::array(), walls = Json::array(), sources = Json::array();
  for (const auto& m : s.materials) materials.push_back(Writer::material(m, s.contact.model));
  // What [flume] generates is written as [flume], not as walls and particles.
  for (const auto& wall : s.walls) {
    if (!wall.generated) walls.push_back(w.wall(wall));
  }
  for (const auto& source : s.sources) {
    if (!source.generated) sources.push_back(w.source(source));
  }
  doc["materials"] = std::move(materials);
  if (s.flume) doc["flume"] = Writer::flume(*s.flume, s);
  if (s.dam_break) doc["dam_break"] = Writer::dam_break(*s.dam_break, s);
  if (!walls.empty()) doc["walls"] = std::move(walls);
  if (!sources.empty()) doc["particles"] = std::move(sources);
  if (!s.membranes.empty()) {
    Json membranes = Json::array();
    for (const auto& m : s.membranes) membranes.push_back(detail::membrane_table(m));
    doc["membranes"] = std::move(membranes);
  }
  if (s.triaxial) doc["triaxial"] = detail::triaxial_table(*s.triaxial);
  if (s.hollow_sphere) doc["hollow_sphere"] = detail::hollow_sphere_table(*s.hollow_sphere);
  if (s.gripper) doc["gripper"] = detail::gripper_table(*s.gripper);
  if (s.beam) doc["beam"] = detail::beam_table(*s.beam);
  doc["output"] = Writer::output(s.output);
  return doc;
}

}  // namespace

std::string scenario_to_toml(const dem::DemScenario& scenario) {
  return "# Resolved DEM scenario: every parameter as used, defaults included.\n" +
         detail::json_to_toml(scenario_table(scenario));
}

nlohmann::json scenario_to_json(const dem::DemScenario& scenario) {
  return nlohmann::json::parse(scenario_table(scenario).dump());
}

}  // namespace talus::io
