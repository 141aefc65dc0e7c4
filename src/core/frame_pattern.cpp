#include "texsynth/core/frame_pattern.h"

#include <utility>

#include "texsynth/core/error.h"

namespace texsynth {

FramePattern::FramePattern(std::string pattern, const std::string& parameter) : pattern_(std::move(pattern)) {
  std::string* out = &prefix_;
  for (std::size_t i = 0; i < pattern_.size(); ++i) {
    if (pattern_[i] != '%') {
      *out += pattern_[i];
      continue;
    }
    std::size_t j = i + 1;
    if (j < pattern_.size() && pattern_[j] == '%') {
      *out += '%';
      i = j;
      continue;
    }
    const bool zeroPad = j < pattern_.size() && pattern_[j] == '0';
    if (zeroPad) ++j;
    int width = 0;
    while (j < pattern_.size() && pattern_[j] >= '0' && pattern_[j] <= '9' && width < 100)
      width = width * 10 + (pattern_[j++] - '0');
    if (j >= pattern_.size() || pattern_[j] != 'd' || width > 9)
      throw ParameterError(parameter,
                           "'" + pattern_ + "': a '%' must start a frame number (%d, %04d) or be doubled (%%)");
    if (numbered_) throw ParameterError(parameter, "'" + pattern_ + "' has more than one frame number");
    numbered_ = true;
    zeroPad_ = zeroPad;
    width_ = width;
    out = &suffix_;
    i = j;
  }
}

std::string FramePattern::path(int frame) const {
  if (!numbered_) return prefix_;
  std::string number = std::to_string(frame);
  if (int(number.size()) < width_) number.insert(0, std::size_t(width_) - number.size(), zeroPad_ ? '0' : ' ');
  return prefix_ + number + suffix_;
}

}  // namespace texsynth
