#include "animate_outputs.h"

#include <chrono>
#include <filesystem>

#include "texsynth/core/atomic_file.h"
#include "texsynth/core/error.h"
#include "texsynth/core/output_batch.h"
#include "texsynth/core/temporary_files.h"
#include "texsynth/core/timing.h"
#include "texsynth/io/file_kind.h"
#include "texsynth/io/image_io.h"
#include "texsynth/io/mesh_io.h"
#include "texsynth/io/video_io.h"

namespace texsynth::cli {
namespace {

void createParentDirectory(const std::string& path) {
  const std::filesystem::path parent = std::filesystem::path(path).parent_path();
  if (!parent.empty() && !std::filesystem::exists(parent)) createOutputDirectories(parent.string());
}

}  // namespace

FrameOutputs::FrameOutputs(const std::vector<std::string>& outputs, bool meshFrames, double fps) : fps_(fps) {
  for (const std::string& out : outputs) {
    if (isVideoFile(out)) {
      requireVideoEncoder(out);
      videos_.push_back(out);
      continue;
    }
    FramePattern pattern(out, "--output");
    const FileKind kind = fileKind(out);
    if (kind != FileKind::Image && !(meshFrames && kind == FileKind::Mesh))
      throw ParameterError("--output", "'" + out + "': write frames as images (" + readableImageExtensions() + ")" +
                                           (meshFrames ? ", vertex-colored meshes (.ply .obj .glb)" : "") +
                                           " or a video (.mp4 .webm .gif)");
    if (!pattern.numbered())
      throw ParameterError("--output", "'" + out + "' has no frame number: give a pattern such as frames/%04d." +
                                           fileExtension(out) + " (or a video: .mp4 .webm .gif)");
    (kind == FileKind::Image ? pictures_ : meshes_).push_back(std::move(pattern));
  }
  if (outputs.empty()) throw ParameterError("--output", "nothing to write: give -o frames/%04d.png and/or -o anim.mp4");
  if (!videos_.empty()) videoFrames_ = std::make_unique<ScratchDirectory>(videos_.front());
}

FrameOutputs::~FrameOutputs() = default;

void FrameOutputs::addPicture(int frame, const Image& picture) {
  const auto start = std::chrono::steady_clock::now();
  for (const FramePattern& pattern : pictures_) {
    const std::string path = pattern.path(frame);
    createParentDirectory(path);
    writeImage(path, picture);
  }
  if (!videos_.empty()) {
    videoFramePaths_.push_back(videoFrames_->path() + "/" + std::to_string(frame) + ".png");
    ImageWriteOptions scratch;
    scratch.staging = Staging::Immediately;  // the encoder reads them before the run commits
    writeImage(videoFramePaths_.back(), picture, scratch);
  }
  frames_ = std::max(frames_, frame + 1);
  writeSeconds_ += secondsSince(start);
}

void FrameOutputs::addMesh(int frame, const Mesh& colored) {
  const auto start = std::chrono::steady_clock::now();
  for (const FramePattern& pattern : meshes_) {
    const std::string path = pattern.path(frame);
    createParentDirectory(path);
    writeMesh(path, colored);
  }
  frames_ = std::max(frames_, frame + 1);
  writeSeconds_ += secondsSince(start);
}

nlohmann::json FrameOutputs::finish() {
  nlohmann::json report = nlohmann::json::array();
  for (const auto* patterns : {&pictures_, &meshes_})
    for (const FramePattern& pattern : *patterns) report.push_back({{"file", pattern.pattern()}, {"frames", frames_}});
  if (!report.empty()) report.back()["seconds"] = writeSeconds_;  // all frame files together
  for (const std::string& video : videos_) {
    const auto start = std::chrono::steady_clock::now();
    createParentDirectory(video);
    encodeVideo(videoFramePaths_, fps_, video);
    report.push_back({{"file", video}, {"frames", videoFramePaths_.size()}, {"seconds", secondsSince(start)}});
  }
  return report;
}

}  // namespace texsynth::cli
