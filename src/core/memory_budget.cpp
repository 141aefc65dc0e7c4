#include "texsynth/core/memory_budget.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <limits>
#include <string>

#include "texsynth/core/error.h"

namespace texsynth {

namespace {

constexpr double kUnknown = std::numeric_limits<double>::infinity();

// A "Key:   123 kB" line of a /proc file, in bytes.
double procField(const char* file, const std::string& key) {
  std::ifstream in(file);
  std::string line;
  while (std::getline(in, line))
    if (line.rfind(key, 0) == 0) return std::strtod(line.c_str() + key.size(), nullptr) * 1024.0;
  return kUnknown;
}

// A file holding one number ("max" or missing: unlimited).
double numberFile(const char* file) {
  std::ifstream in(file);
  std::string text;
  if (!(in >> text) || text == "max") return kUnknown;
  char* end = nullptr;
  const double value = std::strtod(text.c_str(), &end);
  // cgroup v1 says "no limit" with a huge page-rounded number.
  return end != text.c_str() && value > 0 && value < 1e18 ? value : kUnknown;
}

double cgroupRoom() {
  const double v2 = numberFile("/sys/fs/cgroup/memory.max");
  if (std::isfinite(v2)) return v2 - std::min(v2, numberFile("/sys/fs/cgroup/memory.current"));
  const double v1 = numberFile("/sys/fs/cgroup/memory/memory.limit_in_bytes");
  if (std::isfinite(v1)) return v1 - std::min(v1, numberFile("/sys/fs/cgroup/memory/memory.usage_in_bytes"));
  return kUnknown;
}

// $TEXSYNTH_MEMORY_LIMIT less this process's resident memory.
double userLimitRoom() {
  const char* text = std::getenv("TEXSYNTH_MEMORY_LIMIT");
  if (!text || !*text) return kUnknown;
  char* end = nullptr;
  double limit = std::strtod(text, &end);
  switch (end && *end ? *end : ' ') {
    case 'k':
    case 'K':
      limit *= 1024.0;
      break;
    case 'm':
    case 'M':
      limit *= 1024.0 * 1024.0;
      break;
    case 'g':
    case 'G':
      limit *= 1024.0 * 1024.0 * 1024.0;
      break;
    default:
      break;
  }
  if (!(limit > 0)) return kUnknown;
  const double resident = procField("/proc/self/status", "VmRSS:");
  return std::isfinite(resident) ? std::max(0.0, limit - resident) : limit;
}

}  // namespace

double availableMemoryBytes() {
  return std::min({procField("/proc/meminfo", "MemAvailable:"), cgroupRoom(), userLimitRoom()});
}

std::string formatBytes(double bytes) {
  const char* units[] = {"bytes", "KiB", "MiB", "GiB", "TiB", "PiB"};
  int unit = 0;
  while (bytes >= 1024.0 && unit < 5) bytes /= 1024.0, ++unit;
  char text[64];
  std::snprintf(text, sizeof text, unit == 0 ? "%.0f %s" : "%.1f %s", bytes, units[unit]);
  return text;
}

void requireMemory(double bytes, const std::string& parameter, const std::string& what) {
  const double available = availableMemoryBytes();
  if (std::isfinite(bytes) && bytes <= available) return;
  std::string needs =
      std::isfinite(bytes) && bytes < 1e30 ? "about " + formatBytes(bytes) : "an absurd amount of memory";
  throw ParameterError(parameter, "needs " + needs + " for " + what + ", but only " + formatBytes(available) +
                                      " is available; choose a smaller value");
}

}  // namespace texsynth
