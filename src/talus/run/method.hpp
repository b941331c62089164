#pragma once
// The method registry: each method (DEM, MPM, DAN, fv2d) says which scenario
// files it runs, how it validates one and how it builds a running Simulation.
// A new method lives in run/methods/<name>.cpp and is added to the list in
// run/methods/registry.cpp with one line.
#include <fmt/core.h>

#include <filesystem>
#include <functional>
#include <limits>
#include <memory>
#include <string>
#include <vector>

#include "talus/comm/comm.hpp"
#include "talus/run/simulation.hpp"
#include "talus/scenario/scenario.hpp"

namespace talus::run {

struct RunContext {
  std::filesystem::path out;  // the run folder: created and empty, or the run to resume
  int threads = 1;
  bool resume = false;
  // The ranks of an MPI job (comm/comm.hpp), given only to a method that
  // spreads over ranks; rank 0 writes every file, the others only compute.
  const comm::Comm* ranks = nullptr;
  bool writes() const { return ranks == nullptr || ranks->root(); }
  // Makes the folder of a fresh run; a method calls it once its input is
  // checked, before writing scenario.toml.
  std::function<void()> prepare = [] {};
};

// What `talus validate` learns of a scenario: the description it prints, and
// the number of steps the run would take (NaN where the method cannot tell
// before running: adaptive steps that depend on the flow).
struct Validation {
  std::string description;
  double steps = std::numeric_limits<double>::quiet_NaN();
  double duration = 0.0;  // simulated seconds, for the message of a refusal
};

struct Method {
  std::string name;  // "dem", "mpm", "dan", "fv2d"
  // True when this method runs the file: its `method` key, and `run.model`
  // where several methods share one ("runout").
  std::function<bool(const io::ScenarioFile&)> accepts;
  // Parses and builds without running. Throws InputError.
  std::function<Validation(const io::ScenarioFile&)> validate;
  // A fresh run writes the resolved scenario (scenario.toml) into ctx.out and
  // builds; a resumed one builds from it and restores checkpoint.bin.
  // Every method writes checkpoints (its outputs' on_checkpoint) and resumes
  // from them: the run layer offers --resume and checkpoint() for all.
  std::function<std::unique_ptr<Simulation>(const io::ScenarioFile&, const RunContext&)> create;
  // Whether `create` takes ctx.ranks: the run steps on every rank of an MPI
  // job (docs/mpi.md). The others are refused on more than one rank.
  bool spreads_over_ranks = false;
};

// "file:line: [table] 'key'" (without the line when the key is not in the
// file), for messages about a key the methods check after parsing.
inline std::string where_key(const io::ScenarioFile& f, const std::string& table,
                             const std::string& key) {
  const auto* node = f.table[table][key].node();
  const int line = node ? static_cast<int>(node->source().begin.line) : 0;
  return line > 0 ? fmt::format("{}:{}: [{}] '{}'", f.path, line, table, key)
                  : fmt::format("{}: [{}] '{}'", f.path, table, key);
}

// Every registered method, in registration order.
const std::vector<Method>& methods();
// The method that runs `file`; InputError naming the file when none does.
const Method& method_for(const io::ScenarioFile& file);

}  // namespace talus::run
