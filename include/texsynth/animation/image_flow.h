#pragma once
// Velocity fields for 2D flow animation: how far the texture moves in one frame, in output
// pixels (x right, y down), at every output pixel. From an analytic preset or from velocity
// images, one for the whole animation or one per frame (a frame-indexed file pattern).
//
// Presets (SPEC = NAME or NAME:key=value,key=value; centre and radius as fractions of the
// output's width and height; strength in pixels per frame):
//   uniform:dx=1,dy=0                 the same velocity everywhere
//   vortex:strength=1,cx=0.5,cy=0.5,radius=0.17
//   source / sink:strength=...,cx,cy,radius
//   saddle:strength=...,cx,cy,radius
// The centred presets peak at `strength` pixels per frame at `radius` from the centre and fade
// to nearly nothing at the output's border (speed = strength (r/R) exp((1 - (r/R)^2) / 2)), so
// the toroidal output shows no seam; the vortex turns clockwise on screen for a positive
// strength, a source pushes outwards, a sink pulls inwards, a saddle pushes out along x and in
// along y; a negative strength reverses each. Distances from the centre are the shortest ones
// on the torus; r/R is measured in radii of the width along x and of the height along y (an
// ellipse on a non-square output). cx and cy lie in [0, 1], radius in [0.001, 16], strengths and
// dx, dy within kMaxFlowSpeed (flow_limits.h).
//
// Velocity images (.exr, .png, or any readImage format): channels 0 and 1 are x and y. EXR
// stores pixels per frame; 8- and 16-bit images store v = 2 c - 1 in [-1, 1] pixels per frame.
// Every velocity (presets included) is then multiplied by `scale`. An image must be exactly the
// output's size and hold finite values. A SPEC is a file when its NAME is no preset and it
// looks like a path ('/', '.' or '%' in it, or an existing file). A pattern with one
// printf-style frame number (flow/%04d.exr; %d, %Nd, %0Nd, and %% for a literal '%') gives
// frame t the file of number t (frames 0, 1, ...: the flow that carries frame t to frame t + 1).
#include <string>

#include "texsynth/core/image.h"

namespace texsynth {

struct ImageFlowOptions {
  float scale = 1.0f;  // multiplies every velocity; |scale| <= kMaxFlowScale
};

class ImageFlow {
 public:
  // Parses SPEC for a width x height output. Throws ParameterError("flow", ...) for an unknown
  // preset, a bad key or a value outside its range (flow_limits.h) or a malformed pattern,
  // ParameterError("flowScale", ...) for a scale beyond kMaxFlowScale; InputError naming the file
  // for a missing, unreadable, too-small-in-channels (< 2) or wrongly sized velocity image, or one
  // with a velocity that is not finite or beyond kMaxFlowSpeed (the first one, or the only one,
  // is read here).
  static ImageFlow parse(const std::string& spec, int width, int height, const ImageFlowOptions& options = {});

  // Checks before any work that frames 0 .. frames - 2 have their files (a pattern): each one
  // exists and has the output's size and >= 2 channels (read from its header). Throws InputError
  // naming the first bad file.
  void requireFrames(int frames) const;

  // Velocities of frame `frame`: width x height, 2 channels (x, y) in output pixels per frame.
  // Deterministic; reads the frame's file for a pattern (InputError naming it if it is bad).
  Image velocities(int frame) const;

  bool timeVarying() const;         // a frame-indexed pattern
  std::string description() const;  // e.g. "vortex strength 1 at (0.5, 0.5), radius 0.17" or the file
  int width() const;
  int height() const;

 private:
  struct Preset {
    std::string name;
    float dx = 1, dy = 0, strength = 1, cx = 0.5f, cy = 0.5f, radius = 1.0f / 6.0f;
  };
  Preset preset_;
  std::string file_;  // a file or pattern; empty = preset
  Image fixed_;       // the velocities of a preset or a single file, computed once
  int width_ = 0, height_ = 0;
  float scale_ = 1.0f;
};

}  // namespace texsynth
