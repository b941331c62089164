#pragma once
// A run in pieces: `talus run` built, advanced and finished by its caller.
// The constructor does everything before the first step (InputError before
// anything runs, the run folder claimed, scenario.toml written); advance()
// steps the one run loop by steps or to a time (outputs fall on the same
// times however it is driven); finish() writes summary.json. execute()
// (run.hpp) is a session run to its end; the Python API steps one.
#include <atomic>
#include <chrono>
#include <cstdint>
#include <filesystem>
#include <memory>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <thread>
#include <vector>

#include "talus/run/experiment.hpp"
#include "talus/run/loop.hpp"
#include "talus/run/method.hpp"
#include "talus/run/output_folder.hpp"
#include "talus/run/run.hpp"
#include "talus/run/run_log.hpp"
#include "talus/run/summary.hpp"

namespace talus::run {

class RunSession {
 public:
  explicit RunSession(const RunRequest& request);
  // Unfinished (the caller stopped early, or an error left it): summary.json
  // says "stopped" at the time reached. Never throws.
  ~RunSession();
  RunSession(const RunSession&) = delete;
  RunSession& operator=(const RunSession&) = delete;

  // Up to `steps` steps (< 0: no limit), not past `until` (simulated
  // seconds; the run's end when later). A RunError (or any failure) writes
  // summary.json as "failed" and is rethrown; the session is then finished.
  RunStats advance(double until, std::int64_t steps);
  RunStats run_to_end();
  // Writes the checkpoint a resume continues from, now (InputError once the
  // run is done: there is nothing to resume).
  void checkpoint();
  // The walls (DEM): readings, and motion changed from now on, by name; each
  // change is a line in log.txt. InputError for an unknown wall or a method
  // without walls, or a change the wall cannot take (wall_control.hpp).
  std::vector<WallReading> walls() const;
  // What the method chose (time step, grid and its transform, threads):
  // summary.json's "resolved", known from the start (which it makes happen).
  nlohmann::json resolved();
  void set_wall_velocity(const std::string& name, const Vec3& v);
  void set_wall_servo(const std::string& name, double pressure, double speed, double area);
  // The run reached its end time or the method stopped (at rest).
  bool done() const { return loop_->done(); }
  bool finished() const { return finished_; }
  // A call is stepping the run (or changing it) now.
  bool stepping() const { return owner_.load() != std::thread::id(); }
  // Held by every call that steps or changes the run, and by a caller that
  // steps it in pieces (the Python module) across them: the same thread may
  // claim again, another gets InputError ("stepping in another thread").
  class Claim {
   public:
    explicit Claim(RunSession& s);
    ~Claim();
    Claim(const Claim&) = delete;
    Claim& operator=(const Claim&) = delete;

   private:
    RunSession& s_;
  };
  // Writes summary.json: "completed" when done(), otherwise "stopped" (the
  // caller ended it early); returns the headline and warnings.
  RunResult finish();

  Simulation& simulation() { return *sim_; }
  const Simulation& simulation() const { return *sim_; }
  const std::filesystem::path& out() const { return out_; }
  const RunStats& stats() const { return loop_->stats(); }

 private:
  void fill(const char* status, const std::string& error);
  void fail(const std::exception& e);
  void begin();  // the loop's start, before the first advance or checkpoint
  WallControl& walls_of_method() const;
  std::size_t wall_index(const std::string& name) const;

  RunRequest request_;
  std::filesystem::path out_;
  bool resume_ = false;
  RunContext ctx_;
  std::optional<OutputFolder> folder_;
  std::unique_ptr<Simulation> sim_;
  std::vector<std::unique_ptr<Experiment>> experiments_;
  std::unique_ptr<RunLoop> loop_;
  std::unique_ptr<RunLog> log_;
  SummaryInput summary_;
  std::chrono::steady_clock::time_point loop_t0_;
  std::int64_t first_step_ = 0;
  int threads_ = 1;                    // what the run steps on
  std::vector<std::string> warnings_;  // the session's own, added to the method's
  bool started_ = false, finished_ = false;
  // The thread whose call steps or changes the run now (none: id()); a
  // second thread (another Python thread, the GIL being free while stepping)
  // is refused, not raced. depth_: that thread's nested claims.
  std::atomic<std::thread::id> owner_{};
  int depth_ = 0;
};

}  // namespace talus::run
