#pragma once
// The run's log.txt (and, for batch jobs whose stderr is not a terminal, the
// same lines on stderr): when and what started, a progress line every
// `interval` wall seconds (simulated time, steps per second, time left,
// kinetic energy), how the run ended and its headline. LIGGGHTS' thermo output plays this part for
// its users; without it a batch log shows nothing for minutes.
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>

#include "talus/run/loop.hpp"

namespace talus::run {

class RunLog {
 public:
  // Appends to out/log.txt (a resumed run continues its log; an empty `out`:
  // no file). `echo`: also write each line to stderr.
  RunLog(const std::filesystem::path& out, double interval_seconds, bool echo);

  void started(const std::string& what);
  // Called by the run loop's progress callback (every second or so); writes
  // a line when `interval` seconds have passed since the last one.
  void progress(const Progress& p);
  void ended(const std::string& what);
  // A line during the run, as `started` (e.g. the wall-time estimate).
  void note(const std::string& text);
  // The run's key results, after `ended`: into log.txt only (the command
  // line prints them on stderr itself).
  void headline(const std::string& text);

 private:
  void line(const std::string& text, bool echo);

  std::ofstream file_;
  double interval_;
  bool echo_;
  double last_ = 0.0;  // wall seconds of the last progress line
  ProgressClock clock_{0.0};
};

}  // namespace talus::run
