#include "commands.hpp"

#include <fmt/core.h>
#include <toml++/toml.h>
#include <unistd.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <sstream>

#include "talus/comm/comm.hpp"
#include "talus/core/error.hpp"
#include "talus/run/run.hpp"
#include "talus/scenario/scenario.hpp"

namespace fs = std::filesystem;

namespace talus::app {

std::string scenarios_folder() {
  if (const char* env = std::getenv("TALUS_SCENARIOS")) return env;
  return std::string(TALUS_SOURCE_DIR) + "/scenarios";
}

namespace {

void progress_line(const run::Progress& p) {
  const double left = p.steps_per_s > 0 ? (p.end - p.time) / p.time_step / p.steps_per_s : 0.0;
  fmt::print(stderr, "\r  t = {:.4f} / {:.4f} s   {:.0f} steps/s   {:.0f} s left   KE {:.3g} J   ",
             p.time, p.end, p.steps_per_s, left, p.kinetic_energy);
  if (p.time >= p.end) fmt::print(stderr, "\n");
  std::fflush(stderr);
}

}  // namespace

int run_command(const RunOptions& opt) {
  run::RunRequest req;
  req.file = resolve_scenario(opt.file);
  req.out = opt.out;
  req.resume = opt.resume;
  req.sets = opt.sets;
  // --backend is the override it stands for; a resumed run keeps its own
  // (the refusal of extra --set values then names it).
  if (!opt.backend.empty()) req.sets.push_back("run.backend=\"" + opt.backend + "\"");
  req.threads = opt.threads;
  req.force = opt.force;
  req.allow_long_run = opt.allow_long_run;
  // A terminal gets a progress line that rewrites itself; a batch job's log
  // gets log.txt's lines.
  const bool terminal = isatty(STDERR_FILENO);
  if (!opt.quiet && terminal) req.progress = progress_line;
  req.log_to_stderr = !opt.quiet && !terminal;
  req.log_seconds = opt.log_seconds;
  const auto result = run::execute(req);
  // On several MPI ranks, rank 0 speaks for the run.
  if (!talus::comm::Comm::world().root()) return 0;
  for (const auto& text : result.warnings) fmt::print(stderr, "talus: warning: {}\n", text);
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
  const std::string file = resolve_scenario(opt.file);
  auto sets = opt.sets;
  if (!opt.backend.empty()) sets.push_back("run.backend=\"" + opt.backend + "\"");
  fmt::print("{}: {}\n", file, run::validate(file, sets, opt.allow_long_run));
  return 0;
}

namespace {

// The bundled scenario files, in name order, from every sub-folder (dem/, mpm/,
// runout/, compare/): a name is the file's stem, the folder is not part of it.
std::vector<fs::path> bundled_scenarios() {
  const fs::path dir = scenarios_folder();
  if (!fs::is_directory(dir)) throw InputError(dir.string() + ": scenarios folder not found");
  std::vector<fs::path> files;
  for (const auto& e : fs::recursive_directory_iterator(dir))
    if (e.is_regular_file() && e.path().extension() == ".toml") files.push_back(e.path());
  std::sort(files.begin(), files.end(),
            [](const fs::path& a, const fs::path& b) { return a.stem() < b.stem(); });
  return files;
}

// "dem 3D", "runout fv2d 2D", "mpm 2D", "compare": what a scenario runs.
std::string kind_of(const toml::table& t) {
  const std::string method = t["method"].value_or(std::string("?"));
  if (method == "runout") {
    const std::string model = t["run"]["model"].value_or(std::string("dan"));
    return fmt::format("runout {} {}D", model, model == "dan" ? 1 : 2);
  }
  if (const auto dim = t["run"]["dimension"].value<int64_t>())
    return fmt::format("{} {}D", method, *dim);
  return method;
}

}  // namespace

std::string resolve_scenario(const std::string& arg) {
  if (arg.empty() || fs::exists(arg) || arg.find('/') != std::string::npos ||
      fs::path(arg).extension() == ".toml")
    return arg;
  std::vector<fs::path> found;
  for (const auto& f : bundled_scenarios())
    if (f.stem() == arg) found.push_back(f);
  if (found.empty())
    throw InputError(fmt::format(
        "{}: neither a file nor the name of a bundled scenario (`talus list` shows them)", arg));
  // Names are stems and the files sit in sub-folders: a clash must not pick
  // one of two files silently.
  if (found.size() > 1)
    throw InputError(fmt::format("{}: the name of {} bundled scenarios ({}, {}); give the file",
                                 arg, found.size(), found[0].string(), found[1].string()));
  return found.front().string();
}

int list_command() {
  for (const auto& f : bundled_scenarios()) {
    std::string kind = "(unreadable)", duration, desc;
    try {
      // Through the reader, so that a file that extends another shows the result.
      const auto file = io::load_scenario_file(f.string(), {});
      const toml::table& t = file.table;
      kind = kind_of(t);
      desc = t["description"].value_or(std::string());
      if (const auto d = t["run"]["duration"].value<double>()) duration = fmt::format("{:g} s", *d);
    } catch (const std::exception&) {
    }
    fmt::print("{:<28} {:<16} {:>7}  {}\n", f.stem().string(), kind, duration, desc);
  }
  return 0;
}

}  // namespace talus::app
