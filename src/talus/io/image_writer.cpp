#include "talus/io/image_writer.hpp"

#include <fmt/format.h>

#include <stdexcept>

#include "talus/io/archive.hpp"

namespace talus::io {

void write_cell_image(const std::filesystem::path& path, const CellImage& image) {
  const std::size_t n = static_cast<std::size_t>(image.cells[0]) * image.cells[1] * image.cells[2];
  std::string xml = fmt::format(
      "<?xml version=\"1.0\"?>\n"
      "<VTKFile type=\"ImageData\" version=\"1.0\">\n"
      "  <ImageData WholeExtent=\"0 {} 0 {} 0 {}\" Origin=\"{} {} {}\" Spacing=\"{} {} {}\">\n"
      "    <Piece Extent=\"0 {} 0 {} 0 {}\">\n      <CellData>\n",
      image.cells[0], image.cells[1], image.cells[2], image.origin.x(), image.origin.y(),
      image.origin.z(), image.spacing.x(), image.spacing.y(), image.spacing.z(), image.cells[0],
      image.cells[1], image.cells[2]);
  for (const auto& [name, values] : image.scalars) {
    if (values.size() != n)
      throw std::invalid_argument(
          fmt::format("cell image: '{}' has {} values for {} cells", name, values.size(), n));
    xml += fmt::format(
        "        <DataArray type=\"Float64\" Name=\"{}\" NumberOfComponents=\"1\" "
        "format=\"ascii\">\n",
        name);
    for (double v : values) xml += fmt::format("{} ", v);
    xml += "\n        </DataArray>\n";
  }
  for (const auto& [name, values] : image.vectors) {
    if (values.size() != n)
      throw std::invalid_argument(
          fmt::format("cell image: '{}' has {} values for {} cells", name, values.size(), n));
    xml += fmt::format(
        "        <DataArray type=\"Float64\" Name=\"{}\" NumberOfComponents=\"3\" "
        "format=\"ascii\">\n",
        name);
    for (const Vec3& v : values) xml += fmt::format("{} {} {} ", v.x(), v.y(), v.z());
    xml += "\n        </DataArray>\n";
  }
  xml += "      </CellData>\n    </Piece>\n  </ImageData>\n</VTKFile>\n";
  write_file_atomically(path, std::string_view(xml));
}

}  // namespace talus::io
