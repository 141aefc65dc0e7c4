#pragma once
// The checks every numeric flag goes through, as CLI11 validators: they see the text the user
// typed, before any conversion could turn "nan", "1e300" or "-1" into something accepted.
#include <CLI/CLI.hpp>
#include <cstdint>

namespace texsynth::cli {

// A finite number in [low, high], or [low, high) with highOpen: the one rule for float flags.
CLI::Validator finiteIn(double low, double high, bool highOpen = false);

// A whole number in [low, high], written as one (no "1.5", "1e3" or "0x10"): for integer flags.
CLI::Validator integerIn(std::int64_t low, std::int64_t high);

// A plain non-negative integer that fits 64 bits (no sign, no wrap-around): for --seed.
CLI::Validator unsigned64();

}  // namespace texsynth::cli
