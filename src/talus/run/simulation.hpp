#pragma once
// One running method as the run loop sees it: a clock, a way to advance to a
// time, the method's own output files, and its part of summary.json. Each
// method (run/methods/) wraps its solver in one of these; the loop
// (run/loop.hpp) owns time, outputs and checkpoints and knows no method.
#include <algorithm>
#include <cstdint>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "talus/run/observer.hpp"
#include "talus/run/schedule.hpp"
#include "talus/run/wall_control.hpp"

namespace talus::run {

// The intervals a scenario asks for, in simulated seconds.
struct Schedules {
  OutputSchedule series, snapshots, checkpoints;
};

// What a method reports for summary.json besides the loop's counts.
struct MethodReport {
  std::string method;  // "dem", "mpm", "runout"
  std::string model;   // "" unless the method has several ("dan", "fv2d")
  int dimension = 0;
  nlohmann::json scenario;  // the resolved scenario
  nlohmann::json resolved;  // what the method chose (time step, grid, threads)
  nlohmann::json metrics;   // the headline results
  // One line of the key results, printed when the run ends (stderr and log.txt).
  std::string headline;
  // What the user must know of a completed run (material still moving at
  // the end): summary.json's "warnings", stderr and log.txt.
  std::vector<std::string> warnings;
  std::string rate_key;  // "particle_steps_per_s", ...
  double items = 0.0;    // particles, points, blocks or cells advanced per step
  nlohmann::json run_extra = nlohmann::json::object();  // more counts for "run"
};

// One array of a method's state as the Python API shows it, without a copy:
// C order (row-major) of `shape`. Valid until the method next changes its
// storage (a DEM re-sort or removal); fetch the arrays again after stepping.
struct StateArray {
  enum class Type { Float64, Int64 };
  std::string name;  // "x", "v", "h", ...
  std::string unit;  // SI: "m", "m/s", "m^2/s", ...
  Type type = Type::Float64;
  void* data = nullptr;
  std::vector<std::size_t> shape;  // {n}, {n, components} or {rows, columns}
  bool writable = false;           // true where changing it between steps is meaningful
  // Bytes between neighbours along each axis; empty: packed in C order. (A
  // field of an array of structs, e.g. MPM stresses, is strided.)
  std::vector<std::ptrdiff_t> strides = {};
};

class Simulation {
 public:
  virtual ~Simulation() = default;

  virtual double time() const = 0;
  virtual std::int64_t steps() const = 0;
  // The time the run ends at (a fixed-step method's last step may fall just
  // short of the scenario's duration).
  virtual double end_time() const = 0;
  // Times closer than this count as equal (output times, the end).
  virtual double tolerance() const { return 1e-9 * std::max(1.0, end_time()); }
  // The current (or last) time step, for progress estimates.
  virtual double time_step() const = 0;
  // Kinetic energy of what moves now (J; J/m in 2D), for the progress lines.
  virtual double kinetic_energy() const = 0;
  // Steps still to take (NaN when the method cannot tell: adaptive steps).
  virtual double estimated_steps() const = 0;
  virtual Schedules schedules() const = 0;

  // Before the first step: `fresh` starts a new run, otherwise the state was
  // restored from a checkpoint.
  virtual void start(bool fresh) = 0;
  // Steps until time() >= target - tolerance, or max_steps steps are taken,
  // or the method ends early (stopped()); never past end_time(). A method may
  // shorten its steps to land on `target` exactly. Health checks are the
  // method's: a RunError stops the run.
  virtual void advance(double target, double tolerance, std::int64_t max_steps) = 0;
  // True when the method ended before end_time() (e.g. the mass came to rest).
  virtual bool stopped() const { return false; }

  // The method's own files (series.csv, snapshots, checkpoint.bin), called
  // after every experiment's observer.
  virtual Observer& outputs() = 0;
  // Called once after every observer has seen a series row.
  virtual void after_series() {}
  // End of the run: results written once (deposit maps, front tables).
  virtual void finish() {}
  virtual MethodReport report() const = 0;
  // The state's arrays (none where a method shows none yet).
  virtual std::vector<StateArray> state_arrays() { return {}; }
  // How many times the method has reordered or removed rows of its state
  // arrays since the run began (a DEM neighbour build sorts the particles
  // by cell): while it stays the same, row i is the same particle.
  virtual std::int64_t reorders() const { return 0; }
  // The walls a caller may read and drive between steps; null for a method
  // without walls.
  virtual WallControl* wall_control() { return nullptr; }
};

}  // namespace talus::run
