#pragma once
// Runs that could never finish: a mistyped density, stiffness, duration or
// time step can ask for 10^150 steps. Such a run is refused before it starts
// (and by `talus validate`) unless the user allows it (--allow-long-run).
#include <string>

namespace talus::run {

inline constexpr double kStepLimit = 1e9;

// Throws InputError, naming `file`, when `steps` (NaN: unknown, accepted)
// exceeds kStepLimit and `allowed` is false; `duration` (simulated seconds to
// go) goes into the message.
void check_step_count(const std::string& file, double steps, double duration, bool allowed);

}  // namespace talus::run
