#include "talus/io/vtk_writer.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <bit>
#include <cctype>
#include <charconv>
#include <fstream>
#include <iterator>
#include <limits>
#include <numeric>
#include <optional>
#include <stdexcept>
#include <string_view>
#include <system_error>

#include "talus/core/error.hpp"
#include "talus/io/archive.hpp"

namespace talus::io {

namespace {

static_assert(sizeof(Vec3) == 3 * sizeof(double), "Vec3 arrays are written as packed doubles");
static_assert(sizeof(int) == 4, "int arrays are written as Int32");

// VTK cell type codes (vtkCellType.h).
constexpr uint8_t kVtkVertex = 1;
constexpr uint8_t kVtkLine = 3;
constexpr uint8_t kVtkTriangle = 5;

constexpr const char* kByteOrder =
    std::endian::native == std::endian::little ? "LittleEndian" : "BigEndian";

// One array of the appended-data section; the bytes are referenced, not copied.
struct DataArray {
  const char* type;  // VTK type name
  std::string name;
  int components;
  std::string_view bytes;
};

template <class T>
std::string_view bytes_of(const std::vector<T>& values) {
  return {reinterpret_cast<const char*>(values.data()), values.size() * sizeof(T)};
}

std::string xml_escape(std::string_view text) {
  std::string out;
  for (char c : text) {
    switch (c) {
      case '&':
        out += "&amp;";
        break;
      case '<':
        out += "&lt;";
        break;
      case '>':
        out += "&gt;";
        break;
      case '"':
        out += "&quot;";
        break;
      default:
        out += c;
    }
  }
  return out;
}

// Writes an UnstructuredGrid with all arrays in one raw appended block: each
// array is a UInt64 byte count followed by its bytes, found by its offset.
void write_vtu(const std::filesystem::path& path, std::size_t n_points, std::size_t n_cells,
               const std::vector<DataArray>& point_data, const std::vector<DataArray>& cell_data,
               const DataArray& points, const std::vector<DataArray>& cells) {
  std::vector<const DataArray*> order;
  std::string xml = fmt::format(
      "<?xml version=\"1.0\"?>\n"
      "<VTKFile type=\"UnstructuredGrid\" version=\"1.0\" byte_order=\"{}\" "
      "header_type=\"UInt64\">\n"
      "  <UnstructuredGrid>\n"
      "    <Piece NumberOfPoints=\"{}\" NumberOfCells=\"{}\">\n",
      kByteOrder, n_points, n_cells);
  uint64_t offset = 0;
  auto declare = [&](const std::vector<DataArray>& arrays, const char* section) {
    xml += fmt::format("      <{}>\n", section);
    for (const DataArray& array : arrays) {
      xml += fmt::format(
          "        <DataArray type=\"{}\" Name=\"{}\" NumberOfComponents=\"{}\" "
          "format=\"appended\" offset=\"{}\"/>\n",
          array.type, xml_escape(array.name), array.components, offset);
      offset += sizeof(uint64_t) + array.bytes.size();
      order.push_back(&array);
    }
    xml += fmt::format("      </{}>\n", section);
  };
  declare(point_data, "PointData");
  declare(cell_data, "CellData");
  const std::vector<DataArray> point_coordinates{points};  // must outlive `order`
  declare(point_coordinates, "Points");
  declare(cells, "Cells");
  xml += "    </Piece>\n  </UnstructuredGrid>\n  <AppendedData encoding=\"raw\">\n   _";

  std::vector<uint64_t> sizes;
  for (const DataArray* array : order) sizes.push_back(array->bytes.size());
  std::vector<std::string_view> pieces{xml};
  for (std::size_t i = 0; i < order.size(); ++i) {
    pieces.emplace_back(reinterpret_cast<const char*>(&sizes[i]), sizeof(uint64_t));
    pieces.push_back(order[i]->bytes);
  }
  pieces.emplace_back("\n  </AppendedData>\n</VTKFile>\n");
  write_file_atomically(path, pieces);
}

// Letters, digits, '_', '-' and '.': safe in XML and in a folder, no escaping.
bool is_plain_name(std::string_view name) {
  return !name.empty() && std::all_of(name.begin(), name.end(), [](char c) {
    return std::isalnum(static_cast<unsigned char>(c)) || c == '_' || c == '-' || c == '.';
  });
}

// The value of attribute `name` in the text of one XML tag, if it is there.
std::optional<std::string_view> attribute(std::string_view tag, std::string_view name) {
  const std::string key = std::string(name) + "=\"";
  for (auto at = tag.find(key); at != std::string_view::npos; at = tag.find(key, at + 1)) {
    if (at == 0 || !std::isspace(static_cast<unsigned char>(tag[at - 1]))) continue;
    const auto value_start = at + key.size();
    const auto value_end = tag.find('"', value_start);
    if (value_end == std::string_view::npos) return std::nullopt;
    return tag.substr(value_start, value_end - value_start);
  }
  return std::nullopt;
}

void require_size(std::size_t actual, std::size_t expected, const char* what) {
  if (actual != expected) {
    throw std::invalid_argument(
        fmt::format("VTK frame: {} has {} entries, expected {}", what, actual, expected));
  }
}

}  // namespace

PvdSeries::PvdSeries(std::filesystem::path dir, std::string basename, bool resume)
    : dir_(std::move(dir)), basename_(std::move(basename)) {
  if (!is_plain_name(basename_))
    throw std::invalid_argument("PvdSeries: bad basename '" + basename_ + "'");
  std::error_code error;
  std::filesystem::create_directories(dir_, error);
  if (error) {
    throw RunError(fmt::format("cannot create '{}': {}", dir_.string(), error.message()));
  }
  if (resume) {
    load_collection();
  } else {
    write_collection();
  }
}

std::filesystem::path PvdSeries::collection_path() const { return dir_ / (basename_ + ".pvd"); }

std::filesystem::path PvdSeries::next_file_path() const {
  return dir_ / fmt::format("{}_{:06d}.vtu", basename_, next_index_);
}

void PvdSeries::add(double time, const ParticleFrame& frame) {
  const std::size_t n = frame.position.size();
  require_size(frame.velocity.size(), n, "velocity");
  require_size(frame.angular_velocity.size(), n, "angular_velocity");
  require_size(frame.radius.size(), n, "radius");
  require_size(frame.id.size(), n, "id");
  require_size(frame.material.size(), n, "material");
  require_size(frame.contacts.size(), n, "contacts");
  for (const auto& [name, values] : frame.extra_scalars)
    require_size(values.size(), n, name.c_str());

  std::vector<int64_t> connectivity(n), offsets(n);
  std::iota(connectivity.begin(), connectivity.end(), int64_t{0});
  std::iota(offsets.begin(), offsets.end(), int64_t{1});
  const std::vector<uint8_t> types(n, kVtkVertex);

  std::vector<DataArray> point_data{
      {"Float64", "radius", 1, bytes_of(frame.radius)},
      {"Float64", "velocity", 3, bytes_of(frame.velocity)},
      {"Float64", "angular_velocity", 3, bytes_of(frame.angular_velocity)},
      {"Int64", "id", 1, bytes_of(frame.id)},
      {"Int32", "material", 1, bytes_of(frame.material)},
      {"Int32", "contacts", 1, bytes_of(frame.contacts)},
  };
  for (const auto& [name, values] : frame.extra_scalars) {
    point_data.push_back({"Float64", name, 1, bytes_of(values)});
  }
  write_vtu(next_file_path(), n, n, point_data, {},
            {"Float64", "Points", 3, bytes_of(frame.position)},
            {{"Int64", "connectivity", 1, bytes_of(connectivity)},
             {"Int64", "offsets", 1, bytes_of(offsets)},
             {"UInt8", "types", 1, bytes_of(types)}});
  commit(time);
}

void PvdSeries::add(double time, const WallFrame& frame) {
  require_size(frame.line_wall.size(), frame.lines.size(), "line_wall");
  require_size(frame.triangle_wall.size(), frame.triangles.size(), "triangle_wall");
  const auto n_points = static_cast<int64_t>(frame.points.size());
  std::vector<int64_t> connectivity, offsets;
  std::vector<uint8_t> types;
  auto add_cell = [&](const auto& corners, uint8_t type) {
    for (int corner : corners) {
      if (corner < 0 || corner >= n_points) {
        throw std::invalid_argument(
            fmt::format("VTK frame: wall point {} of {}", corner, n_points));
      }
      connectivity.push_back(corner);
    }
    offsets.push_back(static_cast<int64_t>(connectivity.size()));
    types.push_back(type);
  };
  for (const auto& line : frame.lines) add_cell(line, kVtkLine);
  for (const auto& triangle : frame.triangles) add_cell(triangle, kVtkTriangle);
  std::vector<int> wall = frame.line_wall;
  wall.insert(wall.end(), frame.triangle_wall.begin(), frame.triangle_wall.end());

  write_vtu(next_file_path(), frame.points.size(), types.size(), {},
            {{"Int32", "wall", 1, bytes_of(wall)}},
            {"Float64", "Points", 3, bytes_of(frame.points)},
            {{"Int64", "connectivity", 1, bytes_of(connectivity)},
             {"Int64", "offsets", 1, bytes_of(offsets)},
             {"UInt8", "types", 1, bytes_of(types)}});
  commit(time);
}

void PvdSeries::add(double time, const MeshFrame& frame) {
  const std::size_t n = frame.points.size(), nt = frame.triangles.size();
  std::vector<DataArray> point_data, cell_data;
  for (const auto& [name, values] : frame.point_vectors) {
    require_size(values.size(), n, name.c_str());
    point_data.push_back({"Float64", name, 3, bytes_of(values)});
  }
  for (const auto& [name, values] : frame.point_scalars) {
    require_size(values.size(), n, name.c_str());
    point_data.push_back({"Float64", name, 1, bytes_of(values)});
  }
  for (const auto& [name, values] : frame.cell_scalars) {
    require_size(values.size(), nt, name.c_str());
    cell_data.push_back({"Float64", name, 1, bytes_of(values)});
  }
  std::vector<int64_t> connectivity, offsets;
  connectivity.reserve(3 * nt);
  for (const auto& tri : frame.triangles) {
    for (int corner : tri) {
      if (corner < 0 || static_cast<std::size_t>(corner) >= n) {
        throw std::invalid_argument(fmt::format("VTK frame: mesh point {} of {}", corner, n));
      }
      connectivity.push_back(corner);
    }
    offsets.push_back(static_cast<int64_t>(connectivity.size()));
  }
  const std::vector<uint8_t> types(nt, kVtkTriangle);
  write_vtu(next_file_path(), n, nt, point_data, cell_data,
            {"Float64", "Points", 3, bytes_of(frame.points)},
            {{"Int64", "connectivity", 1, bytes_of(connectivity)},
             {"Int64", "offsets", 1, bytes_of(offsets)},
             {"UInt8", "types", 1, bytes_of(types)}});
  commit(time);
}

void PvdSeries::commit(double time) {
  entries_.push_back({time, next_file_path().filename().string()});
  ++next_index_;
  write_collection();
}

void PvdSeries::truncate_after(double time) {
  const auto first_dropped = std::stable_partition(
      entries_.begin(), entries_.end(), [time](const Entry& entry) { return entry.time <= time; });
  for (auto it = first_dropped; it != entries_.end(); ++it) {
    std::error_code ignored;  // a file already gone is what we want anyway
    std::filesystem::remove(dir_ / it->file, ignored);
  }
  entries_.erase(first_dropped, entries_.end());
  // Reuse the numbers of the dropped frames, so a resumed run that writes the
  // same frames again ends up with the same file names as an uninterrupted one.
  next_index_ = 0;
  const std::string prefix = basename_ + "_", suffix = ".vtu";
  for (const Entry& entry : entries_) {
    const std::string_view file = entry.file;
    if (!file.starts_with(prefix) || !file.ends_with(suffix)) continue;
    const std::string_view digits =
        file.substr(prefix.size(), file.size() - prefix.size() - suffix.size());
    int64_t index = 0;
    const auto [end, error] = std::from_chars(digits.data(), digits.data() + digits.size(), index);
    if (error == std::errc{} && end == digits.data() + digits.size()) {
      next_index_ = std::max(next_index_, index + 1);
    }
  }
  write_collection();
}

void PvdSeries::write_collection() const {
  std::string xml = fmt::format(
      "<?xml version=\"1.0\"?>\n"
      "<VTKFile type=\"Collection\" version=\"0.1\" byte_order=\"{}\">\n"
      "  <Collection>\n",
      kByteOrder);
  for (const Entry& entry : entries_) {
    // "{}" prints the shortest text that reads back as the same double, so a
    // resume compares exactly the times that were written.
    xml += fmt::format("    <DataSet timestep=\"{}\" group=\"\" part=\"0\" file=\"{}\"/>\n",
                       entry.time, xml_escape(entry.file));
  }
  xml += "  </Collection>\n</VTKFile>\n";
  write_file_atomically(collection_path(), xml);
}

void PvdSeries::load_collection() {
  const auto path = collection_path();
  std::error_code error;
  if (!std::filesystem::exists(path, error)) return;  // nothing written before the interruption
  std::ifstream in(path);
  const std::string xml((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  if (!in.good() && !in.eof())
    throw InputError(fmt::format("{}: cannot read the file", path.string()));

  // Only collections written by PvdSeries are resumed, so a light parse that
  // looks at the DataSet tags and their timestep and file attributes is enough.
  for (auto tag_start = xml.find("<DataSet"); tag_start != std::string::npos;
       tag_start = xml.find("<DataSet", tag_start + 1)) {
    const std::string_view tag =
        std::string_view(xml).substr(tag_start, xml.find('>', tag_start) - tag_start);
    const auto line = 1 + std::count(xml.begin(), xml.begin() + tag_start, '\n');
    const auto timestep = attribute(tag, "timestep");
    const auto file = attribute(tag, "file");
    // File names must be plain names in the collection's folder: truncate_after()
    // deletes them, so nothing that points elsewhere is accepted.
    if (!timestep || !file || !is_plain_name(*file) || !file->ends_with(".vtu")) {
      throw InputError(fmt::format("{}:{}: DataSet without a timestep or a plain .vtu file name",
                                   path.string(), line));
    }
    Entry entry{0.0, std::string(*file)};
    const auto [end, parse_error] =
        std::from_chars(timestep->data(), timestep->data() + timestep->size(), entry.time);
    if (parse_error != std::errc{} || end != timestep->data() + timestep->size()) {
      throw InputError(
          fmt::format("{}:{}: timestep '{}' is not a number", path.string(), line, *timestep));
    }
    entries_.push_back(entry);
  }
  // Continue numbering after the frames kept; truncate_after() recomputes it.
  truncate_after(std::numeric_limits<double>::infinity());
}

}  // namespace talus::io
