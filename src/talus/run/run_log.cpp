#include "talus/run/run_log.hpp"

#include <fmt/chrono.h>
#include <fmt/format.h>

#include <chrono>
#include <ctime>

namespace talus::run {

RunLog::RunLog(const std::filesystem::path& out, double interval_seconds, bool echo)
    : interval_(interval_seconds), echo_(echo) {
  if (!out.empty()) file_.open(out / "log.txt", std::ios::app);
}

void RunLog::line(const std::string& text, bool echo) {
  const std::time_t now = std::time(nullptr);
  const std::string stamped = fmt::format("{:%Y-%m-%d %H:%M:%S} {}", fmt::localtime(now), text);
  if (file_.is_open()) file_ << stamped << '\n' << std::flush;
  if (echo) {
    fmt::print(stderr, "talus: {}\n", stamped);
    std::fflush(stderr);
  }
}

void RunLog::started(const std::string& what) { line(what, echo_); }

void RunLog::progress(const Progress& p) {
  const double now = clock_.elapsed();
  if (now - last_ < interval_ || p.time >= p.end) return;
  last_ = now;
  const double left = p.steps_per_s > 0 ? (p.end - p.time) / p.time_step / p.steps_per_s : 0.0;
  line(fmt::format(
           "t = {:.6g} / {:.6g} s, {:.0f} steps/s, dt = {:.3g} s, about {:.0f} s left, kinetic "
           "energy {:.4g} J",
           p.time, p.end, p.steps_per_s, p.time_step, left, p.kinetic_energy),
       echo_);
}

void RunLog::ended(const std::string& what) { line(what, echo_); }

void RunLog::note(const std::string& text) { line(text, echo_); }

void RunLog::headline(const std::string& text) { line(text, false); }

}  // namespace talus::run
