#pragma once
// ParaView snapshots: one VTK XML UnstructuredGrid file (.vtu) per frame plus a
// .pvd collection that lists them with their times. The collection is
// rewritten atomically after every frame, so a run interrupted at any moment
// leaves a collection that opens and lists only complete frames.
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include "talus/io/frame.hpp"

namespace talus::io {

class PvdSeries {
 public:
  struct Entry {
    double time;
    std::string file;  // relative to the collection's folder
  };

  // Frames go to dir/<basename>_000000.vtu, ... and dir/<basename>.pvd; dir is
  // created if needed. resume = false starts an empty collection (replacing an
  // old one at once); resume = true loads the existing collection, if any, so
  // that truncate_after() and add() continue it. basename may use letters,
  // digits, '_', '-' and '.'. Throws talus::InputError on an unreadable
  // collection when resuming and talus::RunError on I/O failure.
  PvdSeries(std::filesystem::path dir, std::string basename, bool resume = false);

  // Particles become VTK_VERTEX cells with point data radius, velocity,
  // angular_velocity, id, material, contacts and every extra scalar.
  void add(double time, const ParticleFrame& frame);
  // Walls become VTK_LINE and VTK_TRIANGLE cells with cell data "wall".
  void add(double time, const WallFrame& frame);
  // A mesh becomes VTK_TRIANGLE cells with its point and cell data.
  void add(double time, const MeshFrame& frame);

  // For resume: drops the frames later than `time` from the collection and
  // deletes their files; the next frame reuses the freed numbers.
  void truncate_after(double time);

  std::filesystem::path collection_path() const;
  const std::vector<Entry>& entries() const { return entries_; }

 private:
  std::filesystem::path next_file_path() const;
  void commit(double time);
  void write_collection() const;
  void load_collection();

  std::filesystem::path dir_;
  std::string basename_;
  std::vector<Entry> entries_;
  int64_t next_index_ = 0;
};

}  // namespace talus::io
