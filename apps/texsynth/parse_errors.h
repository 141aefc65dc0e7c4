#pragma once
// The one place where the command-line parser's errors become a line the user can act on: the
// flag or command as typed, what was wrong with it, and the nearest name for a typo, instead of
// CLI11's own wording ("A subcommand is required", "At Most 1 required but received 2").
#include <CLI/CLI.hpp>
#include <string>
#include <vector>

namespace texsynth::cli {

// The message for `error`, raised while `app` parsed `arguments` (argv without the program).
std::string describeParseError(const CLI::ParseError& error, const CLI::App& app,
                               const std::vector<std::string>& arguments);

// The candidate closest to `typed` by edit distance, or "" when none is close enough to be a typo.
std::string nearestName(const std::string& typed, const std::vector<std::string>& candidates);

}  // namespace texsynth::cli
