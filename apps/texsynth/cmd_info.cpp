// texsynth info FILE: what an image, mesh, volume, rotation-field or gradient-solid file holds.
#include <algorithm>
#include <cstdio>

#include "cli_common.h"
#include "texsynth/field/field_io.h"
#include "texsynth/gradient/gradient_solid_file.h"
#include "texsynth/io/file_kind.h"
#include "texsynth/io/image_io.h"
#include "texsynth/io/mesh_io.h"
#include "texsynth/io/readable_file.h"
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
  json attributes = json::array();  // "uv" says whether `surface --bake` can use the mesh
  for (const auto& entry : mesh.attributes) attributes.push_back(entry.first);
  return {{"kind", "mesh"},
          {"vertices", mesh.vertexCount()},
          {"triangles", mesh.triangleCount()},
          {"bounds_min", {box.min.x(), box.min.y(), box.min.z()}},
          {"bounds_max", {box.max.x(), box.max.y(), box.max.z()}},
          {"surface_area", mesh.surfaceArea()},
          {"has_colors", !mesh.colors.empty()},
          {"has_uvs", mesh.attributes.count(kUvAttribute) > 0},
          {"vertex_attributes", attributes}};
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

// Per channel, the range of the control points' values over both regions' feature sets.
static json valueRanges(const GradientSolid& solid) {
  json ranges = json::array();
  for (int c = 0; c < solid.channels; ++c) {
    double lo = 1e30, hi = -1e30;
    for (const std::vector<float>* sets : {&solid.positive, &solid.negative})
      for (std::size_t i = std::size_t(c); i < sets->size(); i += std::size_t(solid.setSize()))
        lo = std::min(lo, double((*sets)[i])), hi = std::max(hi, double((*sets)[i]));
    ranges.push_back({{"min", lo}, {"max", hi}});
  }
  return ranges;
}

static json describeGradientSolid(const std::string& path) {
  const GradientSolid solid = readGradientSolid(path);
  std::int64_t boundary = 0;
  for (std::int32_t index : solid.negativeIndex) boundary += index >= 0;
  const std::uint64_t fileBytes = gradientSolidFileBytes(solid), rawBytes = rawVolumeBytes(solid);
  return {{"kind", "gradient solid"},
          {"voxels", {solid.voxels.x(), solid.voxels.y(), solid.voxels.z()}},
          {"controls", {solid.controls.x(), solid.controls.y(), solid.controls.z()}},
          {"spacing", solid.spacing},
          {"channels", solid.channels},
          {"regions", solid.hasRegions()},
          {"boundary_controls", boundary},
          {"detail", solid.hasDetail()},
          {"file_bytes", fileBytes},
          {"raw_volume_bytes", rawBytes},
          {"percent_of_raw", 100.0 * double(fileBytes) / double(rawBytes)},
          {"value_ranges", valueRanges(solid)}};
}

static void printHuman(const std::string& path, const json& d) {
  std::printf("%s: %s\n", path.c_str(), d["kind"].get<std::string>().c_str());
  for (auto& [key, value] : d.items())
    if (key != "kind") std::printf("  %-18s %s\n", key.c_str(), value.dump().c_str());
}

Command registerInfoCommand(CLI::App& app, const GlobalOptions& globals) {
  auto* sub =
      app.add_subcommand("info", "Print what an image, mesh, volume, rotation-field or gradient-solid file holds");
  auto path = std::make_shared<std::string>();
  sub->add_option("FILE", *path,
                  "Image (" + readableImageExtensions() + "), mesh (" + readableMeshExtensions() + "), volume (" +
                      readableVolumeExtensions() + "), rotation field (" + readableFieldExtensions() +
                      ") or gradient solid (" + readableGradientSolidExtensions() + ")")
      ->required();
  return {sub,
          [path, &globals] {
            requireReadableFile(*path);  // a missing file or a directory is that, not an unknown type
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
              case FileKind::GradientSolid:
                d = describeGradientSolid(*path);
                break;
              case FileKind::Unknown:
                throw InputError(*path, "unknown file type; texsynth reads images (" + readableImageExtensions() +
                                            "), meshes (" + readableMeshExtensions() + "), volumes (" +
                                            readableVolumeExtensions() + "), rotation fields (" +
                                            readableFieldExtensions() + ") and gradient solids (" +
                                            readableGradientSolidExtensions() + ")");
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
