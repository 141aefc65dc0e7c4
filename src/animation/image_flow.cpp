#include "texsynth/animation/image_flow.h"

#include <algorithm>
#include <cmath>
#include <string_view>

#include "flow_spec.h"
#include "texsynth/animation/flow_limits.h"
#include "texsynth/core/error.h"
#include "texsynth/core/frame_pattern.h"
#include "texsynth/core/math.h"
#include "texsynth/core/parallel.h"
#include "texsynth/io/image_io.h"

namespace texsynth {
namespace {

using flow_detail::FlowSpec;
using flow_detail::PresetKeys;
using flow_detail::shortNumber;

// Speeds in pixels per frame; centre and radius in fractions of the output.
constexpr flow_detail::PresetKey kSpeed(std::string_view name) {
  return {name, -kMaxFlowSpeed, kMaxFlowSpeed};
}
constexpr flow_detail::PresetKey kCentre[] = {{"cx", 0, 1}, {"cy", 0, 1}, {"radius", 1e-3, 16}};
const PresetKeys kPresets[] = {{"uniform", {kSpeed("dx"), kSpeed("dy")}},
                               {"vortex", {kSpeed("strength"), kCentre[0], kCentre[1], kCentre[2]}},
                               {"source", {kSpeed("strength"), kCentre[0], kCentre[1], kCentre[2]}},
                               {"sink", {kSpeed("strength"), kCentre[0], kCentre[1], kCentre[2]}},
                               {"saddle", {kSpeed("strength"), kCentre[0], kCentre[1], kCentre[2]}}};

constexpr std::int64_t kRowsPerChunk = 16;

// Fills a width x height, 2-channel image with velocity(x, y) at pixel centres, in parallel rows.
template <class Velocity>
Image velocityImage(int width, int height, const Velocity& velocity) {
  Image out(width, height, 2);
  parallelForChunks(0, height, kRowsPerChunk, [&](std::int64_t begin, std::int64_t end) {
    for (int y = int(begin); y < int(end); ++y)
      for (int x = 0; x < width; ++x) {
        const Vec2f v = velocity(x, y);
        out.at(x, y, 0) = v.x();
        out.at(x, y, 1) = v.y();
      }
  });
  return out;
}

// The shortest displacement from `from` to `to` on a circle of length `period`.
float torusDelta(float to, float from, float period) {
  const float d = to - from;
  return d - period * std::round(d / period);
}

// A centred preset: speed strength (r/R) exp((1 - (r/R)^2) / 2), with r/R measured in radii
// of width along x and of height along y; the direction from the preset's name.
Image centredVelocities(std::string_view name, float strength, float cx, float cy, float radius, int width,
                        int height) {
  const float centreX = cx * float(width), centreY = cy * float(height);
  const float radiusX = radius * float(width), radiusY = radius * float(height);
  return velocityImage(width, height, [&](int x, int y) {
    const float dx = torusDelta(float(x) + 0.5f, centreX, float(width));
    const float dy = torusDelta(float(y) + 0.5f, centreY, float(height));
    const float length = std::hypot(dx, dy);
    if (length == 0) return Vec2f(0, 0);
    const float s2 = (dx / radiusX) * (dx / radiusX) + (dy / radiusY) * (dy / radiusY);
    const Vec2f outwards = Vec2f(dx, dy) / length;
    const Vec2f v = strength * std::sqrt(s2) * std::exp((1 - s2) / 2) * outwards;
    if (name == "vortex") return Vec2f(-v.y(), v.x());  // y points down: clockwise on screen
    if (name == "sink") return Vec2f(-v);
    if (name == "saddle") return Vec2f(v.x(), -v.y());
    return v;  // source
  });
}

// Throws InputError naming `path` unless its header describes a width x height image with at
// least 2 channels.
void requireVelocityImage(const std::string& path, const ImageFileInfo& info, int width, int height) {
  if (info.channels < 2)
    throw InputError(path, "has " + std::to_string(info.channels) + " channel" + (info.channels == 1 ? "" : "s") +
                               "; a velocity image needs 2 (x, y)");
  if (info.width != width || info.height != height)
    throw InputError(path, "is " + std::to_string(info.width) + "x" + std::to_string(info.height) + ", the output is " +
                               std::to_string(width) + "x" + std::to_string(height));
}

// Velocities of one image file: EXR as stored, integer formats mapped from [0, 1] to [-1, 1].
Image readVelocityImage(const std::string& path, int width, int height) {
  const ImageFileInfo info = readImageInfo(path);
  requireVelocityImage(path, info, width, height);
  const Image image = readImage(path);
  const bool raw = info.format == "exr";
  Image out = velocityImage(width, height, [&](int x, int y) {
    const Vec2f c(image.at(x, y, 0), image.at(x, y, 1));
    return raw ? c : Vec2f(2 * c - Vec2f::Ones());
  });
  const auto bad = std::find_if(out.pixels.begin(), out.pixels.end(),
                                [](float v) { return !(std::abs(v) <= kMaxFlowSpeed); });  // NaN too
  if (bad != out.pixels.end()) {
    const std::size_t pixel = std::size_t(bad - out.pixels.begin()) / 2;
    throw InputError(path, "has a velocity of " + shortNumber(*bad) + " at pixel (" +
                               std::to_string(pixel % std::size_t(width)) + ", " +
                               std::to_string(pixel / std::size_t(width)) + "); velocities must be finite and within " +
                               std::to_string(int(kMaxFlowSpeed)) + " pixels per frame");
  }
  return out;
}

Image scaled(Image velocities, float scale) {
  flow_detail::scaleVelocities(velocities.pixels, scale);
  return velocities;
}

}  // namespace

std::span<const PresetKeys> flow_detail::imagePresets() {
  return kPresets;
}

ImageFlow ImageFlow::parse(const std::string& spec, int width, int height, const ImageFlowOptions& options) {
  TS_CHECK_MSG(width > 0 && height > 0, "an image flow needs a non-empty output");
  requireFlowScale(options.scale);
  const FlowSpec parsed = FlowSpec::parse(spec, kPresets);
  ImageFlow flow;
  flow.width_ = width;
  flow.height_ = height;
  flow.scale_ = options.scale;
  if (parsed.isFile()) {
    flow.file_ = parsed.name();
    const FramePattern pattern(flow.file_, "flow");
    Image first = readVelocityImage(pattern.path(0), width, height);
    if (!pattern.numbered()) flow.fixed_ = scaled(std::move(first), flow.scale_);
    return flow;
  }
  Preset& p = flow.preset_;
  p.name = parsed.name();
  if (p.name == "uniform") {
    p.dx = parsed.number("dx", p.dx);
    p.dy = parsed.number("dy", p.dy);
    flow.fixed_ = scaled(velocityImage(width, height, [&](int, int) { return Vec2f(p.dx, p.dy); }), flow.scale_);
    return flow;
  }
  p.strength = parsed.number("strength", p.strength);
  p.cx = parsed.number("cx", p.cx);
  p.cy = parsed.number("cy", p.cy);
  p.radius = parsed.number("radius", p.radius);
  flow.fixed_ = scaled(centredVelocities(p.name, p.strength, p.cx, p.cy, p.radius, width, height), flow.scale_);
  return flow;
}

void ImageFlow::requireFrames(int frames) const {
  if (file_.empty()) return;
  const FramePattern pattern(file_, "flow");
  if (!pattern.numbered()) return;
  for (int t = 0; t + 1 < frames; ++t) {
    const std::string path = pattern.path(t);
    requireVelocityImage(path, readImageInfo(path), width_, height_);
  }
}

Image ImageFlow::velocities(int frame) const {
  TS_CHECK_MSG(frame >= 0, "frames count from 0");
  if (!fixed_.empty()) return fixed_;
  return scaled(readVelocityImage(FramePattern(file_, "flow").path(frame), width_, height_), scale_);
}

bool ImageFlow::timeVarying() const {
  return !file_.empty() && FramePattern(file_, "flow").numbered();
}

std::string ImageFlow::description() const {
  std::string text;
  if (!file_.empty())
    text = timeVarying() ? "velocity images " + file_ + " (one per frame)" : "velocity image " + file_;
  else if (preset_.name == "uniform")
    text = "uniform (" + shortNumber(preset_.dx) + ", " + shortNumber(preset_.dy) + ") pixels per frame";
  else
    text = preset_.name + " strength " + shortNumber(preset_.strength) + " at (" + shortNumber(preset_.cx) + ", " +
           shortNumber(preset_.cy) + "), radius " + shortNumber(preset_.radius);
  if (scale_ != 1.0f) text += ", scale " + shortNumber(scale_);
  return text;
}

int ImageFlow::width() const {
  return width_;
}
int ImageFlow::height() const {
  return height_;
}

}  // namespace texsynth
