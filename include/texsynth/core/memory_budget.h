#pragma once
// Up-front memory checks for size-driven work: a request whose estimated footprint cannot fit
// is refused before anything is allocated, with an error naming the parameter that drives the
// size and the memory it would need, instead of growing until the system kills the process.
#include <cstdint>
#include <string>

namespace texsynth {

// Memory this process may still use, in bytes: the least of the system's MemAvailable, the
// cgroup's limit less its usage (containers), and $TEXSYNTH_MEMORY_LIMIT (bytes, or with a
// K/M/G suffix) less what the process already holds. Unknown parts are ignored.
double availableMemoryBytes();

// "1.5 GiB", "312 MiB", "20 KiB".
std::string formatBytes(double bytes);

// Throws ParameterError(parameter, "needs about X for WHAT, only Y is available") if `bytes`
// (an estimate; infinite or NaN counts as too much) exceeds availableMemoryBytes().
void requireMemory(double bytes, const std::string& parameter, const std::string& what);

}  // namespace texsynth
