#pragma once
// A run folder that talus owns while it writes there, and that it may later
// empty again without touching anyone else's files.
//
// Claiming a folder creates it (or takes an empty one), records in
// `.talus-run` that a run is writing there, and holds an exclusive lock on
// `.talus-lock` (flock: the kernel drops it when the process dies, so a killed
// run leaves no stale lock). When the OutputFolder goes away (the run finished,
// failed or threw) `.talus-run` lists every entry the folder then holds: those
// are talus's. `--force` on a non-empty folder empties it only when every
// entry is in that list; a folder without the record, one left by a run that
// was killed, or one holding anything else is refused with the reason.
#include <filesystem>
#include <string>

namespace talus::run {

class OutputFolder {
 public:
  // Creates or takes `out` for a new run; refuses (InputError) a non-empty
  // folder unless `force`, and with `force` a folder holding files talus did
  // not write; refuses a folder another run holds. `threads`: what the run
  // runs on (recorded, so that a resume can take the same; 0: not a run).
  static OutputFolder claim(const std::filesystem::path& out, bool force, int threads = 0);
  // Takes an existing run folder to continue a run in it (resume) on
  // `threads`; refuses one whose scenario.toml changed since the run wrote it.
  static OutputFolder reopen(const std::filesystem::path& out, int threads);
  // The thread count the run in `out` last ran on; 0 when not recorded.
  static int recorded_threads(const std::filesystem::path& out);
  // Records the checksum of the scenario.toml the run just wrote.
  void scenario_written();
  // Gives up the space claim() and reopen() hold back (`.talus-reserve`,
  // 64 KiB), so that the summary of a run that failed on a full disk fits.
  void free_reserve() noexcept;
  // The run was refused before it started (bad input found while building):
  // removes what it wrote, and the folder itself when claim() created it, so
  // that the refusal leaves nothing behind.
  void discard() noexcept;

  OutputFolder(OutputFolder&& other) noexcept;
  OutputFolder& operator=(OutputFolder&& other) noexcept;
  OutputFolder(const OutputFolder&) = delete;
  OutputFolder& operator=(const OutputFolder&) = delete;
  // Records the folder's entries as talus's and releases the lock.
  ~OutputFolder();

  const std::filesystem::path& path() const { return path_; }

 private:
  OutputFolder(std::filesystem::path path, int lock_fd) : path_(std::move(path)), lock_(lock_fd) {}
  void release() noexcept;

  std::filesystem::path path_;
  int lock_ = -1;  // file descriptor holding the flock, -1 when released
  // Whether release() lists the entries as talus's: only once the folder was
  // found empty or emptied, never for a claim that was refused.
  bool recording_ = false;
  std::string scenario_ = "-";  // checksum of scenario.toml, "-" before it is written
  int threads_ = 0;             // the run's thread count, 0 when not a run
  bool created_ = false;        // claim() made the folder
};

// A run name becomes the folder runs/<name>: it must be a plain name (letters,
// digits, '-', '_', '.', not starting with '.'). Throws InputError naming
// `where` otherwise.
void check_run_name(const std::string& name, const std::string& where);

}  // namespace talus::run
