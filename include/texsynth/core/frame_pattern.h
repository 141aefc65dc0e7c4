#pragma once
// File names with a printf-style frame number: "frames/%04d.png" names frame 7 "frames/0007.png".
// Read by time-varying flows and written by animations.
#include <string>

namespace texsynth {

class FramePattern {
 public:
  FramePattern() = default;
  // At most one frame number (%d, %4d, %04d; width up to 9); %% is a literal '%'. Throws
  // ParameterError(parameter, ...) for another '%' conversion or a second frame number.
  FramePattern(std::string pattern, const std::string& parameter);

  bool numbered() const { return numbered_; }
  // The file of frame `frame` (>= 0); the one file when not numbered.
  std::string path(int frame) const;
  const std::string& pattern() const { return pattern_; }

 private:
  std::string pattern_, prefix_, suffix_;
  bool numbered_ = false, zeroPad_ = false;
  int width_ = 0;
};

}  // namespace texsynth
