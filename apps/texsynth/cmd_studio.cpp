// texsynth studio [MESH] [EXEMPLAR]: the interactive sketch-and-cut interface, served to the
// browser from this machine until Ctrl-C (or SIGTERM): then it stops cleanly and dies of the signal.
#include <malloc.h>
#include <spawn.h>

#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <filesystem>

#include "cli_common.h"
#include "number_checks.h"
#include "texsynth/core/error.h"
#include "texsynth/studio/studio_server.h"

extern char** environ;

namespace texsynth::cli {

namespace {

struct StudioArgs {
  std::string mesh, exemplar, host = "127.0.0.1", webRoot;
  int port = 8080, workers = 2, uploadMiB = 64, keptUploads = 8;
  bool open = false;
};

#ifndef TEXSYNTH_WEB_DIR
#define TEXSYNTH_WEB_DIR "web"
#endif

// The page's folder: the one given (--web-root, else $TEXSYNTH_WEB), which must hold the page, else
// the source tree's web/ if it does; none serves the API alone.
std::string webRoot(const StudioArgs& args) {
  if (!args.webRoot.empty()) return args.webRoot;
  if (const char* env = std::getenv("TEXSYNTH_WEB"); env && *env) return env;
  std::error_code error;
  return std::filesystem::is_regular_file(std::filesystem::path(TEXSYNTH_WEB_DIR) / "index.html", error)
             ? TEXSYNTH_WEB_DIR
             : "";
}

// Opens the page in the desktop's browser, if there is a desktop; the address is printed anyway.
void openBrowser(const std::string& url) {
  pid_t pid;
  const char* argv[] = {"xdg-open", url.c_str(), nullptr};
  if (posix_spawnp(&pid, "xdg-open", nullptr, nullptr, const_cast<char**>(argv), environ) != 0)
    std::fprintf(stderr, "texsynth studio: no xdg-open here; open %s in a browser\n", url.c_str());
}

// After a clean shutdown, dies of the signal that asked for it, as the other commands do: whoever
// started the studio (a shell, a service manager) tells a stop from a failure by it. The library's
// handler, if installed (temporary_files.h), removes any temporaries first.
[[noreturn]] void dieOf(int signal) {
  std::fflush(nullptr);
  sigset_t only;
  sigemptyset(&only);
  sigaddset(&only, signal);
  std::raise(signal);  // pending while blocked in this thread
  pthread_sigmask(SIG_UNBLOCK, &only, nullptr);
  std::_Exit(128 + signal);  // only if the signal is ignored
}

void runStudio(const StudioArgs& args, const GlobalOptions& globals) {
  // Two malloc arenas instead of one per busy thread (the server runs up to 64): with one each,
  // freed buffers stayed spread over them and the process grew by ~50 MiB per minute of a 50-client
  // load test; with two it stays flat (bench/studio.sh).
  mallopt(M_ARENA_MAX, 2);
  studio::StudioOptions options;
  options.host = args.host;
  options.port = args.port;
  options.webRoot = webRoot(args);
  options.workers = args.workers;
  options.limits.meshBytes = std::size_t(args.uploadMiB) << 20;
  options.limits.keptUploads = args.keptUploads;
  options.cacheDirectory = defaultCacheDirectory();
  options.mesh = args.mesh;
  options.exemplar = args.exemplar;
  // Ctrl-C and termination are taken by this thread (sigwait) rather than by a handler: the server's
  // threads, started below, inherit the blocked mask.
  sigset_t stopSignals;
  sigemptyset(&stopSignals);
  sigaddset(&stopSignals, SIGINT);
  sigaddset(&stopSignals, SIGTERM);
  pthread_sigmask(SIG_BLOCK, &stopSignals, nullptr);
  int signal = 0;
  {
    studio::StudioServer server(options);
    const int port = server.start();
    const std::string url =
        "http://" + (args.host == "0.0.0.0" ? std::string("127.0.0.1") : args.host) + ":" + std::to_string(port) + "/";
    if (args.host != "127.0.0.1" && args.host != "localhost" && args.host != "::1")
      std::fprintf(stderr,
                   "texsynth studio: listening on %s: anyone who can reach this address can use the studio (no "
                   "login)\n",
                   args.host.c_str());
    if (globals.json)
      std::printf("{\"url\": \"%s\", \"port\": %d}\n", url.c_str(), port);
    else
      std::printf("texsynth studio: %s  (Ctrl-C to stop)\n", url.c_str());
    std::fflush(stdout);
    if (args.open) openBrowser(url);
    sigwait(&stopSignals, &signal);
    say(globals, "texsynth studio: stopping");
  }  // the server stops: connections close, jobs are cancelled, uploads removed
  dieOf(signal);
}

}  // namespace

Command registerStudioCommand(CLI::App& app, const GlobalOptions& globals) {
  auto* sub = app.add_subcommand(
      "studio",
      "Sketch-guided solid texturing in the browser: pick a mesh and an exemplar, draw curves on the surface or a "
      "cutting plane to design the rotation field (glyphs update after each curve), see a fast preview then the "
      "lazy solid following the field, cut the model open, and export the textured mesh (.glb), the field "
      "(.tsfield), a volume (.vdb) or the sketch (.json) for the command line. Serves on 127.0.0.1 only unless "
      "--host says otherwise; stop with Ctrl-C. The page needs the front-end packages that scripts/install-deps.sh "
      "installs (web/node_modules); the API (docs/studio-api.md) works without them.\n"
      "Example: texsynth studio bunny00 Stone/pink_marble --open");
  auto args = std::make_shared<StudioArgs>();
  sub->add_option("MESH", args->mesh,
                  "Mesh to start with: a name from the catalog (bunny00, elephant, ...) or a mesh file");
  sub->add_option("EXEMPLAR", args->exemplar,
                  "Exemplar to start with: a GIMP pattern name (Stone/pink_marble, pink_marble) or an image file");
  sub->add_option("--port", args->port, "TCP port (0: any free port, printed)")
      ->capture_default_str()
      ->check(integerIn(0, 65535));
  sub->add_option("--host", args->host, "Address to listen on; other than loopback, anyone who reaches it can use it")
      ->capture_default_str();
  sub->add_flag("--open", args->open, "Open the page in the desktop's browser (xdg-open)");
  sub->add_option("--workers", args->workers, "Synthesis jobs that run at once")
      ->capture_default_str()
      ->check(integerIn(1, 16));
  sub->add_option("--max-upload", args->uploadMiB, "Largest mesh upload, in MiB (exemplars: 16)")
      ->capture_default_str()
      ->check(integerIn(1, 1024));
  sub->add_option("--keep-uploads", args->keptUploads,
                  "Uploads of each kind (meshes, exemplars) kept, the most recently used; older ones are forgotten "
                  "with their files (the scene's mesh and exemplar never)")
      ->capture_default_str()
      ->check(integerIn(1, 1000));
  sub->add_option("--web-root", args->webRoot,
                  "Folder with the page, index.html (default: $TEXSYNTH_WEB, else the source tree's web/; without "
                  "either, the API alone)");
  return {sub, [args, &globals] { runStudio(*args, globals); }, {{"mesh", fromFile(args->mesh)}}, ""};
}

}  // namespace texsynth::cli
