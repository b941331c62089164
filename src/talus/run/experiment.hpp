#pragma once
// Experiments as plug-ins: a named analysis (the flume, a triaxial test, a
// beam in bending) that attaches to a run when its scenario asks for it,
// observes the run through the loop, and writes its files and its part of
// summary.json. Each lives in run/experiments/<name>.cpp and is added to the
// list in run/experiments/registry.cpp with one line; no method knows one.
#include <functional>
#include <memory>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "talus/run/method.hpp"
#include "talus/run/observer.hpp"
#include "talus/run/simulation.hpp"

namespace talus::run {

class Experiment : public Observer {
 public:
  // Its key in summary.json ("flume", "triaxial", ...).
  virtual std::string name() const = 0;
  // Its part of summary.json, once the run has ended (or failed).
  virtual nlohmann::json finish() = 0;
  // Key results for the end of the run, from its summary part ("" for none).
  virtual std::string headline(const nlohmann::json& /*part*/) const { return ""; }
};

struct ExperimentKind {
  std::string name;
  // The experiment `sim` runs, when its scenario asks for this one; else null.
  std::function<std::unique_ptr<Experiment>(Simulation& sim, const RunContext& ctx)> attach;
};

// Every registered experiment, in registration order.
const std::vector<ExperimentKind>& experiments();

// The experiments a run asks for, attached to it.
std::vector<std::unique_ptr<Experiment>> attach_experiments(Simulation& sim, const RunContext& ctx);

}  // namespace talus::run
