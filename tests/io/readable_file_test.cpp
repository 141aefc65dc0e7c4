// Every reader checks that its input is a readable regular file before looking at its type, so
// a missing file or a directory is reported as that and not as an unsupported format.
#include "texsynth/io/readable_file.h"

#include <gtest/gtest.h>
#include <sys/stat.h>

#include "test_support.h"
#include "texsynth/io/image_io.h"
#include "texsynth/io/mesh_io.h"
#include "texsynth/io/volume_io.h"

namespace texsynth {
namespace {
using test::TempDir;

TEST(ReadableFile, MissingFilesDirectoriesAndPipesAreNamedAsSuch) {
  TempDir dir;
  test::writeBytes(dir.file("plain.bin"), "x");
  EXPECT_NO_THROW(requireReadableFile(dir.file("plain.bin")));
  test::expectInputError([&] { requireReadableFile(dir.file("missing.xyz")); }, dir.file("missing.xyz"),
                         "file does not exist");
  test::expectInputError([&] { requireReadableFile(dir.path()); }, dir.path(), "is a directory, not a file");
  ASSERT_EQ(::mkfifo(dir.file("pipe.png").c_str(), 0600), 0);
  test::expectInputError([&] { requireReadableFile(dir.file("pipe.png")); }, dir.file("pipe.png"),
                         "is not a regular file");
}

TEST(ReadableFile, ReadersReportDirectoriesAndMissingFilesBeforeTheFormat) {
  TempDir dir;
  for (const char* name : {"folder.png", "folder.ply", "folder.nrrd"}) {
    ASSERT_EQ(::mkdir(dir.file(name).c_str(), 0700), 0);
  }
  for (const std::string& path : {dir.path(), dir.file("folder.png")})
    test::expectInputError([&] { readImage(path); }, path, "is a directory, not a file");
  for (const std::string& path : {dir.path(), dir.file("folder.ply")})
    test::expectInputError([&] { readMesh(path); }, path, "is a directory, not a file");
  for (const std::string& path : {dir.path(), dir.file("folder.nrrd")})
    test::expectInputError([&] { readVolume(path); }, path, "is a directory, not a file");
  const std::string missing = dir.file("missing.xyz");
  test::expectInputError([&] { readImage(missing); }, missing, "file does not exist");
  test::expectInputError([&] { readMesh(missing); }, missing, "file does not exist");
  test::expectInputError([&] { readVolume(missing); }, missing, "file does not exist");
}

}  // namespace
}  // namespace texsynth
