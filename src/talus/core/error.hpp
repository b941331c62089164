#pragma once
// Errors carry where they come from, so the command line can map them to exit
// codes: bad input (2) is found before anything runs, a failed run (1) after.
#include <stdexcept>
#include <string>

namespace talus {

// Bad input: the message names the file, line and key when they are known.
class InputError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// A run that went wrong: NaN, energy blow-up, unstable time step.
class RunError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

}  // namespace talus
