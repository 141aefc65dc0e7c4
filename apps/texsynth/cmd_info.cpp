// texsynth info FILE: what an image, mesh, volume or rotation-field file holds.
#include <algorithm>
#include <cstdio>

#include "cli_common.h"
#include "texsynth/field/field_io.h"
#include "texsynth/io/file_kind.h"
#include "texsynth/io/image_io.h"
#include "texsynth/io/mesh_io.h"
#include "texsynth/io/volume_io.h"

namespace texsynth::cli {

using nlohmann::json;

// Per-channel minimum, mean and maximum of interleaved float samples.
static json channelStats(const std::vector<float>& values, int channels) {
  json stats = json::array();
  std::size_t count = channels > 0 ? values.size() / channels : 0;
  for (int c = 0; c < channels; ++c) {
    double lo = 1e30, hi = -1e30, sum = 0;
    for (std::size_t i = 0; i < count; ++i) {
      double v = values[i * channels + c];
      lo = std::min(lo, v), hi = std::max(hi, v), sum += v;
    }
    stats.push_back({{"min", lo}, {"mean", count ? sum / count : 0.0}, {"max", hi}});
  }
  return stats;
}

static json describeImage(const std::string& path) {
  ImageFileInfo info = readImageInfo(path);
  Image image = readImage(path);
  return {{"kind", "image"},
          {"format", info.format},
          {"width", image.width},
          {"height", image.height},
          {"channels", image.channels},
          {"bits_per_channel", info.bitsPerChannel},
          {"channel_stats", channelStats(image.pixels, image.channels)}};
}

static json describeMesh(const std::string& path) {
  Mesh mesh = readMesh(path);
  Box3f box = mesh.bounds();
  return {{"kind", "mesh"},
          {"vertices", mesh.vertexCount()},
          {"triangles", mesh.triangleCount()},
          {"bounds_min", {box.min.x(), box.min.y(), box.min.z()}},
          {"bounds_max", {box.max.x(), box.max.y(), box.max.z()}},
          {"surface_area", mesh.surfaceArea()},
          {"has_colors", !mesh.colors.empty()}};
}

static json describeVolume(const std::string& path) {
  Volume volume = readVolume(path);
  return {{"kind", "volume"},
          {"size", {volume.nx, volume.ny, volume.nz}},
          {"channels", volume.channels},
          {"channel_stats", channelStats(volume.voxels, volume.channels)}};
}

static json describeField(const std::string& path) {
  FieldFile field = readField(path);
  const FieldGrid& grid = field.rotations.grid();
  // How far the frames turn from the identity, to tell a designed field from a trivial one.
  double sum = 0, largest = 0;
  for (const Quatf& q : field.rotations.rotations()) {
    const double angle = rotationAngleDegrees(q, Quatf::Identity());
    sum += angle, largest = std::max(largest, angle);
  }
  const auto nodes = double(field.rotations.rotations().size());
  return {{"kind", "rotation field"},
          {"nodes", {grid.nodes.x(), grid.nodes.y(), grid.nodes.z()}},
          {"origin", {grid.origin.x(), grid.origin.y(), grid.origin.z()}},
          {"spacing", grid.spacing},
          {"has_scale", field.hasScale},
          {"rotation_from_identity_degrees", {{"mean", nodes > 0 ? sum / nodes : 0.0}, {"max", largest}}}};
}

static void printHuman(const std::string& path, const json& d) {
  std::printf("%s: %s\n", path.c_str(), d["kind"].get<std::string>().c_str());
  for (auto& [key, value] : d.items())
    if (key != "kind") std::printf("  %-18s %s\n", key.c_str(), value.dump().c_str());
}

Command registerInfoCommand(CLI::App& app, const GlobalOptions& globals) {
  auto* sub = app.add_subcommand("info", "Print what an image, mesh, volume or rotation-field file holds");
  auto path = std::make_shared<std::string>();
  sub->add_option("FILE", *path,
                  "Image (" + readableImageExtensions() + "), mesh (" + readableMeshExtensions() + "), volume (" +
                      readableVolumeExtensions() + ") or rotation field (" + readableFieldExtensions() + ")")
      ->required();
  return {sub,
          [path, &globals] {
            json d;
            switch (fileKind(*path)) {
              case FileKind::Image:
                d = describeImage(*path);
                break;
              case FileKind::Mesh:
                d = describeMesh(*path);
                break;
              case FileKind::Volume:
                d = describeVolume(*path);
                break;
              case FileKind::Field:
                d = describeField(*path);
                break;
              case FileKind::Unknown:
                throw InputError(*path, "unknown file type; texsynth reads images (" + readableImageExtensions() +
                                            "), meshes (" + readableMeshExtensions() + "), volumes (" +
                                            readableVolumeExtensions() + ") and rotation fields (" +
                                            readableFieldExtensions() + ")");
            }
            d["file"] = *path;
            if (globals.json)
              printJson(d);
            else
              printHuman(*path, d);
          },
          {{"mesh", fromFile(*path)}, {"image", fromFile(*path)}, {"volume", fromFile(*path)}},
          ""};
}

}  // namespace texsynth::cli
