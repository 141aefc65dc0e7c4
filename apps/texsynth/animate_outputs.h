#pragma once
// The files `texsynth animate` writes, frame by frame as they come: numbered pictures
// (frames/%04d.png: the texture, or the rendered mesh), numbered vertex-colored meshes
// (colors/%04d.ply, with --mesh) and videos (.mp4 .webm .gif through ffmpeg, encoded at the end
// from private copies of the pictures). Everything goes through the run's OutputBatch, so a
// failed or interrupted animation leaves no frame and replaces no earlier one.
#include <memory>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "texsynth/core/frame_pattern.h"
#include "texsynth/core/image.h"
#include "texsynth/core/mesh.h"
#include "texsynth/core/temporary_files.h"

namespace texsynth::cli {

class FrameOutputs {
 public:
  // Sorts -o outputs by kind and checks them before any work (pattern or video, extension,
  // ffmpeg present for videos). Throws ParameterError("--output", ...).
  FrameOutputs(const std::vector<std::string>& outputs, bool meshFrames, double fps);
  ~FrameOutputs();
  FrameOutputs(const FrameOutputs&) = delete;
  FrameOutputs& operator=(const FrameOutputs&) = delete;

  // Whether any output needs the frame as a picture (numbered images or a video).
  bool wantsPictures() const { return !pictures_.empty() || !videos_.empty(); }
  bool wantsMeshes() const { return !meshes_.empty(); }

  void addPicture(int frame, const Image& picture);
  void addMesh(int frame, const Mesh& colored);
  // Encodes the videos; one report entry per output (file, frames, seconds).
  nlohmann::json finish();

 private:
  std::vector<FramePattern> pictures_, meshes_;
  std::vector<std::string> videos_;
  std::unique_ptr<ScratchDirectory> videoFrames_;  // PNG copies of the frames for the encoder
  std::vector<std::string> videoFramePaths_;
  double fps_ = 24;
  int frames_ = 0;
  double writeSeconds_ = 0;
};

}  // namespace texsynth::cli
