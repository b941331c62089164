#include "talus/runout/checkpoint.hpp"

#include <fmt/format.h>

#include <string>

#include "talus/core/error.hpp"
#include "talus/io/archive.hpp"

namespace talus::runout {

namespace {

constexpr int32_t kVersion = 3;  // 2: fv2d's peak momentum; 3: the grid models' path results

// The header every runout checkpoint starts with; `kind` tells DAN from fv2d.
void put_header(io::ArchiveWriter& w, const char* kind, const StepCount& count) {
  w.put("talus-runout-checkpoint");
  w.put(kVersion);
  w.put(kind);
  w.put(count.steps);
  w.put(count.last_time_step);
}

StepCount get_header(io::ArchiveReader& r, const std::string& kind, const std::string& where) {
  if (r.get<std::string>() != "talus-runout-checkpoint")
    throw InputError(where + "not a talus runout checkpoint");
  if (const auto version = r.get<int32_t>(); version != kVersion)
    throw InputError(where + fmt::format("checkpoint format version {} is not this talus's {} "
                                         "(written by another version): rerun from the start",
                                         version, kVersion));
  if (const auto found = r.get<std::string>(); found != kind)
    throw InputError(where + fmt::format("a {} checkpoint, not {}", found, kind));
  StepCount count;
  r.get(count.steps), r.get(count.last_time_step);
  return count;
}

void check_end(const io::ArchiveReader& r, const std::string& where) {
  if (!r.at_end()) throw InputError(where + "trailing data in checkpoint");
}

// One function per model serves both directions, so that what is saved and
// what is loaded cannot drift apart (as mpm/checkpoint.cpp).
template <class Ar>
void transfer(Ar& ar, RunoutResults& r) {
  ar(r.front), ar(r.deposit), ar(r.runup_max), ar(r.runup_final);
  ar(r.tail_s), ar(r.tail_s_absolute), ar(r.barrier_arrival_time), ar(r.rest_time);
  ar(r.max_depth), ar(r.max_speed);
}

template <class Ar>
void transfer(Ar& ar, DanBlocks& b, DanModel::EnergyWatch& watch, RunoutResults& r) {
  ar(b.s), ar(b.v), ar(b.volume), ar(b.k), ar(b.time);
  ar(watch.lowest), ar(watch.kinetic_peak), ar(watch.depth_start);
  transfer(ar, r);
}

template <class Ar>
void transfer(Ar& ar, FlowState& s, std::vector<double>& k, double& outflow, Fv2dMaxima& m,
              double& released_volume, RunoutResults& path) {
  ar(s.h), ar(s.hu), ar(s.hv), ar(s.time);
  ar(k), ar(outflow);
  ar(m.height), ar(m.speed), ar(m.pressure), ar(m.arrival);
  ar(m.peak_speed), ar(m.peak_height), ar(m.peak_momentum);
  ar(released_volume);
  transfer(ar, path);
}

template <class Ar>
void transfer(Ar& ar, TwoPhaseState& s, std::vector<double>& k, TwoPhaseTotals& t,
              TwoPhaseMaxima& m, ReleasedVolumes& released, RunoutResults& path) {
  ar(s.hs), ar(s.hsu), ar(s.hsv), ar(s.hf), ar(s.hfu), ar(s.hfv), ar(s.time);
  ar(k), ar(t.solid_outflow), ar(t.fluid_outflow), ar(t.rained), ar(t.infiltrated);
  for (auto* v : {&m.height, &m.solid_height, &m.fluid_height, &m.solid_speed, &m.fluid_speed,
                  &m.pressure, &m.solid_pressure, &m.fluid_pressure, &m.arrival})
    ar(*v);
  ar(m.peak_speed), ar(m.peak_height);
  ar(released.solid), ar(released.fluid);
  transfer(ar, path);
}

}  // namespace

void save_checkpoint(const DanModel& model, const RunoutTracker& tracker, StepCount count,
                     const std::filesystem::path& path) {
  io::ArchiveWriter w;
  put_header(w, "dan", count);
  DanBlocks b = model.blocks();
  DanModel::EnergyWatch watch = model.energy_watch();
  RunoutResults r = tracker.results();
  io::ArchiveSaver save{w};
  transfer(save, b, watch, r);
  w.save(path);
}

StepCount load_checkpoint(DanModel& model, RunoutTracker& tracker,
                          const std::filesystem::path& path) {
  const std::string where = path.string() + ": ";
  io::ArchiveReader r(path);
  const StepCount count = get_header(r, "dan", where);
  DanBlocks b;
  DanModel::EnergyWatch watch;
  RunoutResults res;
  io::ArchiveLoader load{r};
  transfer(load, b, watch, res);
  check_end(r, where);
  try {
    model.restore(std::move(b), watch);
  } catch (const InputError& e) {
    throw InputError(where + e.what());
  }
  tracker.restore(std::move(res));
  return count;
}

void save_checkpoint(const Fv2dSolver& solver, const Fv2dMaxima& maxima, double released_volume,
                     const RunoutResults& path_results, StepCount count,
                     const std::filesystem::path& path) {
  io::ArchiveWriter w;
  put_header(w, "fv2d", count);
  FlowState s = solver.state();
  std::vector<double> k = solver.earth_pressure();
  double outflow = solver.outflow_volume();
  Fv2dMaxima m = maxima;
  RunoutResults r = path_results;
  io::ArchiveSaver save{w};
  transfer(save, s, k, outflow, m, released_volume, r);
  w.save(path);
}

StepCount load_checkpoint(Fv2dSolver& solver, Fv2dMaxima& maxima, double& released_volume,
                          RunoutResults& path_results, const std::filesystem::path& path) {
  const std::string where = path.string() + ": ";
  io::ArchiveReader r(path);
  const StepCount count = get_header(r, "fv2d", where);
  FlowState s;
  std::vector<double> k;
  double outflow = 0.0;
  Fv2dMaxima m;
  io::ArchiveLoader load{r};
  transfer(load, s, k, outflow, m, released_volume, path_results);
  check_end(r, where);
  const std::size_t cells = solver.terrain().shape().cells();
  if (m.height.size() != cells || m.speed.size() != cells || m.pressure.size() != cells ||
      m.arrival.size() != cells)
    throw InputError(where + "the checkpoint's grid is not this scenario's");
  try {
    solver.restore(s, std::move(k), outflow);
  } catch (const InputError& e) {
    throw InputError(where + e.what());
  }
  maxima = std::move(m);
  return count;
}

void save_checkpoint(const TwoPhaseSolver& solver, const TwoPhaseMaxima& maxima,
                     ReleasedVolumes released, const RunoutResults& path_results, StepCount count,
                     const std::filesystem::path& path) {
  io::ArchiveWriter w;
  put_header(w, "two_phase", count);
  TwoPhaseState s = solver.state();
  std::vector<double> k = solver.earth_pressure();
  TwoPhaseTotals t = solver.totals();
  TwoPhaseMaxima m = maxima;
  RunoutResults r = path_results;
  io::ArchiveSaver save{w};
  transfer(save, s, k, t, m, released, r);
  w.save(path);
}

StepCount load_checkpoint(TwoPhaseSolver& solver, TwoPhaseMaxima& maxima, ReleasedVolumes& released,
                          RunoutResults& path_results, const std::filesystem::path& path) {
  const std::string where = path.string() + ": ";
  io::ArchiveReader r(path);
  const StepCount count = get_header(r, "two_phase", where);
  TwoPhaseState s;
  std::vector<double> k;
  TwoPhaseTotals t;
  TwoPhaseMaxima m;
  io::ArchiveLoader load{r};
  transfer(load, s, k, t, m, released, path_results);
  check_end(r, where);
  const std::size_t cells = solver.terrain().shape().cells();
  for (const auto* v : {&m.height, &m.solid_height, &m.fluid_height, &m.solid_speed, &m.fluid_speed,
                        &m.pressure, &m.solid_pressure, &m.fluid_pressure, &m.arrival})
    if (v->size() != cells)
      throw InputError(where + "the checkpoint's grid is not this scenario's");
  try {
    solver.restore(s, std::move(k), t);
  } catch (const InputError& e) {
    throw InputError(where + e.what());
  }
  maxima = std::move(m);
  return count;
}

}  // namespace talus::runout
