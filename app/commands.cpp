#include "commands.hpp"

#include <fmt/core.h>
#include <omp.h>
#include <toml++/toml.h>
#include <unistd.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <sstream>

#include "talus/core/error.hpp"
#include "talus/run/run.hpp"

namespace fs = std::filesystem;

namespace talus::app {

std::string scenarios_folder() {
  if (const char* env = std::getenv("TALUS_SCENARIOS")) return env;
  return std::string(TALUS_SOURCE_DIR) + "/scenarios";
}

namespace {

void progress_line(const run::Progress& p) {
  const double left = p.steps_per_s > 0 ? (p.end - p.time) / p.time_step / p.steps_per_s : 0.0;
  fmt::print(stderr, "\r  t = {:.4f} / {:.4f} s   {:.0f} steps/s   {:.0f} s left   ", p.time, p.end,
             p.steps_per_s, left);
  if (p.time >= p.end) fmt::print(stderr, "\n");
  std::fflush(stderr);
}

}  // namespace

int run_command(const RunOptions& opt) {
  omp_set_num_threads(opt.threads);
  run::RunRequest req;
  req.file = opt.file;
  req.out = opt.out;
  req.resume = opt.resume;
  req.sets = opt.sets;
  req.threads = opt.threads;
  req.force = opt.force;
  // A terminal gets a progress line that rewrites itself; a batch job's log
  // gets log.txt's lines.
  const bool terminal = isatty(STDERR_FILENO);
  if (!opt.quiet && terminal) req.progress = progress_line;
  req.log_to_stderr = !opt.quiet && !terminal;
  req.log_seconds = opt.log_seconds;
  const auto result = run::execute(req);
  if (!opt.quiet) {
    fmt::print(stderr, "talus: {} steps in {:.2f} s; results in {}\n", result.stats.steps,
               result.stats.wall_seconds, result.out.string());
    for (const auto& text : result.headline) {
      std::istringstream lines(text);
      for (std::string line; std::getline(lines, line);) fmt::print(stderr, "talus: {}\n", line);
    }
  }
  return 0;
}

int validate_command(const ValidateOptions& opt) {
  fmt::print("{}: {}\n", opt.file, run::validate(opt.file, opt.sets));
  return 0;
}

int list_command() {
  const fs::path dir = scenarios_folder();
  if (!fs::is_directory(dir)) throw InputError(dir.string() + ": scenarios folder not found");
  std::vector<fs::path> files;
  for (const auto& e : fs::directory_iterator(dir))
    if (e.path().extension() == ".toml") files.push_back(e.path());
  std::sort(files.begin(), files.end());
  for (const auto& f : files) {
    std::string desc;
    try {
      const auto t = toml::parse_file(f.string());
      desc = t["description"].value_or(std::string());
    } catch (const std::exception&) {
      desc = "(unreadable)";
    }
    fmt::print("{:<28} {}\n", f.stem().string(), desc);
  }
  return 0;
}

}  // namespace talus::app
