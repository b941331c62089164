#pragma once
// Memory a run may use, checked before anything large is allocated: a
// mistyped cell size or spacing must end in a clear refusal (exit 2) with the
// estimate, not in std::bad_alloc after minutes of swapping.
#include <fmt/core.h>

#include <algorithm>
#include <cstdlib>
#include <fstream>
#include <limits>
#include <string>

#include "talus/core/error.hpp"

namespace talus {

// Bytes this process may allocate: TALUS_MEMORY_LIMIT (GiB) when set, else the
// kernel's MemAvailable and, inside a cgroup (batch jobs, containers), what
// its memory.max leaves; infinity when neither can be read.
inline double memory_limit_bytes(std::string* source = nullptr) {
  constexpr double kGiB = 1024.0 * 1024.0 * 1024.0;
  if (const char* env = std::getenv("TALUS_MEMORY_LIMIT")) {
    char* end = nullptr;
    const double gib = std::strtod(env, &end);
    if (end != env && gib > 0) {
      if (source) *source = "TALUS_MEMORY_LIMIT";
      return gib * kGiB;
    }
  }
  double limit = std::numeric_limits<double>::infinity();
  std::ifstream meminfo("/proc/meminfo");
  for (std::string key; meminfo >> key;) {
    double kib = 0;
    meminfo >> kib;
    meminfo.ignore(std::numeric_limits<std::streamsize>::max(), '\n');
    if (key == "MemAvailable:") {
      limit = kib * 1024.0;
      if (source) *source = "available memory";
      break;
    }
  }
  std::ifstream max("/sys/fs/cgroup/memory.max"), current("/sys/fs/cgroup/memory.current");
  double cap = 0, used = 0;
  if (max >> cap && current >> used && cap - used < limit) {  // "max" (no cap) fails to read
    limit = std::max(0.0, cap - used);
    if (source) *source = "memory left to this cgroup";
  }
  return limit;
}

// Throws InputError when `bytes` exceeds memory_limit_bytes(); `what` says
// what needs it and which keys set its size.
inline void check_memory(double bytes, const std::string& what) {
  std::string source;
  const double limit = memory_limit_bytes(&source);
  if (!(bytes > limit)) return;
  constexpr double kGiB = 1024.0 * 1024.0 * 1024.0;
  throw InputError(fmt::format(
      "{} would need about {:.3g} GiB of memory, more than the {:.3g} GiB of {} (set "
      "TALUS_MEMORY_LIMIT, in GiB, to allow more)",
      what, bytes / kGiB, limit / kGiB, source));
}

}  // namespace talus
