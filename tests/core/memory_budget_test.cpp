// Up-front memory checks name the parameter and the size, and honour $TEXSYNTH_MEMORY_LIMIT.
#include "texsynth/core/memory_budget.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>

#include "texsynth/core/error.h"

using namespace texsynth;

namespace {

struct ScopedLimit {
  explicit ScopedLimit(const char* value) { ::setenv("TEXSYNTH_MEMORY_LIMIT", value, 1); }
  ~ScopedLimit() { ::unsetenv("TEXSYNTH_MEMORY_LIMIT"); }
};

}  // namespace

TEST(MemoryBudget, KnowsWhatIsAvailable) {
  const double available = availableMemoryBytes();
  EXPECT_GT(available, 1 << 20);
  ScopedLimit limit("3G");
  EXPECT_LE(availableMemoryBytes(), 3.0 * (1 << 30));
  EXPECT_LE(availableMemoryBytes(), available);
}

TEST(MemoryBudget, RefusesNamingTheParameterAndTheSize) {
  ScopedLimit limit("512M");
  EXPECT_NO_THROW(requireMemory(1 << 20, "--size", "a small image"));
  try {
    requireMemory(7.5 * (1 << 30), "--grid", "a field on 13000000 grid nodes");
    FAIL() << "accepted 7.5 GiB under a 512 MiB limit";
  } catch (const ParameterError& e) {
    EXPECT_EQ(e.parameter(), "--grid");
    EXPECT_NE(e.problem().find("7.5 GiB"), std::string::npos) << e.what();
    EXPECT_NE(e.problem().find("13000000 grid nodes"), std::string::npos) << e.what();
  }
}

TEST(MemoryBudget, AbsurdEstimatesAreRefused) {
  EXPECT_THROW(requireMemory(1e300, "--resolution", "a volume"), ParameterError);
  EXPECT_THROW(requireMemory(std::nan(""), "--resolution", "a volume"), ParameterError);
  EXPECT_THROW(requireMemory(INFINITY, "--resolution", "a volume"), ParameterError);
}

TEST(MemoryBudget, FormatsSizes) {
  EXPECT_EQ(formatBytes(512), "512 bytes");
  EXPECT_EQ(formatBytes(1536), "1.5 KiB");
  EXPECT_EQ(formatBytes(7.5 * (1 << 30)), "7.5 GiB");
}
