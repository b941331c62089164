#include "talus/runout/checkpoint.hpp"

#include <fmt/format.h>

#include <string>

#include "talus/core/error.hpp"
#include "talus/io/archive.hpp"

namespace talus::runout {

namespace {

constexpr int32_t kVersion = 1;

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

}  // namespace

void save_checkpoint(const DanModel& model, const RunoutTracker& tracker, StepCount count,
                     const std::filesystem::path& path) {
  io::ArchiveWriter w;
  put_header(w, "dan", count);
  const auto& b = model.blocks();
  w.put(b.s), w.put(b.v), w.put(b.volume), w.put(b.k), w.put(b.time);
  const auto watch = model.energy_watch();
  w.put(watch.lowest), w.put(watch.kinetic_peak), w.put(watch.depth_start);
  const auto& r = tracker.results();
  w.put(r.front), w.put(r.deposit), w.put(r.runup_max), w.put(r.runup_final);
  w.put(r.tail_s), w.put(r.tail_s_absolute), w.put(r.barrier_arrival_time), w.put(r.rest_time);
  w.put(r.max_depth), w.put(r.max_speed);
  w.save(path);
}

StepCount load_checkpoint(DanModel& model, RunoutTracker& tracker,
                          const std::filesystem::path& path) {
  const std::string where = path.string() + ": ";
  io::ArchiveReader r(path);
  const StepCount count = get_header(r, "dan", where);
  DanBlocks b;
  r.get(b.s), r.get(b.v), r.get(b.volume), r.get(b.k), r.get(b.time);
  DanModel::EnergyWatch watch;
  r.get(watch.lowest), r.get(watch.kinetic_peak), r.get(watch.depth_start);
  RunoutResults res;
  r.get(res.front), r.get(res.deposit), r.get(res.runup_max), r.get(res.runup_final);
  r.get(res.tail_s), r.get(res.tail_s_absolute), r.get(res.barrier_arrival_time),
      r.get(res.rest_time);
  r.get(res.max_depth), r.get(res.max_speed);
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
                     StepCount count, const std::filesystem::path& path) {
  io::ArchiveWriter w;
  put_header(w, "fv2d", count);
  const auto& s = solver.state();
  w.put(s.h), w.put(s.hu), w.put(s.hv), w.put(s.time);
  w.put(solver.earth_pressure()), w.put(solver.outflow_volume());
  w.put(maxima.height), w.put(maxima.speed), w.put(maxima.pressure), w.put(maxima.arrival);
  w.put(maxima.peak_speed), w.put(maxima.peak_height);
  w.put(released_volume);
  w.save(path);
}

StepCount load_checkpoint(Fv2dSolver& solver, Fv2dMaxima& maxima, double& released_volume,
                          const std::filesystem::path& path) {
  const std::string where = path.string() + ": ";
  io::ArchiveReader r(path);
  const StepCount count = get_header(r, "fv2d", where);
  FlowState s;
  r.get(s.h), r.get(s.hu), r.get(s.hv), r.get(s.time);
  std::vector<double> k;
  double outflow = 0.0;
  r.get(k), r.get(outflow);
  Fv2dMaxima m;
  r.get(m.height), r.get(m.speed), r.get(m.pressure), r.get(m.arrival);
  r.get(m.peak_speed), r.get(m.peak_height);
  r.get(released_volume);
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

}  // namespace talus::runout
