#pragma once
// `talus run` and `talus validate` without the command line: from a scenario
// file (or a run folder to resume) to a finished run folder with its
// summary.json. The command line (app/) only parses options and prints.
#include <filesystem>
#include <functional>
#include <string>
#include <vector>

#include "talus/run/loop.hpp"
#include "talus/run/output_folder.hpp"

namespace talus::run {

struct RunRequest {
  std::string file;  // the scenario; empty when resuming
  // The scenario's text instead of reading `file` (the Python API's
  // scenarios from dicts); `file` then names it in messages, and relative
  // paths in it resolve against its folder.
  std::string text;
  std::filesystem::path out;      // empty: runs/<name>
  std::filesystem::path resume;   // a run folder to continue from its checkpoint
  std::vector<std::string> sets;  // "key=value" overrides
  // OpenMP threads; 0: one for a new run, and for a resume the count the run
  // last ran on (its bits depend on it).
  int threads = 0;
  bool force = false;  // empty an existing output folder
  std::function<void(const Progress&)> progress;
  double log_seconds = 10.0;    // wall seconds between progress lines in log.txt
  bool log_to_stderr = false;   // also write log.txt's lines to stderr (batch jobs)
  bool allow_long_run = false;  // run even when estimated above 10^9 steps (step_limit.hpp)
};

struct RunResult {
  std::filesystem::path out;
  RunStats stats;
  std::vector<std::string> headline;  // key results, one line each
  std::vector<std::string> warnings;  // the method's (MethodReport::warnings)
};

// Runs a scenario to its end. InputError before anything runs; RunError when
// the run fails (summary.json then says "failed" and why).
RunResult execute(const RunRequest& request);

// Parses and builds a scenario without running: the one-line description.
// Refuses (InputError) a run estimated above 10^9 steps unless `allow_long_run`.
std::string validate(const std::string& file, const std::vector<std::string>& sets,
                     bool allow_long_run = false);
// The same for a scenario's text, named `file` (RunRequest::text).
std::string validate_text(const std::string& text, const std::string& file,
                          const std::vector<std::string>& sets, bool allow_long_run = false);

}  // namespace talus::run
