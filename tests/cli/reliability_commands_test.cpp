// Reliability of the commands added since the first reliability pass (animate, surface, edit,
// vectorize) and of the parser's words: an interrupted animation leaves no folder, scratch or
// partial file; frame patterns never overwrite an input or each other; "wrote" is said only
// once the outputs are in place; preset values, flow scales and level counts are checked before
// any work; every parser error names what the user typed.
#include <gtest/gtest.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <filesystem>
#include <functional>
#include <thread>

#include "cli_runner.h"
#include "texsynth/io/image_io.h"
#include "texsynth/io/mesh_io.h"
#include "texsynth/render/primitives.h"

using namespace texsynth;
using test::RunResult;
using test::runTexsynth;
namespace fs = std::filesystem;

namespace {

struct Inputs {
  test::TempDir dir;
  std::string exemplar = dir.file("ex0001.png"), cube = dir.file("cube.ply");
  Inputs() {
    writeImage(exemplar, test::makeTestPattern(32, 32));
    writeMesh(cube, makeBoxMesh(Vec3f::Zero(), Vec3f::Ones()));
  }
  RunResult run(const std::string& arguments, const std::string& environment = "") const {
    return runTexsynth(arguments + " --quiet", dir, environment);
  }
};

bool hasVideoEncoder() {
  return std::system("command -v ffmpeg >/dev/null 2>&1") == 0;
}

// The names in `directory`, hidden ones included.
std::vector<std::string> entries(const std::string& directory) {
  std::vector<std::string> found;
  std::error_code ec;
  for (fs::directory_iterator it(directory, ec), end; !ec && it != end; it.increment(ec))
    found.push_back(it->path().filename().string());
  std::sort(found.begin(), found.end());
  return found;
}

std::size_t fileCount(const std::string& directory) {
  std::size_t count = 0;
  std::error_code ec;
  for (fs::recursive_directory_iterator it(directory, ec), end; !ec && it != end; it.increment(ec))
    count += it->is_regular_file(ec);
  return count;
}

// Starts texsynth with `arguments` in the background (its temp directory `tmp`), waits until
// `ready` holds, sends `signal`, and returns how the process ended.
int interruptWhen(const std::string& arguments, const Inputs& in, const std::string& tmp, int signal,
                  const std::function<bool()>& ready) {
  const std::string command = "exec env TEXSYNTH_CACHE=" + in.dir.file("cache") + " TMPDIR=" + tmp + " " +
                              TEXSYNTH_BINARY + " " + arguments + " --quiet >/dev/null 2>" + in.dir.file("err.txt");
  const pid_t pid = ::fork();
  if (pid == 0) {
    ::signal(SIGINT, SIG_DFL);
    ::execl("/bin/sh", "sh", "-c", command.c_str(), static_cast<char*>(nullptr));
    ::_exit(127);
  }
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(60);
  int status = 0;
  while (!ready() && std::chrono::steady_clock::now() < deadline) {
    if (::waitpid(pid, &status, WNOHANG) == pid) return status;  // finished before the signal: a failure below
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  }
  ::kill(pid, signal);
  ::waitpid(pid, &status, 0);
  return status;
}

}  // namespace

// Class 1: SIGINT or SIGTERM during an animation leaves no output folder, no scratch folder of
// the video's frames and no partial file, in 2D and on a mesh, with numbered frames and a video.
TEST(ReliabilityCommands, AnInterruptedAnimationLeavesNothingBehind) {
  Inputs in;
  const std::string video = hasVideoEncoder() ? " -o " + in.dir.file("anim.gif") : "";
  struct Case {
    std::string arguments;
    int signal;
  };
  const std::vector<Case> cases = {
      {"animate " + in.exemplar + " --flow vortex --size 64 --frames 100000 -o " + in.dir.file("big/%04d.png") + video,
       SIGINT},
      {"animate " + in.exemplar + " --mesh " + in.cube + " --vertices 600 --levels 1 --render-size 32 --flow swirl " +
           "--frames 100000 -o " + in.dir.file("frames/%04d.png") + " -o " + in.dir.file("colors/%04d.ply") + video,
       SIGTERM},
  };
  for (const Case& c : cases) {
    SCOPED_TRACE(c.arguments);
    const std::string tmp = in.dir.file("tmp");
    fs::create_directories(tmp);
    // A few frames staged (hidden temporaries in the output folder) and copied for the video.
    const std::string outputs = in.dir.file(c.signal == SIGINT ? "big" : "colors");
    const int status = interruptWhen(c.arguments, in, tmp, c.signal,
                                     [&] { return fileCount(outputs) >= 3 && (video.empty() || fileCount(tmp) >= 3); });
    ASSERT_TRUE(WIFSIGNALED(status)) << "exit " << WEXITSTATUS(status) << ": " << readFileBytes(in.dir.file("err.txt"));
    EXPECT_EQ(WTERMSIG(status), c.signal);
    EXPECT_EQ(entries(tmp), std::vector<std::string>{}) << "scratch left in the temp directory";
    EXPECT_EQ(entries(in.dir.path()), (std::vector<std::string>{"cache", "cube.ply", "err.txt", "ex0001.png", "tmp"}));
    fs::remove_all(in.dir.file("cache"));
  }
}

// Class 2: a frame pattern is checked frame by frame against the inputs and the other outputs.
TEST(ReliabilityCommands, FramePatternsNeverOverwriteInputsOrEachOther) {
  Inputs in;
  const std::string exemplarBytes = readFileBytes(in.exemplar);
  const std::string animate = "animate " + in.exemplar + " --size 16 --frames 3 ";
  RunResult r = in.run(animate + "--flow vortex -o " + in.dir.file("ex%04d.png"));
  test::expectOneLineError(r, 2, "is also an input");
  EXPECT_EQ(readFileBytes(in.exemplar), exemplarBytes);

  fs::create_directories(in.dir.file("flow"));
  for (int t = 0; t < 2; ++t) writeImage(in.dir.file("flow/000" + std::to_string(t) + ".png"), Image(16, 16, 3, 0.5f));
  const std::string flowBytes = readFileBytes(in.dir.file("flow/0000.png"));
  r = in.run(animate + "--flow " + in.dir.file("flow/%04d.png") + " -o " + in.dir.file("flow/%04d.png"));
  test::expectOneLineError(r, 2, "is also an input (--flow");
  EXPECT_EQ(readFileBytes(in.dir.file("flow/0000.png")), flowBytes);

  r = in.run(animate + "--flow vortex -o " + in.dir.file("a/%04d.png") + " -o " + in.dir.file("a/%04d.png"));
  test::expectOneLineError(r, 2, "--output");
  r = in.run(animate + "--flow vortex -o " + in.dir.file("a/%d.png") + " -o " + in.dir.file("a/%01d.png"));
  test::expectOneLineError(r, 2, "both write");
  EXPECT_FALSE(fs::exists(in.dir.file("a")));
  // Distinct patterns in one folder are fine.
  r = in.run(animate + "--flow vortex -o " + in.dir.file("a/%04d.png") + " -o " + in.dir.file("a/b%04d.png"));
  EXPECT_EQ(r.exitCode, 0) << r.err;
}

// Class 5: "wrote" (and the --json report) come only after the commit; when the commit fails
// nothing is said to be written, and nothing is.
TEST(ReliabilityCommands, WroteIsSaidOnlyOnceTheOutputsAreInPlace) {
  Inputs in;
  const std::string volume = in.dir.file("v.nrrd"), solid = in.dir.file("s.tsgs"), strokes = in.dir.file("k.json");
  ASSERT_EQ(in.run("solid " + in.exemplar + " -o " + volume + " --resolution 12").exitCode, 0);
  ASSERT_EQ(in.run("vectorize " + volume + " -o " + solid).exitCode, 0);
  test::writeBytes(strokes, R"({"color": [1, 0, 0], "strokes": [{"points": [[2, 2, 2], [6, 6, 6]]}]})");
  const std::string failing = std::string("LD_PRELOAD=") + TEXSYNTH_FAIL_RENAME + " TEXSYNTH_TEST_FAIL_RENAME=";
  struct Case {
    std::string arguments, target;
  };
  const std::vector<Case> cases = {
      {"surface " + in.exemplar + " --mesh " + in.cube + " --vertices 600 --levels 1 -o " + in.dir.file("a.ply") +
           " --stats " + in.dir.file("a.json"),
       "a.ply"},
      {"edit " + solid + " --strokes " + strokes + " -o " + in.dir.file("e.tsgs") + " --stats " + in.dir.file("e.json"),
       "e.tsgs"},
      {"vectorize " + volume + " -o " + in.dir.file("w.tsgs") + " --stats " + in.dir.file("w.json"), "w.tsgs"},
      {"solid " + in.exemplar + " --slice z=0.5 -o " + in.dir.file("l.png") + " --resolution 8 --stats " +
           in.dir.file("l.json"),
       "l.png"},
  };
  for (const Case& c : cases)
    for (const char* json : {"", " --json"}) {
      SCOPED_TRACE(c.arguments + json);
      const RunResult r = runTexsynth(c.arguments + json, in.dir, failing + c.target);
      test::expectOneLineError(r, 1, c.target);
      EXPECT_EQ(r.err.find("wrote"), std::string::npos) << r.err;
      EXPECT_EQ(r.out, "");
      const std::string stats = c.target.substr(0, 1) + ".json";
      EXPECT_FALSE(fs::exists(in.dir.file(c.target)));
      EXPECT_FALSE(fs::exists(in.dir.file(stats))) << "one output of a failed run was written";
      // The same run without the failure says what it wrote.
      const RunResult ok = runTexsynth(c.arguments, in.dir);
      EXPECT_EQ(ok.exitCode, 0) << ok.err;
      EXPECT_TRUE(fs::exists(in.dir.file(c.target)));
      fs::remove(in.dir.file(c.target));
      fs::remove(in.dir.file(stats));
    }
}

// Class 7: values no one should get away with are refused as typed, before any work.
TEST(ReliabilityCommands, FlowValuesAreCheckedAsTyped) {
  Inputs in;
  const std::string animate = "animate " + in.exemplar + " --size 16 --frames 2 -o " + in.dir.file("f/%04d.png") + " ";
  test::expectOneLineError(in.run(animate + "--flow vortex --fps nan"), 2, "--fps");
  test::expectOneLineError(in.run(animate + "--flow vortex --flow-scale 1e30"), 2, "--flow-scale");
  test::expectOneLineError(in.run(animate + "--flow vortex --flow-scale -1e308"), 2, "--flow-scale");
  test::expectOneLineError(in.run(animate + "--flow saddle:strength=1e30"), 2, "--flow");
  test::expectOneLineError(in.run(animate + "--flow uniform:dx=nan"), 2, "--flow");
  test::expectOneLineError(in.run(animate + "--flow swirl:seed=-1"), 2, "--flow");
  test::expectOneLineError(in.run(animate + "--flow vortex --coherence 1e30"), 2, "--coherence");
  EXPECT_FALSE(fs::exists(in.dir.file("cache"))) << "refused after work had started";
  // A velocity file far out of range is the file's problem.
  Image fast(16, 16, 3, 1e9f);
  writeImage(in.dir.file("fast.exr"), fast);
  test::expectOneLineError(in.run(animate + "--flow " + in.dir.file("fast.exr")), 1, "fast.exr");
}

// Classes 8 and 10: level counts blame what was typed, and are refused before the mesh is read or
// the exemplar analysed.
TEST(ReliabilityCommands, LevelsAndVerticesAreCheckedBeforeAnyWork) {
  Inputs in;
  const std::string surface = "surface " + in.exemplar + " --mesh " + in.cube + " -o " + in.dir.file("s.ply") + " ";
  RunResult r = in.run(surface + "--vertices 200");
  test::expectOneLineError(r, 2, "--vertices");
  EXPECT_EQ(r.err.find("--levels"), std::string::npos) << r.err;
  r = in.run(surface + "--levels 6");
  test::expectOneLineError(r, 2, "--levels");
  r = in.run(surface + "--levels 3 --vertices 300");
  test::expectOneLineError(r, 2, "--vertices");
  EXPECT_FALSE(fs::exists(in.dir.file("cache"))) << "refused after the analysis";
}

// Class 8: the parser's errors in the user's words.
TEST(ReliabilityCommands, ParserErrorsNameWhatWasTyped) {
  Inputs in;
  RunResult r = in.run("surfac");
  test::expectOneLineError(r, 2, "unknown command 'surfac'; did you mean 'surface'?");
  r = in.run("image " + in.exemplar + " --sze 8 -o " + in.dir.file("a.png"));
  test::expectOneLineError(r, 2, "did you mean '--size'?");
  r = in.run("image " + in.exemplar + " --method optimise -o " + in.dir.file("a.png"));
  test::expectOneLineError(r, 2, "--method: 'optimise' is not one of");
  EXPECT_NE(r.err.find("did you mean 'optimize'?"), std::string::npos) << r.err;
  r = runTexsynth("image " + in.exemplar + " -o " + in.dir.file("a.png") + " --threads", in.dir);  // last: no value
  test::expectOneLineError(r, 2, "--threads needs a value");
  r = in.run("image " + in.exemplar + " -o " + in.dir.file("a.png") + " -o " + in.dir.file("b.png"));
  test::expectOneLineError(r, 2, "--output takes one value");
  r = in.run("animate " + in.exemplar + " --flow vortex --fps 0 -o " + in.dir.file("f/%04d.png"));
  test::expectOneLineError(r, 2, "--fps");
  for (const char* raw : {"At Most", "required but received", "not in range", "A subcommand"})
    EXPECT_EQ(r.err.find(raw), std::string::npos) << r.err;
  r = in.run("");
  test::expectOneLineError(r, 2, "give a command");
}

// Class 8: a colour, and the gradient synthesis's exemplar and mask counts, as typed.
TEST(ReliabilityCommands, ColoursAndExemplarCountsNameTheFlag) {
  Inputs in;
  const std::string volume = in.dir.file("v.nrrd"), solid = in.dir.file("s.tsgs"), strokes = in.dir.file("k.json");
  ASSERT_EQ(in.run("solid " + in.exemplar + " -o " + volume + " --resolution 12").exitCode, 0);
  ASSERT_EQ(in.run("vectorize " + volume + " -o " + solid).exitCode, 0);
  test::writeBytes(strokes, R"({"strokes": [{"points": [[2, 2, 2]]}]})");
  RunResult r = in.run("edit " + solid + " --strokes " + strokes + " --color nan,0,0 -o " + in.dir.file("e.tsgs"));
  test::expectOneLineError(r, 2, "'nan,0,0'");
  const std::string gradient = " --method gradient --slice z=0.5 -o " + in.dir.file("g.png") + " --resolution 8";
  r = in.run("solid " + in.exemplar + " " + in.exemplar + gradient);
  test::expectOneLineError(r, 2, "EXEMPLAR");
  writeImage(in.dir.file("m.png"), Image(8, 8, 1, 1.0f));
  r = in.run("solid " + in.exemplar + gradient + " --mask " + in.dir.file("m.png") + " --mask " + in.dir.file("m.png"));
  test::expectOneLineError(r, 2, "--mask");
  r = in.run("solid " + in.exemplar + gradient + " --mask " + in.dir.file("m.png"));
  test::expectOneLineError(r, 1, "m.png");
  for (const char* internal : {"masks:", "exemplars:", "maskCount", "exemplarCount"})
    EXPECT_EQ(r.err.find(internal), std::string::npos) << r.err;
}
