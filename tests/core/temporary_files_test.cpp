// Temporaries of atomic writes: recognizable names, removal of stale ones whose process is gone,
// and removal on a catchable signal.
#include "texsynth/core/temporary_files.h"

#include <gtest/gtest.h>
#include <signal.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <filesystem>

#include "test_support.h"
#include "texsynth/core/atomic_file.h"
#include "texsynth/core/output_batch.h"

using namespace texsynth;
namespace fs = std::filesystem;

namespace {

// A PID that belonged to a process that has exited and been reaped.
pid_t deadPid() {
  pid_t child = ::fork();
  if (child == 0) ::_exit(0);
  ::waitpid(child, nullptr, 0);
  return child;
}

// `temporary`'s name with its PID replaced by `pid`.
std::string withPid(const std::string& temporary, pid_t pid) {
  std::string name = fs::path(temporary).filename().string();
  // Built piecewise: GCC 12 warns falsely (-Wrestrict) on a chain of operator+ starting at a literal.
  std::string own = "-", replacement = "-";
  own.append(std::to_string(::getpid())).append("-");
  replacement.append(std::to_string(pid)).append("-");
  name.replace(name.find(own), own.size(), replacement);
  return (fs::path(temporary).parent_path() / name).string();
}

int countTemporaries(const std::string& dir) {
  int n = 0;
  for (const auto& entry : fs::directory_iterator(dir)) n += isTemporaryName(entry.path().filename().string());
  return n;
}

}  // namespace

TEST(TemporaryFiles, NamesKeepTheExtensionAndAreRecognized) {
  const std::string temp = temporaryPathFor("/some/dir/out.png");
  EXPECT_EQ(fs::path(temp).parent_path(), "/some/dir");
  EXPECT_EQ(fs::path(temp).extension(), ".png");
  EXPECT_TRUE(isTemporaryName(fs::path(temp).filename().string()));
  EXPECT_NE(temp, temporaryPathFor("/some/dir/out.png"));
  EXPECT_FALSE(isTemporaryName("out.png"));
  EXPECT_FALSE(isTemporaryName(".out.tmp123.png"));
}

TEST(TemporaryFiles, StaleOnesFromDeadProcessesAreRemoved) {
  test::TempDir dir;
  const std::string stale = withPid(temporaryPathFor(dir.file("a.png")), deadPid());
  const std::string live = withPid(temporaryPathFor(dir.file("b.png")), ::getppid());
  test::writeBytes(stale, "partial");
  test::writeBytes(live, "being written");
  test::writeBytes(dir.file("keep.png"), "a user's file");
  EXPECT_EQ(removeStaleTemporaries(dir.path()), 1);
  EXPECT_FALSE(fs::exists(stale));
  EXPECT_TRUE(fs::exists(live));
  EXPECT_TRUE(fs::exists(dir.file("keep.png")));
}

TEST(TemporaryFiles, AnAtomicWriteSweepsItsDirectory) {
  test::TempDir dir;
  const std::string stale = withPid(temporaryPathFor(dir.file("old.png")), deadPid());
  test::writeBytes(stale, "left by a killed run");
  writeFileAtomically(dir.file("new.txt"), "x");
  EXPECT_FALSE(fs::exists(stale));
}

TEST(TemporaryFiles, ACatchableSignalRemovesThemAndStillKills) {
  for (int signal : {SIGINT, SIGTERM, SIGHUP}) {
    test::TempDir dir;
    pid_t child = ::fork();
    if (child == 0) {
      removeTemporariesOnSignals();
      writeFileAtomically(dir.file("out.bin"), "x");  // a finished output stays
      writeAtomically(dir.file("big.bin"), [signal](const std::string& temp) {
        test::writeBytes(temp, "half written");
        ::raise(signal);  // the user presses Ctrl-C during the write
      });
      ::_exit(0);  // not reached
    }
    int status = 0;
    ::waitpid(child, &status, 0);
    EXPECT_TRUE(WIFSIGNALED(status) && WTERMSIG(status) == signal) << "signal " << signal;
    EXPECT_EQ(countTemporaries(dir.path()), 0) << "signal " << signal;
    EXPECT_TRUE(fs::exists(dir.file("out.bin")));
    EXPECT_FALSE(fs::exists(dir.file("big.bin")));
  }
}

// A long run stages more temporaries than the signal-safe registry holds, in directories it
// created, beside a scratch directory: a signal removes all of it, and keeps what was there.
TEST(TemporaryFiles, ASignalRemovesEveryStagedFileCreatedDirectoryAndScratch) {
  test::TempDir dir;
  const std::string scratchFile = dir.file("scratch-path.txt");
  test::writeBytes(dir.file("keep.png"), "a user's file");
  pid_t child = ::fork();
  if (child == 0) {
    removeTemporariesOnSignals();
    OutputBatch batch;
    createOutputDirectories(dir.file("frames/deep"));
    for (int frame = 0; frame < 400; ++frame)  // past the 256 registry slots
      writeFileAtomically(dir.file("frames/deep/" + std::to_string(frame) + ".png"), "frame");
    writeFileAtomically(dir.file("keep.png"), "replacement");  // staged beside a kept file
    ScratchDirectory scratch("a video");
    test::writeBytes(scratch.path() + "/0.png", "copy for the encoder");
    writeFileAtomically(scratchFile, scratch.path(), Staging::Immediately);
    ::raise(SIGTERM);
    ::_exit(0);  // not reached
  }
  int status = 0;
  ::waitpid(child, &status, 0);
  EXPECT_TRUE(WIFSIGNALED(status) && WTERMSIG(status) == SIGTERM);
  EXPECT_FALSE(fs::exists(dir.file("frames"))) << "a created directory (or a frame) survived";
  EXPECT_EQ(countTemporaries(dir.path()), 0);
  EXPECT_EQ(readFileBytes(dir.file("keep.png")), "a user's file");
  ASSERT_TRUE(fs::exists(scratchFile));
  EXPECT_FALSE(fs::exists(readFileBytes(scratchFile))) << "the scratch directory survived";
}

// While signals are held, one only waits: the step finishes, then the process dies of it.
TEST(TemporaryFiles, HeldSignalsActWhenReleased) {
  test::TempDir dir;
  pid_t child = ::fork();
  if (child == 0) {
    removeTemporariesOnSignals();
    {
      SignalsHeld held;
      ::raise(SIGTERM);
      test::writeBytes(dir.file("after.txt"), "the held step finished");
    }
    test::writeBytes(dir.file("too-late.txt"), "not reached");
    ::_exit(0);
  }
  int status = 0;
  ::waitpid(child, &status, 0);
  EXPECT_TRUE(WIFSIGNALED(status) && WTERMSIG(status) == SIGTERM);
  EXPECT_TRUE(fs::exists(dir.file("after.txt")));
  EXPECT_FALSE(fs::exists(dir.file("too-late.txt")));
}

TEST(TemporaryFiles, AFileSizeLimitIsAnErrorNotADeath) {
  test::TempDir dir;
  pid_t child = ::fork();
  if (child == 0) {
    removeTemporariesOnSignals();
    rlimit limit{4096, 4096};
    ::setrlimit(RLIMIT_FSIZE, &limit);
    try {
      writeFileAtomically(dir.file("big.bin"), std::string(1 << 16, 'x'));
    } catch (const std::exception&) {
      ::_exit(countTemporaries(dir.path()) == 0 && !fs::exists(dir.file("big.bin")) ? 42 : 1);
    }
    ::_exit(2);
  }
  int status = 0;
  ::waitpid(child, &status, 0);
  ASSERT_TRUE(WIFEXITED(status)) << "killed by signal " << WTERMSIG(status);
  EXPECT_EQ(WEXITSTATUS(status), 42);
}
