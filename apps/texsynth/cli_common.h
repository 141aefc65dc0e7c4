#pragma once
// Pieces every texsynth subcommand shares: global flags, size parsing, progress, JSON output.
#include <CLI/CLI.hpp>
#include <cstdint>
#include <functional>
#include <memory>
#include <nlohmann/json.hpp>
#include <string>

#include "parameter_sources.h"
#include "texsynth/core/math.h"
#include "texsynth/core/mesh.h"
#include "texsynth/core/progress.h"
#include "texsynth/eval/metrics.h"

namespace texsynth::cli {

// --threads above this is a typo, not a machine.
inline constexpr int kMaxThreads = 1024;

// Flags accepted by every subcommand (before or after the subcommand name).
struct GlobalOptions {
  std::uint64_t seed = 1;
  int threads = 0;  // 0: all hardware threads
  bool quiet = false;
  bool json = false;
};

// A registered subcommand: its CLI11 parser, what to run once parsing succeeded, where its
// library parameters came from, and the flags that drive its memory use ("--size or --window").
struct Command {
  CLI::App* parser = nullptr;
  std::function<void()> run;
  ParameterSources sources;
  std::string memoryFlags;  // empty: no flag drives it
};

// Runs a parsed command so that its errors name what the user typed: a ParameterError on a
// library parameter becomes one on its flag, or an InputError on the file its data came from;
// running out of memory names the flags to lower.
void runCommand(const Command& command);

void addGlobalOptions(CLI::App& app, GlobalOptions& globals);

// A progress bar on stderr, or a silent one with --quiet / --json.
std::unique_ptr<Progress> makeProgress(const GlobalOptions& globals);

// "512x384" or "512" (square). Throws ParameterError naming `flag`.
struct Size2 {
  int width = 0, height = 0;
};
Size2 parseSize(const std::string& text, const std::string& flag);

// "A" or "A,B" (B defaults to A), each a finite number. Throws ParameterError naming `flag`.
std::pair<float, float> parseFloatPair(const std::string& text, const std::string& flag);

// "X,Y,Z" (or, with oneForAll, "V" for all three), each a finite number. Throws ParameterError
// naming `flag` and quoting `text` whole.
Vec3f parseFloatTriple(const std::string& text, const std::string& flag, bool oneForAll);

// "X,Y,Z": three finite numbers, not all zero (only the direction matters). Throws
// ParameterError naming `flag`.
Vec3f parseDirection(const std::string& text, const std::string& flag);

// The up direction of a command's views of `mesh` (RenderOptions::up): --up's direction when
// `upFlag` (its text) is not empty, else the rule of viewUpDirection (render/view_up.h).
Vec3f viewUp(const std::string& upFlag, const Mesh& mesh);

// viewUpDirection's rule in --help's words, and the --up of commands whose --up only turns the views.
inline constexpr const char* kViewUpRule =
    "automatic: the model stands on the face of its bounding box it touches over the widest area (the convex hull of "
    "its vertices within 0.75% of the box diagonal from a floor level or leaning up to 3 degrees), if that covers at "
    "least 10% of the face, else +Y; CGAL's dino comes out +Z up, its pig -Y, the bunny and cow +Y";
inline const std::string kViewUpHelp =
    std::string("X,Y,Z: the model's up direction in the views, which orbit around it (default: ") + kViewUpRule + ")";

// "z=0.5" -> (axis 2, 0.5): a plane across a box, for --slice (position in [0, 1]) and --cut
// (openInterval: in (0, 1)). Throws ParameterError naming `flag`.
std::pair<int, float> parseAxisPosition(const std::string& text, const std::string& flag, bool openInterval);

// "X,Y,W,H": a window of an infinite texture (X, Y may be negative, the window within +-2^28 of
// the origin as every random-access method needs; W, H in 1..65536).
struct Window {
  std::int64_t x = 0, y = 0;
  int width = 0, height = 0;
};
Window parseWindow(const std::string& text, const std::string& flag);

// The tile-blend flags shared by `image` and `solid`: --tile-size and --blend-exponent.
void addTileBlendOptions(CLI::App& sub, float& tileSize, float& blendExponent);

// Prints a JSON document on stdout (for --json).
void printJson(const nlohmann::json& document);

// The quality metrics of `texsynth eval` as JSON (without its timing), for eval's and the demo's reports.
nlohmann::json metricsJson(const QualityMetrics& metrics);

// The one cache directory (exemplar analyses, candidate triples): $TEXSYNTH_CACHE, else
// $XDG_CACHE_HOME/texsynth, else $HOME/.cache/texsynth, else a per-user directory under the
// system temp directory. Empty variables count as unset; relative XDG_CACHE_HOME and HOME are
// ignored.
std::string defaultCacheDirectory();

// Per-request peak memory: the process's peak resident memory (MiB, Linux VmHWM) since the last
// call, after which the peak starts over from the current use (so one request's peak is not
// hidden by an earlier one's); -1 where unknown. Call once before the first request.
// processPeakResidentMiB: the largest peak over all calls so far.
double takePeakResidentMiB();
double processPeakResidentMiB();

// Marks an option (or positional) as naming files the subcommand writes, or reads. Before a run,
// checkFileArguments checks every output destination (its directory exists and is writable),
// that no two outputs are the same file and that no output is one of the inputs, so a typo or a
// slip costs nothing and no input is ever overwritten.
// With `frames`, a value may be a frame pattern (frames/%04d.png): each frame's file, 0 .. *frames - 1,
// is checked as a file of its own (a --flow preset is no file and collides with nothing).
CLI::Option* outputFiles(CLI::Option* option, const int* frames = nullptr);
CLI::Option* inputFiles(CLI::Option* option, const int* frames = nullptr);
void checkFileArguments(const CLI::App& subcommand);

// Short human-readable message on stderr, unless --quiet.
void say(const GlobalOptions& globals, const std::string& message);

// What a run says about its outputs ("wrote ...", its --json report) waits until main has moved
// them all into place: a run that fails or is stopped first never claims to have written a file.
// main calls sayCommitted once the commit succeeded.
void sayWhenCommitted(const GlobalOptions& globals, const std::string& message);
void printJsonWhenCommitted(const nlohmann::json& document);
void sayCommitted();

// A command's result: written to `statsFile` as JSON when one is given, then printed as JSON on stdout with
// --json, else `summary` on stderr, both once the run's outputs are committed.
void finishReport(const GlobalOptions& globals, const nlohmann::json& report, const std::string& statsFile,
                  const std::string& summary);

// The subcommands; each lives in its own cmd_<name>.cpp.
Command registerDemoCommand(CLI::App& app, const GlobalOptions& globals);
Command registerEvalCommand(CLI::App& app, const GlobalOptions& globals);
Command registerRenderCommand(CLI::App& app, const GlobalOptions& globals);
Command registerInfoCommand(CLI::App& app, const GlobalOptions& globals);
Command registerImageCommand(CLI::App& app, const GlobalOptions& globals);
Command registerSolidCommand(CLI::App& app, const GlobalOptions& globals);
Command registerFieldCommand(CLI::App& app, const GlobalOptions& globals);
Command registerVectorizeCommand(CLI::App& app, const GlobalOptions& globals);
Command registerEditCommand(CLI::App& app, const GlobalOptions& globals);
Command registerStudioCommand(CLI::App& app, const GlobalOptions& globals);
Command registerSurfaceCommand(CLI::App& app, const GlobalOptions& globals);
Command registerAnimateCommand(CLI::App& app, const GlobalOptions& globals);

}  // namespace texsynth::cli
