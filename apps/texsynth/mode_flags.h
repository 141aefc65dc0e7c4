#pragma once
// Flags that only some modes of a subcommand use (tile-deform's --cell, lazy's --levels ...).
// A flag given in a mode that ignores it is rejected: silently ignoring it would hide a typo or a
// misunderstanding behind a result that looks right.
#include <CLI/CLI.hpp>
#include <string>
#include <vector>

namespace texsynth::cli {

struct ModeFlag {
  std::string flag;                // as CLI11 knows it: "--cell", "-k"
  std::vector<std::string> modes;  // the modes that use it
};

// Throws ParameterError(flag, ...) for the first flag of `table` given on `sub`'s command line
// whose modes do not include `mode`; `modePhrase` says the mode as the user chose it
// ("with --method parallel", "without --render").
void rejectFlagsOutsideMode(const CLI::App& sub, const std::vector<ModeFlag>& table, const std::string& mode,
                            const std::string& modePhrase);

}  // namespace texsynth::cli
