#pragma once
// The built-in methods, each defined in its own file beside this one.
#include "talus/run/method.hpp"

namespace talus::run {

Method dem_method();
Method mpm_method();
Method dan_method();
Method fv2d_method();
Method two_phase_method();

}  // namespace talus::run
