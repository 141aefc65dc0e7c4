// Writes small valid inputs for every fuzz target with the project's own writers, so each
// corpus starts from files the readers accept: make_seeds DIR fills
// DIR/{image,mesh,volume,field,gradient_solid}/.
#include <filesystem>
#include <iostream>

#include "texsynth/field/field_io.h"
#include "texsynth/gradient/gradient_solid_file.h"
#include "texsynth/io/image_io.h"
#include "texsynth/io/mesh_io.h"
#include "texsynth/io/volume_io.h"

namespace {

using namespace texsynth;

// Values that vary along every axis and channel, so no encoder sees a constant.
float ramp(std::size_t i) {
  return float(i * 37 % 101) / 100.0f;
}

void writeImages(const std::string& dir) {
  for (int channels = 1; channels <= 4; ++channels) {
    Image image(5, 3, channels);
    for (std::size_t i = 0; i < image.pixels.size(); ++i) image.pixels[i] = ramp(i);
    std::string stem = dir + "/c" + std::to_string(channels);
    for (const char* extension : {".png", ".jpg", ".bmp", ".tga", ".exr", ".pat"}) writeImage(stem + extension, image);
    writeImage(stem + "-16bit.png", image, {.bitsPerChannel = 16});
  }
}

void writeVolumes(const std::string& dir) {
  for (int channels : {1, 3}) {
    Volume volume(3, 2, 2, channels);
    for (std::size_t i = 0; i < volume.voxels.size(); ++i) volume.voxels[i] = ramp(i);
    for (bool gzip : {false, true})
      for (bool floatSamples : {false, true})
        writeVolume(dir + "/c" + std::to_string(channels) + (gzip ? "-gzip" : "-raw") +
                        (floatSamples ? "-f32" : "-u8") + ".nrrd",
                    volume, {.gzip = gzip, .floatSamples = floatSamples});
  }
}

void writeMeshes(const std::string& dir) {
  Mesh mesh;
  mesh.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
  mesh.triangles = {{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 2, 3}};
  mesh.colors = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {1, 1, 1}};
  writeMesh(dir + "/tetra.ply", mesh);
  writeMesh(dir + "/tetra.obj", mesh);
}

void writeFields(const std::string& dir) {
  FieldGrid grid;
  grid.nodes = {3, 2, 2};
  grid.spacing = 0.5f;
  for (bool hasScale : {false, true}) {
    FieldFile field{RotationField(grid), ScaleField(grid, 2.0f), hasScale};
    writeField(dir + (hasScale ? "/scaled.tsfield" : "/plain.tsfield"), field);
  }
}

// Small solids (2 x 2 x 3 control points) with every combination of regions and detail.
void writeGradientSolids(const std::string& dir) {
  for (bool regions : {false, true})
    for (bool detail : {false, true}) {
      GradientSolid solid = GradientSolid::zeros({3, 2, 6}, 2);
      for (std::size_t i = 0; i < solid.positive.size(); ++i) solid.positive[i] = ramp(i) - 0.2f;
      const auto n = std::size_t(solid.controlCount());
      if (regions) {
        solid.distance.resize(4 * n);
        for (std::size_t i = 0; i < solid.distance.size(); ++i) solid.distance[i] = 4 * ramp(i + 5) - 2;
        solid.negativeIndex.assign(n, -1);
        solid.negativeIndex[1] = 0, solid.negativeIndex[4] = 1;
        solid.negative.resize(2 * std::size_t(solid.setSize()));
        for (std::size_t i = 0; i < solid.negative.size(); ++i) solid.negative[i] = ramp(i + 9);
      }
      if (detail) {
        solid.detail.resize(solid.positive.size());
        for (std::size_t i = 0; i < solid.detail.size(); ++i) solid.detail[i] = 0.1f * ramp(i + 3);
      }
      writeGradientSolid(dir + "/" + (regions ? "regions" : "plain") + (detail ? "-detail" : "") + ".tsgs", solid);
    }
}

}  // namespace

int main(int argc, char** argv) {
  if (argc != 2) {
    std::cerr << "usage: make_seeds DIR\n";
    return 2;
  }
  const std::string root = argv[1];
  for (const char* family : {"image", "mesh", "volume", "field", "gradient_solid"})
    std::filesystem::create_directories(root + "/" + family);
  writeImages(root + "/image");
  writeMeshes(root + "/mesh");
  writeVolumes(root + "/volume");
  writeFields(root + "/field");
  writeGradientSolids(root + "/gradient_solid");
  return 0;
}
