#pragma once
// Internals shared by the parts of the DEM scenario reader and writer
// (scenario*.cpp). Not part of the public API.
#include <fmt/format.h>

#include <filesystem>
#include <limits>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "talus/core/declared_keys.hpp"
#include "talus/dem/params.hpp"
#include "talus/geometry/flume_params.hpp"
#include "talus/io/toml_reader.hpp"

namespace talus::geometry {
struct FlumeGeometry;
}

namespace talus::io::detail {

// The file's names of the enumerated options; the first one is listed first
// in messages, the writer maps values back to these names.
inline const EnumNames<dem::Backend> kBackends = {{"cpu", dem::Backend::Cpu},
                                                  {"gpu", dem::Backend::Gpu}};
inline const EnumNames<dem::RollingModel> kRollingModels = {{"none", dem::RollingModel::None},
                                                            {"epsd", dem::RollingModel::Epsd},
                                                            {"kuen", dem::RollingModel::Kuen}};
inline const EnumNames<dem::PairRule> kPairRules = {{"max", dem::PairRule::Max},
                                                    {"min", dem::PairRule::Min},
                                                    {"harmonic", dem::PairRule::Harmonic},
                                                    {"mean", dem::PairRule::Mean}};
inline const EnumNames<dem::WallKind> kWallKinds = {
    {"segment", dem::WallKind::Segment}, {"arc", dem::WallKind::Arc},
    {"plane", dem::WallKind::Plane},     {"triangle", dem::WallKind::Triangle},
    {"mesh", dem::WallKind::Mesh},       {"cylinder", dem::WallKind::Cylinder}};
inline const EnumNames<dem::SourceKind> kSourceKinds = {
    {"list", dem::SourceKind::List},
    {"lattice", dem::SourceKind::Lattice},
    {"random_fill", dem::SourceKind::RandomFill},
    {"grow", dem::SourceKind::Grow},
    {"file", dem::SourceKind::File}};
inline const EnumNames<dem::MembraneMeshKind> kMembraneMeshes = {
    {"flat_sheet", dem::MembraneMeshKind::FlatSheet},
    {"cylinder", dem::MembraneMeshKind::Cylinder},
    {"geodesic_sphere", dem::MembraneMeshKind::GeodesicSphere},
    {"geodesic_hemisphere", dem::MembraneMeshKind::GeodesicHemisphere},
    {"box", dem::MembraneMeshKind::Box},
    {"stl", dem::MembraneMeshKind::Stl}};
inline const EnumNames<dem::MembraneFixed> kMembraneFixed = {
    {"none", dem::MembraneFixed::None},
    {"edge", dem::MembraneFixed::Edge},
    {"bottom_ring", dem::MembraneFixed::BottomRing},
    {"top_ring", dem::MembraneFixed::TopRing},
    {"both_rings", dem::MembraneFixed::BothRings},
    {"all", dem::MembraneFixed::All}};
inline const std::vector<std::string> kJitterNames = {"none", "peer"};

template <typename E>
std::string name_of(const EnumNames<E>& names, E value) {
  for (const auto& [name, v] : names) {
    if (v == value) return std::string(name);
  }
  return "?";
}

// Fails at r's "name" when `name` is taken by one of `earlier` (anything with
// a .name, in the order read): "<what> '<name>' is <verb> twice (first
// <where(j)>)", j the first that has it.
template <typename Earlier, typename Where>
void check_unique_name(const TomlReader& r, const Earlier& earlier, const std::string& name,
                       std::string_view what, std::string_view verb, Where where) {
  for (std::size_t j = 0; j < std::size(earlier); ++j)
    if (earlier[j].name == name)
      r.fail("name", fmt::format("{} '{}' is {} twice (first {})", what, name, verb, where(j)));
}

// What the parts of the reader need to know about the whole scenario.
struct DemContext {
  int dimension = 3;
  std::filesystem::path folder;  // of the scenario file, for relative paths
  std::vector<std::string> material_names;
  std::vector<std::string> wall_names;  // filled once [[walls]] are read
};

// Intervals come from the laws' declarations (core/declared_keys.hpp).
using talus::between;
using talus::Interval;
using talus::non_negative;
using talus::positive;
// How a message says which numbers an interval holds: "a positive number",
// "a number in (0, 1]".
std::string describe(const Interval& range);

std::optional<double> optional_number_in(TomlReader& r, std::string_view key, Interval range);
double number_in(TomlReader& r, std::string_view key, double fallback, Interval range);
double required_number_in(TomlReader& r, std::string_view key, Interval range);

// A point or direction; in 2D runs it is [x, y] (a third number must be 0).
Vec3 required_point(TomlReader& r, std::string_view key, const DemContext& ctx);
Vec3 point_or(TomlReader& r, std::string_view key, const DemContext& ctx, const Vec3& fallback);
// v / |v|, or v itself when it is unit up to round-off: reading a resolved
// scenario back gives the same vector (normalising twice may not).
Vec3 unit(const Vec3& v);
// A non-zero vector, normalised (unit above).
Vec3 unit_vector_or(TomlReader& r, std::string_view key, const DemContext& ctx,
                    const Vec3& fallback);
// An angular velocity in rad/s: in 2D a number (about z) or [0, 0, w].
Vec3 spin_or_zero(TomlReader& r, std::string_view key, const DemContext& ctx);
// A box {min = [..], max = [..]} with min < max in every used coordinate.
void read_box(TomlReader& r, std::string_view key, const DemContext& ctx, Vec3& min, Vec3& max);
// A file name, relative to the folder of the file it is written in (the
// scenario or a base it extends) unless absolute; must exist.
std::string required_file(TomlReader& r, std::string_view key, const DemContext& ctx);
// The optional table `key` of root, or an empty one in its place (its keys'
// defaults then apply; `empty` must outlive the reader).
TomlReader table_or_empty(TomlReader& root, std::string_view key, const toml::table& empty);
// Fails unless name is one of the [[materials]].
void check_material(const TomlReader& r, std::string_view key, const std::string& name,
                    const DemContext& ctx);
// "up" in the run's dimension: +y in 2D, +z in 3D.
Vec3 up(const DemContext& ctx);

// The parts of parse_dem_scenario, one per table.
// Each material reads the keys of the named contact law (dem/contact/laws.hpp).
std::vector<dem::MaterialParams> read_materials(std::vector<TomlReader>& readers,
                                                const std::string& contact_model);
std::vector<dem::PairOverride> read_pairs(TomlReader& contact, const DemContext& ctx);
dem::WallParams read_wall(TomlReader& r, std::size_t index, const DemContext& ctx);
dem::ParticleSourceParams read_source(TomlReader& r, const DemContext& ctx);
// [[membranes]] (3D only), and its table for the resolved scenario.
dem::MembraneSpec read_membrane(TomlReader& r, std::size_t index, const DemContext& ctx);
nlohmann::ordered_json membrane_table(const dem::MembraneSpec& m);
// [triaxial] (after walls and membranes): fills s.triaxial, checking that the
// plates are servo-controlled plane walls and the membrane a confining cylinder;
// and its table for the resolved scenario.
void read_triaxial(TomlReader& r, dem::DemScenario& s);
nlohmann::ordered_json triaxial_table(const dem::TriaxialParams& t);
// [hollow_sphere] (after membranes and particles): fills s.hollow_sphere,
// checking that the object is a fixed sphere inside the shell's membrane
// under the same vacuum; and its table for the resolved scenario.
void read_hollow_sphere(TomlReader& r, dem::DemScenario& s);
nlohmann::ordered_json hollow_sphere_table(const dem::HollowSphereParams& h);
// [gripper] (after membranes, materials and output): fills s.gripper with
// its phase times; and its table for the resolved scenario.
void read_gripper(TomlReader& r, dem::DemScenario& s, const DemContext& ctx);
nlohmann::ordered_json gripper_table(const dem::GripperParams& g);
// [beam] (after membranes, run and output): fills s.beam with its step count;
// and its table for the resolved scenario.
void read_beam(TomlReader& r, dem::DemScenario& s);
nlohmann::ordered_json beam_table(const dem::BeamParams& b);
// Pieces of [[particles]] that [flume.release] shares.
// box_min/box_max of a source from its polygon.
void set_polygon_bounds(dem::ParticleSourceParams& s);
void read_radius_range(TomlReader& r, dem::ParticleSourceParams& s);
std::optional<int> read_count(TomlReader& r);
dem::SettleParams read_settle(TomlReader& r);
// The flume's keys, read and written the same way by DEM and MPM ([flume])
// and by DAN and fv2d ([path] type = "flume") (scenario_flume_keys.cpp).
// The DEM and MPM flume is 2D only.
void require_2d_flume(TomlReader& r, const DemContext& ctx);
// beta (degrees in the file), arc_radius, l_star, barrier_length.
geometry::FlumeShape read_flume_shape(TomlReader& r);
// front_quantile, profile_bin, tail_thickness.
geometry::FlumeMeasures read_flume_measures(TomlReader& r);
// The shape's geometry, failing at "beta" when its pieces do not fit; sets
// the shape's l_star and barrier_length to the values it uses.
geometry::FlumeGeometry resolve_flume_shape(TomlReader& r, geometry::FlumeShape& f);
// An angle held in radians as a resolved scenario writes it: degrees rounded
// to 1e-9, so that the file's 33 is written back as 33.
double degrees_for_file(double radians);
// Their keys in a resolved scenario's table (beta in degrees).
void write_flume_shape(nlohmann::ordered_json& t, const geometry::FlumeShape& f);
void write_flume_measures(nlohmann::ordered_json& t, const geometry::FlumeMeasures& m);
// [flume]: fills s.flume, appends the generated walls (and the release fill
// when [flume.release] is given) to s.walls and s.sources.
void read_flume(TomlReader& r, dem::DemScenario& s, const DemContext& ctx);
// [flume.release] / [dam_break.release]: a settled random fill of `polygon`
// (counter-clockwise) with Kuen's defaults.
dem::ParticleSourceParams read_release(TomlReader& r, const std::vector<Vec3>& polygon,
                                       const DemContext& ctx);
// [dam_break]: fills s.dam_break, appends its walls and release fill.
void read_dam_break(TomlReader& r, dem::DemScenario& s, const DemContext& ctx);

// TOML text for a JSON object of tables, arrays of tables and values, keys in
// the object's order. Small tables of plain values become inline tables.
std::string json_to_toml(const nlohmann::ordered_json& root);

}  // namespace talus::io::detail
