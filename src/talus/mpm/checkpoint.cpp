#include "talus/mpm/checkpoint.hpp"

#include <fmt/format.h>

#include <cstdint>

#include "talus/core/error.hpp"
#include "talus/io/archive.hpp"

namespace talus::mpm {

namespace {
constexpr const char* kMagic = "talus-mpm-checkpoint";
// 2: the membranes' state follows the rigid bodies (version 1 had none).
// 3: the work each rigid body has done.
constexpr int32_t kVersion = 3;

// One function serves both directions so the two can never drift apart. The
// material states go field by field (bool is not archivable as a vector).
template <int D, class Ar, class S>
void transfer(Ar& ar, S& s) {
  auto& p = s.particles;
  ar(s.time), ar(s.steps), ar(s.last_dt);
  ar(p.x), ar(p.v), ar(p.mass), ar(p.volume), ar(p.volume0), ar(p.velocity_gradient),
      ar(p.material), ar(p.affine);
  for (auto& r : s.rigid_bodies) ar(r.x), ar(r.normal), ar(r.hinge), ar(r.angle), ar(r.work);
  // All of a membrane's state; what the scenario rebuilds (masses, rest
  // shapes, fixed nodes) goes too, so a resumed run cannot depend on
  // rebuilding it bit for bit.
  for (auto& m : s.membranes) {
    ar(m.x), ar(m.v), ar(m.mass), ar(m.fixed), ar(m.rest_length);
    ar(m.tangent), ar(m.stretch), ar(m.velocity_gradient);
    ar(m.triangles), ar(m.rest_inverse), ar(m.rest_area);
  }
}

struct StateColumns {
  std::vector<Mat3> stress, deformation;
  std::vector<double> plastic_strain, cohesion;
  std::vector<uint8_t> yielding;
};

}  // namespace

template <int D>
void save_checkpoint(const Solver<D>& s, const std::filesystem::path& path) {
  io::ArchiveWriter w;
  w.put(kMagic);
  w.put(kVersion);
  w.put(static_cast<int32_t>(D));
  w.put(static_cast<int64_t>(s.particles.size()));
  w.put(static_cast<int32_t>(s.rigid_bodies.size()));
  w.put(static_cast<int32_t>(s.membranes.size()));
  for (const auto& m : s.membranes)
    w.put(static_cast<int64_t>(m.size())), w.put(static_cast<int64_t>(m.carriers()));
  io::ArchiveSaver save{w};
  transfer<D>(save, const_cast<Solver<D>&>(s));
  StateColumns c;
  for (const auto& st : s.particles.state) {
    c.stress.push_back(st.stress);
    c.deformation.push_back(st.deformation);
    c.plastic_strain.push_back(st.plastic_strain);
    c.cohesion.push_back(st.cohesion);
    c.yielding.push_back(st.yielding ? 1 : 0);
  }
  w.put(c.stress), w.put(c.deformation), w.put(c.plastic_strain), w.put(c.cohesion),
      w.put(c.yielding);
  w.save(path);
}

template <int D>
void load_checkpoint(Solver<D>& s, const std::filesystem::path& path) {
  const std::string where = path.string() + ": ";
  io::ArchiveReader r(path);
  if (r.get<std::string>() != kMagic) throw InputError(where + "not a talus MPM checkpoint");
  if (const auto version = r.get<int32_t>(); version != kVersion)
    throw InputError(where + fmt::format("checkpoint format version {} is not this talus's {} "
                                         "(written by another version): rerun from the start",
                                         version, kVersion));
  if (r.get<int32_t>() != D) throw InputError(where + "checkpoint has another dimension");
  if (r.get<int64_t>() != static_cast<int64_t>(s.particles.size()))
    throw InputError(where + "checkpoint has another number of material points than the scenario");
  if (r.get<int32_t>() != static_cast<int32_t>(s.rigid_bodies.size()))
    throw InputError(where + "checkpoint has another number of rigid bodies than the scenario");
  if (r.get<int32_t>() != static_cast<int32_t>(s.membranes.size()))
    throw InputError(where + "checkpoint has another number of membranes than the scenario");
  for (const auto& m : s.membranes)
    if (r.get<int64_t>() != static_cast<int64_t>(m.size()) ||
        r.get<int64_t>() != static_cast<int64_t>(m.carriers()))
      throw InputError(where + fmt::format("membrane '{}' has other nodes or carriers than in the "
                                           "checkpoint",
                                           m.name));
  io::ArchiveLoader load{r};
  transfer<D>(load, s);
  StateColumns c;
  r.get(c.stress), r.get(c.deformation), r.get(c.plastic_strain), r.get(c.cohesion),
      r.get(c.yielding);
  const std::size_t n = s.particles.size();
  if (s.particles.x.size() != n || s.particles.affine.size() != n || c.stress.size() != n ||
      c.yielding.size() != n)
    throw InputError(where + "inconsistent point tables");
  for (const auto& m : s.membranes)
    if (m.v.size() != m.size() || m.mass.size() != m.size() || m.fixed.size() != m.size() ||
        m.rest_area.size() != m.triangles.size() || m.rest_inverse.size() != m.triangles.size())
      throw InputError(where + "inconsistent membrane tables");
  for (std::size_t i = 0; i < n; ++i) {
    auto& st = s.particles.state[i];
    st.stress = c.stress[i];
    st.deformation = c.deformation[i];
    st.plastic_strain = c.plastic_strain[i];
    st.cohesion = c.cohesion[i];
    st.yielding = c.yielding[i] != 0;
  }
  if (!r.at_end()) throw InputError(where + "trailing data in checkpoint");
}

template void save_checkpoint<2>(const Solver<2>&, const std::filesystem::path&);
template void save_checkpoint<3>(const Solver<3>&, const std::filesystem::path&);
template void load_checkpoint<2>(Solver<2>&, const std::filesystem::path&);
template void load_checkpoint<3>(Solver<3>&, const std::filesystem::path&);

}  // namespace talus::mpm
