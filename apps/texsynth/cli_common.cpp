#include "cli_common.h"

#include <charconv>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <iostream>

#include "texsynth/core/error.h"

namespace texsynth::cli {

void addGlobalOptions(CLI::App& app, GlobalOptions& globals) {
  app.add_option("--seed", globals.seed, "Random seed; the same seed gives the same bits for any thread count")
      ->capture_default_str();
  app.add_option("--threads", globals.threads, "Worker threads (0 = all cores)")
      ->capture_default_str()
      ->check(CLI::NonNegativeNumber);
  app.add_flag("--quiet,-q", globals.quiet, "No progress bar or messages on stderr");
  app.add_flag("--json", globals.json, "Print machine-readable results as JSON on stdout");
}

std::unique_ptr<Progress> makeProgress(const GlobalOptions& globals) {
  if (globals.quiet || globals.json) return std::make_unique<NullProgress>();
  return std::make_unique<ConsoleProgress>();
}

static int parsePositive(std::string_view text, const std::string& flag, const std::string& whole) {
  int value = 0;
  auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (ec != std::errc() || end != text.data() + text.size() || text.empty())
    throw ParameterError(flag, "'" + whole + "' is not a size; use WxH (e.g. 512x512) or N");
  if (value <= 0 || value > 65536) throw ParameterError(flag, "'" + whole + "': each side must be between 1 and 65536");
  return value;
}

Size2 parseSize(const std::string& text, const std::string& flag) {
  auto x = text.find_first_of("xX");
  if (x == std::string::npos) {
    int n = parsePositive(text, flag, text);
    return {n, n};
  }
  return {parsePositive(std::string_view(text).substr(0, x), flag, text),
          parsePositive(std::string_view(text).substr(x + 1), flag, text)};
}

void printJson(const nlohmann::json& document) {
  std::cout << document.dump(2) << std::endl;
}

std::string defaultCacheDirectory() {
  if (const char* dir = std::getenv("TEXSYNTH_CACHE"); dir && *dir) return dir;
  if (const char* dir = std::getenv("XDG_CACHE_HOME"); dir && *dir) return std::string(dir) + "/texsynth";
  if (const char* home = std::getenv("HOME"); home && *home) return std::string(home) + "/.cache/texsynth";
  return (std::filesystem::temp_directory_path() / "texsynth-cache").string();
}

void say(const GlobalOptions& globals, const std::string& message) {
  if (!globals.quiet) std::fprintf(stderr, "%s\n", message.c_str());
}

}  // namespace texsynth::cli
