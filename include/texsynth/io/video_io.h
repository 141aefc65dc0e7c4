#pragma once
// Videos and animated GIFs from numbered frames, through Debian's `ffmpeg` program (found on
// PATH, checked before any work so that a long animation never fails at its end).
//   .mp4   H.264 (libx264), yuv420p, even sides (a column/row is padded if needed), crf 18
//   .webm  VP9 (libvpx-vp9), crf 32
//   .gif   a palette made from the frames (palettegen/paletteuse), looping forever
// The output goes through writeAtomically's staging (an active OutputBatch stages it too), so a
// failed encode never leaves a partial file or replaces a good one.
#include <string>
#include <vector>

namespace texsynth {

// Whether `path`'s extension is one encodeVideo writes (mp4, webm, gif; case-insensitive).
bool isVideoFile(const std::string& path);

// Throws OutputError(path, ...) with a clear message (how to install: apt-get install ffmpeg)
// if no ffmpeg program runs, and ParameterError("output", ...) for an extension it cannot write.
void requireVideoEncoder(const std::string& path);

// Encodes the PNG frames `framePaths` (all the same size, in order) at `fps` frames per second
// into `path`. Throws OutputError(path, ...) with ffmpeg's last error line if it fails.
void encodeVideo(const std::vector<std::string>& framePaths, double fps, const std::string& path);

}  // namespace texsynth
