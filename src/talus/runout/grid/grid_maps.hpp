#pragma once
// The map files the grid models (fv2d, two-phase) write on the terrain's
// grid: result rasters (GeoTIFF with the band's description and unit, and
// .npy for the plot script), and snapshot series (one GeoTIFF per field and
// time for QGIS, snapshots/times.csv, and snapshots/flow.pvd: the terrain
// surface, two triangles per cell, with the fields as cell data for
// ParaView). Values outside the domain (the terrain's no-data) are NaN, the
// GeoTIFFs' declared no-data value.
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include "talus/io/csv_writer.hpp"
#include "talus/io/frame.hpp"
#include "talus/io/vtk_writer.hpp"
#include "talus/runout/scenario.hpp"

namespace talus::runout {

// One map: values per cell of the grid, what they are and their unit.
struct GridField {
  std::string name;  // file stem: "max_height", "height"
  std::vector<double> values;
  std::string description, unit;
};

// dir/<name>.tif and dir/<name>.npy, NaN outside the domain.
void write_result_map(const std::filesystem::path& dir, const GridSpec& grid, GridField field);

class GridSnapshots {
 public:
  // In dir/snapshots; resume = true continues the files of a run interrupted
  // after its checkpoint at resume_time (dropping what came after it).
  GridSnapshots(const std::filesystem::path& dir, const GridSpec& grid, bool resume,
                double resume_time);
  // snapshots/<name>_NNNNNN.tif per field and one frame of flow.pvd.
  void add(double time, std::vector<GridField> fields);
  void flush();

 private:
  std::filesystem::path folder_;
  const GridSpec& grid_;
  std::unique_ptr<io::CsvSeries> times_;
  std::unique_ptr<io::PvdSeries> meshes_;
  // The terrain surface (built once), mesh_cell_ the cell of each triangle.
  io::MeshFrame mesh_;
  std::vector<std::size_t> mesh_cell_;
};

}  // namespace talus::runout
