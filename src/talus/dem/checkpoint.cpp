#include "talus/dem/checkpoint.hpp"

#include "talus/core/error.hpp"
#include "talus/io/archive.hpp"

namespace talus::dem {

namespace {
constexpr const char* kMagic = "talus-dem-checkpoint";
constexpr int32_t kVersion = 3;

struct PairIndex {
  int32_t i, j;
};

// One function serves both directions so the two can never drift apart.
template <int D, class Ar, class System>
void transfer(Ar& ar, System& s) {
  auto& p = s.particles;
  ar(s.time), ar(s.step), ar(s.dt), ar(s.removed), ar(s.skin), ar(s.wall_displacement_at_build),
      ar(s.wall_angle_at_build);
  ar(p.x), ar(p.v), ar(p.f), ar(p.w), ar(p.t), ar(p.r), ar(p.inv_m), ar(p.inv_I), ar(p.m);
  ar(p.material), ar(p.id), ar(p.contacts), ar(p.wall_contacts);
  ar(s.pair_contacts), ar(s.wall_contacts);
  auto& nl = s.neighbours;
  ar(nl.wall_start), ar(nl.wall_prim), ar(nl.builds);
  ar(nl.reference_positions());
}

template <int D>
struct Saver {
  io::ArchiveWriter& w;
  template <class T>
  void operator()(const T& v) {
    w.put(v);
  }
};
template <int D>
struct Loader {
  io::ArchiveReader& r;
  template <class T>
  void operator()(T& v) {
    r.get(v);
  }
};
}  // namespace

template <int D>
void save_checkpoint(const DemSystem<D>& s, const std::filesystem::path& path) {
  if (!s.membranes.empty())
    throw RunError("checkpoints of runs with [[membranes]] are not implemented yet");
  io::ArchiveWriter w;
  w.put(kMagic);
  w.put(kVersion);
  w.put(static_cast<int32_t>(D));
  w.put(static_cast<int32_t>(s.walls.size()));
  Saver<D> save{w};
  transfer<D>(save, const_cast<DemSystem<D>&>(s));
  const auto& nl = s.neighbours;
  std::vector<PairIndex> pairs;
  std::vector<typename Space<D>::Vec> shear, wshear;
  std::vector<typename Space<D>::Rot> roll, wroll;
  for (const auto& q : nl.pairs) pairs.push_back({q.i, q.j});
  shear = nl.pair_shear;
  roll = nl.pair_roll;
  for (const auto& h : nl.wall_history) wshear.push_back(h.shear), wroll.push_back(h.roll);
  w.put(pairs), w.put(shear), w.put(roll), w.put(wshear), w.put(wroll);
  w.put(nl.skin());
  for (const auto& wall : s.walls) w.put(wall.force), w.put(wall.torque), w.put(wall.impulse);
  w.save(path);
}

template <int D>
void load_checkpoint(DemSystem<D>& s, const std::filesystem::path& path) {
  const std::string where = path.string() + ": ";
  if (!s.membranes.empty())
    throw InputError(where + "runs with [[membranes]] cannot resume from a checkpoint yet");
  io::ArchiveReader r(path);
  if (r.get<std::string>() != kMagic) throw InputError(where + "not a talus DEM checkpoint");
  if (r.get<int32_t>() != kVersion) throw InputError(where + "checkpoint format version differs");
  if (r.get<int32_t>() != D) throw InputError(where + "checkpoint has another dimension");
  if (r.get<int32_t>() != static_cast<int32_t>(s.walls.size()))
    throw InputError(where + "checkpoint has another number of walls than the scenario");
  Loader<D> load{r};
  transfer<D>(load, s);
  auto& nl = s.neighbours;
  std::vector<PairIndex> pairs;
  std::vector<typename Space<D>::Vec> shear, wshear;
  std::vector<typename Space<D>::Rot> roll, wroll;
  r.get(pairs), r.get(shear), r.get(roll), r.get(wshear), r.get(wroll);
  nl.set_skin(r.get<double>());
  if (shear.size() != pairs.size() || wshear.size() != nl.wall_prim.size())
    throw InputError(where + "inconsistent contact tables");
  if (roll.size() != pairs.size()) throw InputError(where + "inconsistent contact tables");
  nl.pairs.clear();
  for (const auto& q : pairs) nl.pairs.push_back({q.i, q.j});
  nl.pair_shear = std::move(shear);
  nl.pair_roll = std::move(roll);
  nl.wall_history.resize(wshear.size());
  for (std::size_t k = 0; k < wshear.size(); ++k) {
    nl.wall_history[k].shear = wshear[k];
    nl.wall_history[k].roll = wroll[k];
  }
  for (auto& wall : s.walls) r.get(wall.force), r.get(wall.torque), r.get(wall.impulse);
  if (!r.at_end()) throw InputError(where + "trailing data in checkpoint");
}

template void save_checkpoint<2>(const DemSystem<2>&, const std::filesystem::path&);
template void save_checkpoint<3>(const DemSystem<3>&, const std::filesystem::path&);
template void load_checkpoint<2>(DemSystem<2>&, const std::filesystem::path&);
template void load_checkpoint<3>(DemSystem<3>&, const std::filesystem::path&);

}  // namespace talus::dem
