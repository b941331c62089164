#pragma once
namespace talus {
inline constexpr const char* version() { return TALUS_VERSION; }
}  // namespace talus
