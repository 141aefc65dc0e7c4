// Outputs a user can trust (issue: all-or-nothing, no litter, memory guards): a run writes all
// of its outputs or none, never replaces a good file when another output fails, leaves no
// temporary behind when it is interrupted, and refuses up front what cannot fit in memory.
#include <gtest/gtest.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <filesystem>

#include "cli_runner.h"
#include "texsynth/core/math.h"
#include "texsynth/core/temporary_files.h"
#include "texsynth/io/image_io.h"
#include "texsynth/io/mesh_io.h"
#include "texsynth/render/primitives.h"

using namespace texsynth;
using test::RunResult;
using test::runTexsynth;
namespace fs = std::filesystem;

namespace {

const char* kSketch = R"({"curves": [{"points": [[0.1, 0.2, 1.0], [0.5, 0.5, 1.0], [0.9, 0.6, 1.0]]}]})";

struct Inputs {
  std::string exemplar, mesh, sketch;
};

Inputs writeInputs(const test::TempDir& dir) {
  Inputs in{dir.file("exemplar.png"), dir.file("cube.ply"), dir.file("sketch.json")};
  writeImage(in.exemplar, test::makeTestPattern(32, 32));
  writeMesh(in.mesh, makeBoxMesh(Vec3f::Zero(), Vec3f::Ones()));
  test::writeBytes(in.sketch, kSketch);
  return in;
}

std::string contents(const std::string& path) {
  return fs::exists(path) ? readFileBytes(path) : "<missing>";
}

// Files in `dir` other than the test's inputs and the runner's own captures.
std::vector<std::string> leftovers(const test::TempDir& dir, const std::vector<std::string>& expected) {
  std::vector<std::string> extra;
  for (const auto& entry : fs::directory_iterator(dir.path())) {
    const std::string name = entry.path().filename().string();
    if (name == "stdout.txt" || name == "stderr.txt" || name == "cache") continue;
    if (std::find(expected.begin(), expected.end(), name) == expected.end()) extra.push_back(name);
  }
  return extra;
}

// `good` holds a sentinel before the run; the run must fail with exit 1 or 2 and leave it as it was.
void expectUntouched(const RunResult& r, const std::string& good, const std::string& sentinel) {
  EXPECT_TRUE(r.exitCode == 1 || r.exitCode == 2) << r.exitCode << " " << r.err;
  EXPECT_EQ(test::lineCount(r.err), 1) << r.err;
  EXPECT_EQ(contents(good), sentinel) << "a failed run replaced " << good;
}

}  // namespace

// Class 1: a bad destination anywhere in the run, found before any work.
TEST(ReliabilityOutputs, ABadLaterDestinationKeepsEarlierOutputs) {
  test::TempDir dir;
  const Inputs in = writeInputs(dir);
  const std::string good = dir.file("good.png"), mesh = dir.file("good.ply");
  const std::vector<std::string> runs = {
      "solid " + in.exemplar + " --slice z=0.5 -o " + good + " --volume " + dir.file("nodir/x.nrrd") +
          " --resolution 8",
      "solid " + in.exemplar + " --slice z=0.5 -o " + good + " --resolution 8 --stats " + dir.file("nodir/s.json"),
      "solid " + in.exemplar + " --mesh " + in.mesh + " -o " + good + " --slice z=0.5 --resolution 8 --render " +
          dir.file("nodir/r.png") + " --render-size 32 --views 1",
      "solid " + in.exemplar + " --mesh " + in.mesh + " -o " + mesh + " --volume " + dir.file("nodir/v.nrrd") +
          " --resolution 8",
      "field " + in.mesh + " --sketch " + in.sketch + " -o " + dir.file("good.tsfield") + " --grid 4 --render " +
          dir.file("nodir/r.png"),
  };
  for (const std::string& args : runs) {
    for (const std::string& file : {good, mesh, dir.file("good.tsfield")}) test::writeBytes(file, "sentinel");
    const RunResult r = runTexsynth(args, dir);
    expectUntouched(r, good, "sentinel");
    expectUntouched(r, mesh, "sentinel");
    expectUntouched(r, dir.file("good.tsfield"), "sentinel");
    EXPECT_NE(r.err.find("nodir"), std::string::npos) << r.err;
  }
}

// Class 1: an output that fails while being written (here: past the file-size limit) after an
// earlier one was finished; the earlier one must not replace the good file, and nothing is left.
TEST(ReliabilityOutputs, AWriteThatFailsLateKeepsEveryGoodFile) {
  test::TempDir dir;
  const Inputs in = writeInputs(dir);
  const std::string good = dir.file("good.png"), volume = dir.file("v.nrrd");
  test::writeBytes(good, "sentinel");
  const RunResult r = runTexsynth(
      "solid " + in.exemplar + " --slice z=0.5 -o " + good + " --resolution 48 --volume " + volume + " --float-volume",
      // 200 blocks of 512 bytes: the slice fits, the volume does not.
      dir, "sh -c 'ulimit -f 200; exec \"$0\" \"$@\"'");
  expectUntouched(r, good, "sentinel");
  EXPECT_EQ(r.exitCode, 1) << r.err;
  EXPECT_NE(r.err.find("v.nrrd"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(volume));
  EXPECT_EQ(leftovers(dir, {"exemplar.png", "cube.ply", "sketch.json", "good.png"}), std::vector<std::string>{});
}

TEST(ReliabilityOutputs, TheSameFileTwiceOrAnInputAsOutputIsRefused) {
  test::TempDir dir;
  const Inputs in = writeInputs(dir);
  const std::string exemplarBytes = contents(in.exemplar);
  RunResult r = runTexsynth("image " + in.exemplar + " --size 16 -o " + in.exemplar, dir);
  test::expectOneLineError(r, 2, "--output");
  EXPECT_TRUE(contents(in.exemplar) == exemplarBytes) << "the input was overwritten";
  r = runTexsynth("solid " + in.exemplar + " --slice z=0.5 --slice x=0.5 -o " + dir.file("a.png") + " -o " +
                      dir.file("./a.png") + " --resolution 8",
                  dir);
  test::expectOneLineError(r, 2, "written twice");
  r = runTexsynth("solid " + in.exemplar + " --mesh " + in.mesh + " -o " + in.mesh, dir);
  test::expectOneLineError(r, 2, "is also an input");
  r = runTexsynth("eval " + in.exemplar + " " + in.exemplar, dir);  // two inputs may be the same file
  EXPECT_EQ(r.exitCode, 0) << r.err;
  fs::create_symlink(in.exemplar, dir.file("link.png"));
  r = runTexsynth("image " + dir.file("link.png") + " --size 16 -o " + in.exemplar, dir);
  test::expectOneLineError(r, 2, "is also an input");
  EXPECT_TRUE(contents(in.exemplar) == exemplarBytes) << "the input was overwritten";
}

// Class 2: interrupted runs leave no temporary files; stale ones from killed runs are swept.
// The signal arrives while the output is being written: the test waits for the temporary to
// appear (a hidden file beside the output) before sending it.
TEST(ReliabilityOutputs, AnInterruptedWriteLeavesNoTemporary) {
  test::TempDir dir;
  const Inputs in = writeInputs(dir);
  for (int signal : {SIGINT, SIGTERM, SIGHUP}) {
    const std::string output = dir.file("big.exr");
    const pid_t child = ::fork();
    if (child == 0) {
      ::freopen("/dev/null", "w", stderr);
      ::execl(TEXSYNTH_BINARY, "texsynth", "image", in.exemplar.c_str(), "--method", "tile-deform", "--size", "6000",
              "-o", output.c_str(), "--quiet", static_cast<char*>(nullptr));
      ::_exit(127);
    }
    bool interrupted = false;
    for (int wait = 0; wait < 60000 && !interrupted; ++wait) {  // at most a minute
      for (const auto& entry : fs::directory_iterator(dir.path()))
        if (entry.path().filename().string()[0] == '.' && !interrupted) interrupted = ::kill(child, signal) == 0;
      if (::waitpid(child, nullptr, WNOHANG) == child) break;
      ::usleep(1000);
    }
    int status = 0;
    if (interrupted) ::waitpid(child, &status, 0);
    EXPECT_TRUE(interrupted) << "the write finished before it could be interrupted";
    EXPECT_TRUE(WIFSIGNALED(status) && WTERMSIG(status) == signal) << "signal " << signal;
    EXPECT_EQ(leftovers(dir, {"exemplar.png", "cube.ply", "sketch.json"}), std::vector<std::string>{})
        << "signal " << signal;
  }
}

TEST(ReliabilityOutputs, StaleTemporariesOfKilledRunsAreRemoved) {
  test::TempDir dir;
  const Inputs in = writeInputs(dir);
  // What SIGKILL leaves: a partial temporary whose process is gone (PID 2^22 + 1 is beyond
  // Linux's default pid_max of 2^22, so no process has it).
  std::string stale = fs::path(temporaryPathFor(dir.file("out.png"))).filename().string();
  const std::string own = std::to_string(::getpid());
  stale.replace(stale.find("-" + own + "-"), own.size() + 2, "-4194305-");
  test::writeBytes(dir.file(stale), "partial");
  const RunResult r = runTexsynth("image " + in.exemplar + " --size 16 -o " + dir.file("out.png"), dir);
  EXPECT_EQ(r.exitCode, 0) << r.err;
  EXPECT_FALSE(fs::exists(dir.file(stale)));
}

// Class 7: the demo that fails leaves no half-filled directory.
TEST(ReliabilityOutputs, AFailedDemoLeavesNoDirectory) {
  test::TempDir dir;
  const Inputs in = writeInputs(dir);
  test::writeBytes(dir.file("broken.off"), "OFF\n3 1 0\n0 0 0\n1 0 0\n");
  const RunResult r = runTexsynth("demo -o " + dir.file("report/deeper") + " --exemplar " + in.exemplar + " --mesh " +
                                      dir.file("broken.off") + " --render-size 32",
                                  dir);
  EXPECT_EQ(r.exitCode, 1) << r.err;
  EXPECT_FALSE(fs::exists(dir.file("report"))) << "the demo left a directory behind";
}

// Class 3: sizes that cannot fit are refused before anything is allocated, naming the flag.
TEST(ReliabilityOutputs, MemoryGuardsNameTheFlagAndTheSize) {
  test::TempDir dir;
  const Inputs in = writeInputs(dir);
  const std::string limit = "TEXSYNTH_MEMORY_LIMIT=256M";
  struct Case {
    std::string args, flag;
  };
  const std::vector<Case> cases = {
      {"field " + in.mesh + " --sketch " + in.sketch + " -o " + dir.file("f.tsfield") + " --grid 200", "--grid"},
      {"image " + in.exemplar + " --size 30000 -o " + dir.file("i.png"), "--size"},
      {"image " + in.exemplar + " --window 0,0,40000,40000 -o " + dir.file("i.png"), "--window"},
      {"solid " + in.exemplar + " --volume " + dir.file("v.nrrd") + " --resolution 2000", "--resolution"},
      {"solid " + in.exemplar + " --mesh " + in.mesh + " --render " + dir.file("r.png") + " --render-size 8000",
       "--render-size"},
      {"render " + in.mesh + " -o " + dir.file("r.png") + " --size 16000", "--size"},
  };
  for (const Case& c : cases) {
    const RunResult r = runTexsynth(c.args, dir, limit);
    test::expectOneLineError(r, 2, c.flag);
    EXPECT_NE(r.err.find("needs about"), std::string::npos) << r.err;
    EXPECT_NE(r.err.find("available"), std::string::npos) << r.err;
  }
}
