// Value checks shared by the parts of the DEM scenario reader.
#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>

#include "talus/scenario/declared_keys.hpp"
#include "talus/scenario/scenario_detail.hpp"

namespace talus::io::detail {

std::string describe(const Interval& range) {
  if (std::isinf(range.high)) {
    if (range.low == 0.0) return range.low_open ? "a positive number" : "a number >= 0";
    return fmt::format("a number {} {}", range.low_open ? ">" : ">=", range.low);
  }
  return fmt::format("a number in {}{}, {}{}", range.low_open ? "(" : "[", range.low, range.high,
                     range.high_open ? ")" : "]");
}

std::string describe_key(const Interval& range, KeyUnit unit) {
  std::string text = describe(range);
  if (unit == KeyUnit::Plain) return text;
  // "a number in [0, 90)" -> "an angle in [0, 90) degrees"
  if (text.starts_with("a number")) text = "an angle" + text.substr(8);
  return text + " degrees";
}

double to_stored(double value, KeyUnit unit) {
  if (unit == KeyUnit::Plain) return value;
  const double radians = deg2rad(value);
  return unit == KeyUnit::Degrees ? radians : std::tan(radians);
}

double to_file(double value, KeyUnit unit) {
  if (unit == KeyUnit::Plain) return value;
  return rad2deg(unit == KeyUnit::Degrees ? value : std::atan(value));
}

std::optional<double> optional_number_in(TomlReader& r, std::string_view key, Interval range) {
  if (r.has(key) && !r.is_number(key)) r.expect(false, key, describe(range));
  const auto value = r.optional_number(key);
  if (value) r.expect(range.contains(*value), key, describe(range));
  return value;
}

double number_in(TomlReader& r, std::string_view key, double fallback, Interval range) {
  return optional_number_in(r, key, range).value_or(fallback);
}

double required_number_in(TomlReader& r, std::string_view key, Interval range) {
  if (auto value = optional_number_in(r, key, range)) return *value;
  r.missing(key, fmt::format("missing (expected {})", describe(range)));
}

namespace {
Vec3 checked_point(TomlReader& r, std::string_view key, const DemContext& ctx, const Vec3& v) {
  if (ctx.dimension == 2 && v.z() != 0.0) {
    r.fail(key,
           fmt::format("expected [x, y] in a 2D run (run.dimension = 2), got {}", r.text(key)));
  }
  return v;
}
}  // namespace

Vec3 required_point(TomlReader& r, std::string_view key, const DemContext& ctx) {
  return checked_point(r, key, ctx, r.required_vec3(key));
}

Vec3 point_or(TomlReader& r, std::string_view key, const DemContext& ctx, const Vec3& fallback) {
  return checked_point(r, key, ctx, r.vec3(key, fallback));
}

Vec3 unit(const Vec3& v) {
  // Normalising twice may move the last bit; a vector that is unit up to
  // round-off is kept as written.
  const double eps = std::numeric_limits<double>::epsilon();
  return std::abs(v.squaredNorm() - 1.0) <= 8.0 * eps ? v : v.normalized();
}

Vec3 unit_vector_or(TomlReader& r, std::string_view key, const DemContext& ctx,
                    const Vec3& fallback) {
  const Vec3 v = point_or(r, key, ctx, fallback);
  r.expect(v.norm() > 0.0, key, "a non-zero vector");
  return unit(v);
}

Vec3 spin_or_zero(TomlReader& r, std::string_view key, const DemContext& ctx) {
  if (ctx.dimension == 2 && r.is_number(key)) return Vec3(0.0, 0.0, r.required_number(key));
  if (ctx.dimension == 2 && r.has(key) && !r.table().get(key)->is_array()) {
    r.expect(false, key, "a number (rad/s about z)");
  }
  const Vec3 w = r.vec3(key, Vec3::Zero());
  if (ctx.dimension == 2 && (w.x() != 0.0 || w.y() != 0.0)) {
    r.expect(false, key, "a number (rad/s about z) in a 2D run");
  }
  return w;
}

void read_box(TomlReader& r, std::string_view key, const DemContext& ctx, Vec3& min, Vec3& max) {
  TomlReader box = r.required_table(key);
  min = required_point(box, "min", ctx);
  max = required_point(box, "max", ctx);
  box.finish();
  for (int i = 0; i < ctx.dimension; ++i) {
    if (!(min[i] < max[i])) {
      box.fail("max", fmt::format("expected max > min in every coordinate, got min = {}, max = {}",
                                  box.text("min"), box.text("max")));
    }
  }
}

std::string required_file(TomlReader& r, std::string_view key, const DemContext& ctx) {
  const std::filesystem::path given = r.required_string(key);
  r.expect(!given.empty(), key, "a file name");
  namespace fs = std::filesystem;
  // Relative to the folder of the file the key was written in: a base
  // scenario (`extends`) names its files from where it lies. A --set value
  // (no file of its own) is relative to the scenario's folder.
  const toml::node* node = r.table().get(key);
  const fs::path written_in = fs::path(r.file_of(node)).parent_path();
  const fs::path folder = node && node->source().path ? written_in : ctx.folder;
  const fs::path path =
      fs::absolute(given.is_absolute() ? given : folder / given).lexically_normal();
  std::error_code ec;
  const fs::file_type type = fs::status(path, ec).type();
  if (type == fs::file_type::not_found) r.fail(key, fmt::format("no such file: {}", path.string()));
  if (type == fs::file_type::none)
    r.fail(key, fmt::format("cannot read {} ({})", path.string(), ec.message()));
  if (type == fs::file_type::directory)
    r.fail(key, fmt::format("{} is a folder; expected a file", path.string()));
  if (type != fs::file_type::regular)
    r.fail(key,
           fmt::format("{} is not a regular file (a device, a pipe or a socket)", path.string()));
  return path.string();
}

void check_material(const TomlReader& r, std::string_view key, const std::string& name,
                    const DemContext& ctx) {
  const auto& names = ctx.material_names;
  if (std::find(names.begin(), names.end(), name) != names.end()) return;
  std::string defined;
  for (const std::string& n : names) defined += (defined.empty() ? "'" : ", '") + n + "'";
  const std::string guess = closest_name(name, names);
  const std::string hint = guess.empty() ? "" : fmt::format("; did you mean '{}'?", guess);
  r.fail(key, fmt::format("no material named '{}'{} (defined in [[materials]]: {})", name, hint,
                          defined));
}

Vec3 up(const DemContext& ctx) { return ctx.dimension == 2 ? Vec3::UnitY() : Vec3::UnitZ(); }

TomlReader table_or_empty(TomlReader& root, std::string_view key, const toml::table& empty) {
  if (auto table = root.optional_table(key)) return *table;
  return TomlReader(empty, root.file(), std::string(key), std::string(key));
}

}  // namespace talus::io::detail
