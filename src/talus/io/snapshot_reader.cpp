#include "talus/io/snapshot_reader.hpp"

#include <fmt/format.h>
#include <toml++/toml.h>

#include <bit>
#include <charconv>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <iterator>
#include <optional>
#include <string_view>

#include "talus/core/error.hpp"

namespace talus::io {

namespace {

std::string read_all(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(fmt::format("{}: cannot open the file", path.string()));
  return std::string((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
}

// Value of attribute `name` in one XML tag (files of our own writers: no entities to decode
// beyond what names and numbers use).
std::optional<std::string_view> attribute(std::string_view tag, std::string_view name) {
  std::string key(1, ' ');  // (a leading " " + name trips GCC 12's -Wrestrict)
  key.append(name).append("=\"");
  const auto at = tag.find(key);
  if (at == std::string_view::npos) return std::nullopt;
  const auto start = at + key.size();
  const auto end = tag.find('"', start);
  if (end == std::string_view::npos) return std::nullopt;
  return tag.substr(start, end - start);
}

template <class T>
std::optional<T> number(std::optional<std::string_view> text) {
  if (!text) return std::nullopt;
  T value{};
  const auto [end, error] = std::from_chars(text->data(), text->data() + text->size(), value);
  if (error != std::errc{} || end != text->data() + text->size()) return std::nullopt;
  return value;
}

struct ArrayRef {
  std::string type;
  int components = 1;
  uint64_t offset = 0;
};

}  // namespace

std::vector<SnapshotEntry> read_pvd(const std::filesystem::path& pvd) {
  const std::string xml = read_all(pvd);
  std::vector<SnapshotEntry> out;
  for (auto at = xml.find("<DataSet"); at != std::string::npos; at = xml.find("<DataSet", at + 1)) {
    const std::string_view tag = std::string_view(xml).substr(at, xml.find('>', at) - at);
    const auto line = 1 + std::count(xml.begin(), xml.begin() + at, '\n');
    const auto time = number<double>(attribute(tag, "timestep"));
    const auto file = attribute(tag, "file");
    if (!time || !file || file->empty())
      throw InputError(
          fmt::format("{}:{}: DataSet without a numeric timestep and a file", pvd.string(), line));
    out.push_back({*time, pvd.parent_path() / std::string(*file)});
  }
  return out;
}

ParticleFrame read_particle_vtu(const std::filesystem::path& vtu) {
  const std::string data = read_all(vtu);
  auto fail = [&](const std::string& what) -> InputError {
    return InputError(fmt::format("{}: {}", vtu.string(), what));
  };
  const std::string_view text(data);
  const auto piece = text.find("<Piece");
  if (piece == std::string_view::npos) throw fail("no <Piece>: not a VTK UnstructuredGrid file");
  const auto n = number<uint64_t>(
      attribute(text.substr(piece, text.find('>', piece) - piece), "NumberOfPoints"));
  if (!n) throw fail("<Piece> without NumberOfPoints");
  const std::string little = "byte_order=\"LittleEndian\"";
  if ((text.find(little) != std::string_view::npos) != (std::endian::native == std::endian::little))
    throw fail("written with the other byte order");
  const auto appended = text.find("<AppendedData encoding=\"raw\">");
  if (appended == std::string_view::npos) throw fail("no raw <AppendedData> section");
  const auto base = text.find('_', appended);
  if (base == std::string_view::npos) throw fail("<AppendedData> without its '_' marker");

  std::map<std::string, ArrayRef> arrays;
  for (auto at = text.find("<DataArray"); at < appended; at = text.find("<DataArray", at + 1)) {
    const std::string_view tag = text.substr(at, text.find('>', at) - at);
    const auto name = attribute(tag, "Name");
    const auto type = attribute(tag, "type");
    const auto offset = number<uint64_t>(attribute(tag, "offset"));
    const auto comps = number<int>(attribute(tag, "NumberOfComponents"));
    if (!name || !type || !offset) throw fail("DataArray without Name, type or offset");
    arrays[std::string(*name)] = {std::string(*type), comps.value_or(1), *offset};
  }
  auto read = [&](const char* name, const char* type, int comps, void* dest, std::size_t bytes) {
    const auto it = arrays.find(name);
    if (it == arrays.end()) throw fail(fmt::format("no array '{}'", name));
    if (it->second.type != type || it->second.components != comps)
      throw fail(fmt::format("array '{}' is not {} x {}", name, comps, type));
    const std::size_t start = base + 1 + it->second.offset;
    uint64_t size = 0;
    if (start + sizeof size > data.size()) throw fail(fmt::format("array '{}' is cut off", name));
    std::memcpy(&size, data.data() + start, sizeof size);
    if (size != bytes || start + sizeof size + size > data.size())
      throw fail(fmt::format("array '{}' has {} bytes, expected {}", name, size, bytes));
    std::memcpy(dest, data.data() + start + sizeof size, bytes);
  };
  ParticleFrame f;
  f.position.resize(*n), f.velocity.resize(*n), f.radius.resize(*n), f.id.resize(*n);
  f.material.resize(*n);
  read("Points", "Float64", 3, f.position.data(), *n * sizeof(Vec3));
  read("velocity", "Float64", 3, f.velocity.data(), *n * sizeof(Vec3));
  read("radius", "Float64", 1, f.radius.data(), *n * sizeof(double));
  read("id", "Int64", 1, f.id.data(), *n * sizeof(int64_t));
  read("material", "Int32", 1, f.material.data(), *n * sizeof(int));
  if (arrays.count("angular_velocity")) {
    f.angular_velocity.resize(*n);
    read("angular_velocity", "Float64", 3, f.angular_velocity.data(), *n * sizeof(Vec3));
  }
  if (arrays.count("contacts")) {
    f.contacts.resize(*n);
    read("contacts", "Int32", 1, f.contacts.data(), *n * sizeof(int));
  }
  return f;
}

namespace {

toml::table parse_toml(const std::filesystem::path& scenario_toml) {
  if (!std::filesystem::exists(scenario_toml))
    throw InputError(fmt::format("{}: no such file", scenario_toml.string()));
  try {
    return toml::parse_file(scenario_toml.string());
  } catch (const toml::parse_error& e) {
    throw InputError(
        fmt::format("{}:{}: {}", scenario_toml.string(), e.source().begin.line, e.description()));
  }
}

}  // namespace

int read_run_dimension(const std::filesystem::path& scenario_toml) {
  const toml::table table = parse_toml(scenario_toml);
  const auto dimension = table["run"]["dimension"].value<int64_t>();
  if (!dimension || (*dimension != 2 && *dimension != 3))
    throw InputError(fmt::format("{}: [run] dimension is not 2 or 3", scenario_toml.string()));
  return static_cast<int>(*dimension);
}

std::vector<double> read_material_densities(const std::filesystem::path& scenario_toml) {
  const toml::table table = parse_toml(scenario_toml);
  const toml::array* materials = table["materials"].as_array();
  if (!materials) throw InputError(fmt::format("{}: no [[materials]]", scenario_toml.string()));
  std::vector<double> density;
  for (const toml::node& m : *materials) {
    const auto* t = m.as_table();
    density.push_back(t ? (*t)["density"].value_or(0.0) : 0.0);
  }
  return density;
}

}  // namespace talus::io
