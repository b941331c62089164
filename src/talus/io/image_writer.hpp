#pragma once
// A field on a regular grid of boxes as a VTK XML ImageData file (.vti, ASCII), values as cell
// data: ParaView shows it as it is (e.g. glyphs of a velocity field).
#include <array>
#include <filesystem>
#include <map>
#include <string>
#include <vector>

#include "talus/core/space.hpp"

namespace talus::io {

struct CellImage {
  Vec3 origin = Vec3::Zero();   // lower corner of cell (0, 0, 0)
  Vec3 spacing = Vec3::Ones();  // cell size
  std::array<int, 3> cells{1, 1, 1};
  // Flat index i + nx (j + ny k), as many entries as cells.
  std::map<std::string, std::vector<double>> scalars;
  std::map<std::string, std::vector<Vec3>> vectors;
};

// Throws std::invalid_argument for arrays of the wrong length, RunError on I/O failure.
void write_cell_image(const std::filesystem::path& path, const CellImage& image);

}  // namespace talus::io
