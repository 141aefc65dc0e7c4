#include "cli_common.h"

#include <unistd.h>

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <type_traits>
#include <vector>

#include "number_checks.h"
#include "texsynth/core/atomic_file.h"
#include "texsynth/core/error.h"
#include "texsynth/image/window_support.h"
#include "texsynth/render/view_up.h"

namespace texsynth::cli {

void addGlobalOptions(CLI::App& app, GlobalOptions& globals) {
  app.add_option("--seed", globals.seed, "Random seed; the same seed gives the same bits for any thread count")
      ->capture_default_str()
      ->check(unsigned64());
  app.add_option("--threads", globals.threads, "Worker threads (0 = all cores)")
      ->capture_default_str()
      ->check(integerIn(0, kMaxThreads));
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

// Splits "a,b,c" on commas.
static std::vector<std::string> splitCommas(const std::string& text) {
  std::vector<std::string> parts;
  std::size_t start = 0;
  while (true) {
    std::size_t comma = text.find(',', start);
    parts.push_back(text.substr(start, comma - start));
    if (comma == std::string::npos) return parts;
    start = comma + 1;
  }
}

template <typename T>
static T parseNumber(const std::string& text, const std::string& flag, const std::string& whole) {
  T value{};
  auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (ec != std::errc() || end != text.data() + text.size() || text.empty())
    throw ParameterError(flag, "'" + whole + "' is not a number or list of numbers");
  if constexpr (std::is_floating_point_v<T>)
    if (!std::isfinite(value)) throw ParameterError(flag, "'" + whole + "' is not finite");
  return value;
}

std::pair<float, float> parseFloatPair(const std::string& text, const std::string& flag) {
  auto parts = splitCommas(text);
  if (parts.size() > 2) throw ParameterError(flag, "'" + text + "': give one value or two separated by a comma");
  float a = parseNumber<float>(parts[0], flag, text);
  return {a, parts.size() == 2 ? parseNumber<float>(parts[1], flag, text) : a};
}

Vec3f parseFloatTriple(const std::string& text, const std::string& flag, bool oneForAll) {
  const auto parts = splitCommas(text);
  if (oneForAll && parts.size() == 1) return Vec3f::Constant(parseNumber<float>(parts[0], flag, text));
  if (parts.size() != 3)
    throw ParameterError(flag,
                         "'" + text + "': give three numbers X,Y,Z" + (oneForAll ? " (or one for all three)" : ""));
  return {parseNumber<float>(parts[0], flag, text), parseNumber<float>(parts[1], flag, text),
          parseNumber<float>(parts[2], flag, text)};
}

Vec3f parseDirection(const std::string& text, const std::string& flag) {
  const Vec3f direction = parseFloatTriple(text, flag, false);
  if (!(direction.norm() > 0)) throw ParameterError(flag, "'" + text + "': the direction must not be zero");
  return direction;
}

Vec3f viewUp(const std::string& upFlag, const Mesh& mesh) {
  return upFlag.empty() ? viewUpDirection(mesh) : Vec3f(parseDirection(upFlag, "--up").stableNormalized());
}

std::pair<int, float> parseAxisPosition(const std::string& text, const std::string& flag, bool openInterval) {
  if (text.size() < 3 || text[1] != '=' || (text[0] != 'x' && text[0] != 'y' && text[0] != 'z'))
    throw ParameterError(flag, "'" + text + "': expected AXIS=POSITION, e.g. z=0.5");
  const float position = parseNumber<float>(text.substr(2), flag, text);
  if (openInterval ? !(position > 0 && position < 1) : !(position >= 0 && position <= 1))
    throw ParameterError(flag, "'" + text + "': position must be in " + (openInterval ? "(0, 1)" : "[0, 1]"));
  return {text[0] - 'x', position};
}

Window parseWindow(const std::string& text, const std::string& flag) {
  auto parts = splitCommas(text);
  if (parts.size() != 4) throw ParameterError(flag, "'" + text + "': expected X,Y,W,H");
  Window w{parseNumber<std::int64_t>(parts[0], flag, text), parseNumber<std::int64_t>(parts[1], flag, text),
           parseNumber<int>(parts[2], flag, text), parseNumber<int>(parts[3], flag, text)};
  if (w.width <= 0 || w.height <= 0 || w.width > 65536 || w.height > 65536)
    throw ParameterError(flag, "'" + text + "': W and H must be between 1 and 65536");
  try {  // the library's one rule for every random-access method, checked before any work
    requireWindow(w.x, w.y, w.width, w.height);
  } catch (const ParameterError& e) {
    throw ParameterError(flag, "'" + text + "': " + e.problem());
  }
  return w;
}

void addTileBlendOptions(CLI::App& sub, float& tileSize, float& blendExponent) {
  sub.add_option("--tile-size", tileSize, "tile-blend: triangle edge in exemplar pixels (0 = half the exemplar)")
      ->capture_default_str()
      ->check(finiteIn(0, 65536));
  sub.add_option("--blend-exponent", blendExponent, "tile-blend: sharpness of the blend between tiles (>= 1)")
      ->capture_default_str()
      ->check(finiteIn(1, 64));
}

void printJson(const nlohmann::json& document) {
  std::cout << document.dump(2) << std::endl;
}

nlohmann::json metricsJson(const QualityMetrics& m) {
  return {{"coherence", m.coherence}, {"coherence_p90", m.coherenceTail}, {"completeness", m.completeness},
          {"histogram", m.histogram}, {"periodicity", m.periodicity},     {"lattice", m.lattice},
          {"sharpness", m.sharpness}};
}

std::string defaultCacheDirectory() {
  namespace fs = std::filesystem;
  const auto variable = [](const char* name) -> std::string {
    const char* value = std::getenv(name);
    return value ? value : "";
  };
  // An empty variable counts as unset; TEXSYNTH_CACHE may be relative (to the working directory),
  // a relative XDG_CACHE_HOME is ignored (XDG Base Directory spec), and so is a relative HOME.
  if (std::string dir = variable("TEXSYNTH_CACHE"); !dir.empty()) {
    std::error_code ec;
    fs::path absolute = fs::absolute(dir, ec);
    return ec ? dir : absolute.lexically_normal().string();
  }
  if (fs::path dir = variable("XDG_CACHE_HOME"); dir.is_absolute()) return (dir / "texsynth").string();
  if (fs::path home = variable("HOME"); home.is_absolute()) return (home / ".cache" / "texsynth").string();
  // Per user, so that one user's directory never blocks another's.
  std::error_code ec;
  fs::path temp = fs::temp_directory_path(ec);
  return ((ec ? fs::path("/tmp") : temp) / ("texsynth-cache-" + std::to_string(geteuid()))).string();
}

namespace {
double processPeak = -1;
}

double takePeakResidentMiB() {
  double peak = -1;
  std::ifstream status("/proc/self/status");
  std::string line;
  while (std::getline(status, line))
    if (line.rfind("VmHWM:", 0) == 0) peak = std::strtod(line.c_str() + 6, nullptr) / 1024.0;  // kB
  std::ofstream("/proc/self/clear_refs") << "5";  // restart the peak from the current use
  processPeak = std::max(processPeak, peak);
  return peak;
}

double processPeakResidentMiB() {
  return processPeak;
}

void say(const GlobalOptions& globals, const std::string& message) {
  if (!globals.quiet) std::fprintf(stderr, "%s\n", message.c_str());
}

namespace {
std::vector<std::function<void()>>& messagesWhenCommitted() {
  static std::vector<std::function<void()>> messages;
  return messages;
}
}  // namespace

void sayWhenCommitted(const GlobalOptions& globals, const std::string& message) {
  if (!globals.quiet) messagesWhenCommitted().push_back([message] { std::fprintf(stderr, "%s\n", message.c_str()); });
}

void printJsonWhenCommitted(const nlohmann::json& document) {
  messagesWhenCommitted().push_back([document] { printJson(document); });
}

void sayCommitted() {
  for (const auto& message : messagesWhenCommitted()) message();
  messagesWhenCommitted().clear();
}

void finishReport(const GlobalOptions& globals, const nlohmann::json& report, const std::string& statsFile,
                  const std::string& summary) {
  if (!statsFile.empty()) writeFileAtomically(statsFile, report.dump(2) + "\n");
  if (globals.json)
    printJsonWhenCommitted(report);
  else
    sayWhenCommitted(globals, summary);
}

}  // namespace texsynth::cli
