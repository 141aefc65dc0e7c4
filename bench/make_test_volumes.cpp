// Writes the gradient-solid benchmark's synthetic volumes (8-bit NRRD), skipping files that exist:
//   make_test_volumes DIR [SIDE]              DIR/balls.nrrd, DIR/balls_mask.nrrd, DIR/caustics.nrrd
//   make_test_volumes --mask-from VOLUME OUT  OUT: VOLUME's luminance thresholded at its median
//   make_test_volumes --dark-mask-from IMAGE OUT [FRACTION]  OUT: an image mask of IMAGE's darkest FRACTION
//                                                            (default 0.15) of pixels: e.g. brick joints
#include <cstdio>
#include <exception>
#include <filesystem>
#include <string>

#include "test_volumes.h"
#include "texsynth/io/image_io.h"
#include "texsynth/io/volume_io.h"

namespace {

using namespace texsynth;

constexpr std::uint64_t kSeed = 2011;

bool exists(const std::string& path) {
  if (!std::filesystem::exists(path)) return false;
  std::printf("%s exists, kept\n", path.c_str());
  return true;
}

void write(const std::string& path, const Volume& volume) {
  writeVolume(path, volume, VolumeWriteOptions{.gzip = true, .floatSamples = false});
  std::printf("wrote %s\n", path.c_str());
}

int usage() {
  std::fprintf(stderr,
               "usage: make_test_volumes DIR [SIDE=128] | make_test_volumes --mask-from VOLUME OUT | make_test_volumes "
               "--dark-mask-from IMAGE OUT [FRACTION]\n");
  return 2;
}

}  // namespace

int main(int argc, char** argv) {
  try {
    if (argc == 4 && std::string(argv[1]) == "--mask-from") {
      if (!exists(argv[3])) write(argv[3], bench::medianLuminanceMask(readVolume(argv[2])));
      return 0;
    }
    if ((argc == 4 || argc == 5) && std::string(argv[1]) == "--dark-mask-from") {
      const Image image = readImage(argv[2]);
      Image mask(image.width, image.height, 1);
      mask.pixels = bench::luminanceMask(image.pixels, image.channels, argc == 5 ? std::stof(argv[4]) : 0.15f, false);
      writeImage(argv[3], mask);
      std::printf("wrote %s\n", argv[3]);
      return 0;
    }
    if (argc < 2 || argc > 3 || argv[1][0] == '-') return usage();
    const std::string dir = argv[1];
    const int side = argc == 3 ? std::stoi(argv[2]) : 128;
    if (side < 8 || side > 1024) return usage();
    std::filesystem::create_directories(dir);
    if (!exists(dir + "/balls.nrrd") || !exists(dir + "/balls_mask.nrrd")) {
      Volume mask;
      const Volume balls = bench::makeBallsVolume(side, kSeed, mask);
      write(dir + "/balls.nrrd", balls);
      write(dir + "/balls_mask.nrrd", mask);
    }
    if (!exists(dir + "/caustics.nrrd")) write(dir + "/caustics.nrrd", bench::makeCausticsVolume(side, kSeed));
    return 0;
  } catch (const std::exception& error) {
    std::fprintf(stderr, "make_test_volumes: %s\n", error.what());
    return 1;
  }
}
