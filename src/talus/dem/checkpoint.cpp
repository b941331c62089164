#include "talus/dem/checkpoint.hpp"

#include <fmt/format.h>

#include "talus/core/error.hpp"
#include "talus/io/archive.hpp"

namespace talus::dem {

namespace {
constexpr const char* kMagic = "talus-dem-checkpoint";
// 4: membranes (state and contact springs) and the walls' servo state.
// 5: the critical step, its reference speed and the settling time (a resume
// no longer places the particles it would compute them from).
// 6: the work each wall has done, the kinetic energy removed particles took along.
// 7: the walls' translation and servo settings, which a caller may change
// during the run (the Python API), and the translation they replaced.
// 8: the threads' chunk cut (dem/chunk_cut.hpp), so that a resume on several
// threads sums forces in the same order.
constexpr int32_t kVersion = 8;

struct PairIndex {
  int32_t i, j;
};

// One function serves both directions so the two can never drift apart.
template <int D, class Ar, class System>
void transfer(Ar& ar, System& s) {
  auto& p = s.particles;
  ar(s.time), ar(s.step), ar(s.dt), ar(s.removed), ar(s.skin), ar(s.wall_displacement_at_build),
      ar(s.wall_angle_at_build);
  ar(s.critical_time_step), ar(s.reference_speed), ar(s.settle_time);
  ar(s.removed_kinetic_energy);
  ar(p.x), ar(p.v), ar(p.f), ar(p.w), ar(p.t), ar(p.r), ar(p.inv_m), ar(p.inv_I), ar(p.m);
  ar(p.material), ar(p.id), ar(p.contacts), ar(p.wall_contacts);
  ar(s.pair_contacts), ar(s.wall_contacts);
  auto& nl = s.neighbours;
  ar(nl.wall_start), ar(nl.wall_prim), ar(nl.builds);
  ar(nl.reference_positions());
  ar(s.chunk_cut.build), ar(s.chunk_cut.particles), ar(s.chunk_cut.starts);
}

// The friction springs of one membrane's contacts.
template <class Ar>
void transfer_memory(Ar& ar, membrane::ContactMemory::Saved& m) {
  ar(m.grain), ar(m.feature), ar(m.point), ar(m.shear), ar(m.roll);
}

// Everything of a membrane that evolves, or that the first half kick after a
// resume reads (the forces f). The mesh, masses and material come from the
// scenario. Rest shape, pressure and the pinned particles do not change in a
// run today; they are stored all the same, so that a protocol that changes
// them (pre-tension, a stepped vacuum) resumes correctly.
template <class Ar>
void transfer_membrane(Ar& ar, membrane::MembraneBody& mb) {
  auto& m = mb.body;
  ar(m.x), ar(m.v), ar(m.f), ar(m.fixed), ar(m.follows), ar(m.anchor);
  ar(m.rest.length), ar(m.rest.sin_half_angle), ar(m.params.pressure);
  ar(mb.reaction), ar(mb.contacts), ar(mb.self_contacts);
}

// Chunks start in order within the particles, the first at 0.
bool valid_cut(const ChunkCut& cut) {
  int64_t previous = 0;
  for (const int32_t start : cut.starts) {
    if (start < previous || start > cut.particles) return false;
    previous = start;
  }
  return cut.starts.empty() || cut.starts.front() == 0;
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
  // A driven sphere's friction springs are not stored, nor a membrane rig's
  // mould faces and pinned supports (the scenario reader refuses checkpoints
  // of the experiments that set them up; this guards other callers).
  if (!s.objects.empty())
    throw InputError("checkpoints of runs with a driven object are not supported");
  for (const auto& m : s.membranes)
    if (m.rig) throw InputError("checkpoints of runs with a membrane rig are not supported");
  io::ArchiveWriter w;
  w.put(kMagic);
  w.put(kVersion);
  w.put(static_cast<int32_t>(D));
  w.put(static_cast<int32_t>(s.walls.size()));
  w.put(static_cast<int32_t>(s.membranes.size()));
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
  for (const auto& wall : s.walls) {
    w.put(wall.force), w.put(wall.torque), w.put(wall.impulse), w.put(wall.work);
    w.put(wall.servo_travel), w.put(wall.servo_speed);
    const auto& m = wall.motion;
    w.put(wall.shift), w.put(m.velocity), w.put(m.move_start), w.put(m.move_stop);
    w.put(wall.servo_normal), w.put(m.servo_pressure), w.put(m.servo_area), w.put(m.servo_speed);
    w.put(m.servo_stop);
  }
  for (const auto& mb : s.membranes) {
    w.put(mb.name);
    w.put(static_cast<int64_t>(mb.body.x.size()));
    transfer_membrane(save, const_cast<membrane::MembraneBody&>(mb));
    auto springs = mb.memory.saved(), self_springs = mb.self_memory.saved();
    transfer_memory(save, springs);
    transfer_memory(save, self_springs);
  }
  w.save(path);
}

template <int D>
void load_checkpoint(DemSystem<D>& s, const std::filesystem::path& path) {
  const std::string where = path.string() + ": ";
  io::ArchiveReader r(path);
  if (r.get<std::string>() != kMagic) throw InputError(where + "not a talus DEM checkpoint");
  if (const int32_t v = r.get<int32_t>(); v != kVersion)
    throw InputError(where + fmt::format("checkpoint format version {}, this talus reads version "
                                         "{} (written by another talus: rerun from the start)",
                                         v, kVersion));
  if (r.get<int32_t>() != D) throw InputError(where + "checkpoint has another dimension");
  if (r.get<int32_t>() != static_cast<int32_t>(s.walls.size()))
    throw InputError(where + "checkpoint has another number of walls than the scenario");
  if (r.get<int32_t>() != static_cast<int32_t>(s.membranes.size()))
    throw InputError(where + "checkpoint has another number of membranes than the scenario");
  Loader<D> load{r};
  transfer<D>(load, s);
  if (!valid_cut(s.chunk_cut)) throw InputError(where + "inconsistent thread chunk cut");
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
  for (auto& wall : s.walls) {
    r.get(wall.force), r.get(wall.torque), r.get(wall.impulse), r.get(wall.work);
    r.get(wall.servo_travel), r.get(wall.servo_speed);
    auto& m = wall.motion;
    r.get(wall.shift), r.get(m.velocity), r.get(m.move_start), r.get(m.move_stop);
    r.get(wall.servo_normal), r.get(m.servo_pressure), r.get(m.servo_area), r.get(m.servo_speed);
    r.get(m.servo_stop);
  }
  for (auto& mb : s.membranes) {
    const auto name = r.get<std::string>();
    const auto n = r.get<int64_t>();
    if (name != mb.name || n != static_cast<int64_t>(mb.body.x.size()))
      throw InputError(where + fmt::format("checkpoint has membrane '{}' with {} particles where "
                                           "the scenario has '{}' with {}",
                                           name, n, mb.name, mb.body.x.size()));
    transfer_membrane(load, mb);
    const std::size_t nv = mb.body.x.size(), ne = mb.body.mesh.edges.size();
    if (mb.body.v.size() != nv || mb.body.f.size() != nv || mb.body.fixed.size() != nv ||
        mb.body.follows.size() != nv || mb.body.anchor.size() != nv ||
        mb.body.rest.length.size() != ne || mb.body.rest.sin_half_angle.size() != ne)
      throw InputError(where + "membrane '" + mb.name + "': inconsistent particle arrays");
    membrane::ContactMemory::Saved springs, self_springs;
    transfer_memory(load, springs);
    transfer_memory(load, self_springs);
    try {
      mb.memory.restore(springs);
      mb.self_memory.restore(self_springs);
    } catch (const InputError& e) {
      throw InputError(where + "membrane '" + mb.name + "': " + e.what());
    }
  }
  if (!r.at_end()) throw InputError(where + "trailing data in checkpoint");
}

template void save_checkpoint<2>(const DemSystem<2>&, const std::filesystem::path&);
template void save_checkpoint<3>(const DemSystem<3>&, const std::filesystem::path&);
template void load_checkpoint<2>(DemSystem<2>&, const std::filesystem::path&);
template void load_checkpoint<3>(DemSystem<3>&, const std::filesystem::path&);

}  // namespace talus::dem
