// libFuzzer target for the scenario reader (issue 28 §6; scripts/fuzz.sh).
//
// Input: a scenario file's text, optionally followed by a line "--set" and
// one override ("key=value") per line. The reader must answer anything with
// a scenario or an InputError: any other exception, a crash, a hang or a
// sanitizer report is a finding. A scenario it accepts must also come back
// unchanged through the resolved form a run writes as scenario.toml (and
// reads again on --resume): parse -> emit -> parse succeeds and emits the
// same text.
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <string_view>
#include <vector>

#include "talus/core/error.hpp"
#include "talus/scenario/scenario.hpp"
#include "talus/scenario/scenario_mpm.hpp"
#include "talus/scenario/scenario_runout.hpp"

namespace {

using namespace talus;

// The file "lives" among the bundled scenarios so that `extends` and relative
// raster or mesh names reach real files: by default among the DEM ones, which
// the seeds' extends and data files name (flume_A_model3.toml, the packing
// .csv); the replay places each bundled file at its own path instead.
const std::string kDefaultPath = std::string(TALUS_SOURCE_DIR) + "/scenarios/dem/fuzz_input.toml";
std::string g_path = kDefaultPath;

[[noreturn]] void finding(const char* what, const std::string& a, const std::string& b) {
  std::fprintf(stderr, "fuzz_scenario: %s\n--- first\n%s\n--- second\n%s\n", what, a.c_str(),
               b.c_str());
  std::abort();
}

std::string emit(const io::ScenarioFile& file) {
  if (file.method == "dem") return io::scenario_to_toml(io::parse_dem_scenario(file));
  if (file.method == "mpm") return io::mpm_scenario_to_toml(io::parse_mpm_scenario(file));
  if (file.method == "runout") return io::runout_scenario_to_toml(io::parse_runout_scenario(file));
  return {};  // "compare": a list of other files, read by the compare command
}

void read(std::string_view text, const std::vector<std::string>& sets) {
  const auto file = io::load_scenario_text(text, g_path, sets);
  const std::string resolved = emit(file);
  if (resolved.empty()) return;
  std::string again;
  try {
    again = emit(io::load_scenario_text(resolved, g_path));
  } catch (const InputError& e) {
    finding(("the resolved scenario does not read back: " + std::string(e.what())).c_str(),
            resolved, "");
  }
  if (again != resolved) finding("the resolved scenario changes when read back", resolved, again);
}

}  // namespace

// The path the next inputs are read at; "" for the default (replay_main.cpp).
void fuzz_scenario_place(const std::string& path) { g_path = path.empty() ? kDefaultPath : path; }

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  std::string_view all(reinterpret_cast<const char*>(data), size);
  std::vector<std::string> sets;
  std::string_view text = all;
  if (const auto cut = all.find("\n--set\n"); cut != std::string_view::npos) {
    text = all.substr(0, cut);
    std::string_view rest = all.substr(cut + 7);
    while (!rest.empty()) {
      const auto end = rest.find('\n');
      sets.emplace_back(rest.substr(0, end));
      rest = end == std::string_view::npos ? std::string_view() : rest.substr(end + 1);
    }
  }
  try {
    read(text, sets);
  } catch (const InputError&) {
    // The expected answer to bad input.
  }
  return 0;
}
