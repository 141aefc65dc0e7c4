#pragma once
// Instant editing of gradient solids (gradient-solid-textures §4.4, after Li, Ju & Hu 2010).
//
// The user marks stroke voxels with strengths in [0,1] and picks a reference colour. The influence
// h at a control point is a non-negative sum of m Gaussian RBFs centred on stroke voxels, in position
// and colour (eq. 4); the weights come from a linear program (GLPK) that minimizes the total deviation
// from the strokes' strengths. Each control point's colour moves towards the reference by h, and its
// gradients follow in closed form (eqs. 5-6), so the edit costs one pass over the control points.
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "texsynth/core/math.h"
#include "texsynth/core/volume.h"
#include "texsynth/gradient/gradient_solid.h"

namespace texsynth {

// A polyline through the solid, in the equivalent raster's voxel coordinates, and how strongly the
// voxels it passes through are to be edited (0 keeps them, 1 takes the reference colour).
struct EditStroke {
  std::vector<Vec3f> points;
  float strength = 1.0f;
};

struct EditOptions {
  Vec3f color = Vec3f(1.0f, 0.0f, 1.0f);  // reference colour, [0,1]
  int centres = 24;                       // m, RBF centres drawn from the stroke voxels
  float alpha = 1e-4f;                    // paper: 1e-4 (colours on the 0..255 scale)
  float beta = 0.1f;                      // paper: 0.1 (positions in voxels)
  std::uint64_t seed = 1;
};

struct EditReport {
  int strokeVoxels = 0;
  int centres = 0;
  int lpRows = 0;               // stroke voxels the linear program fitted (a subsample when there are many)
  std::vector<double> weights;  // omega_k >= 0, one per centre
  double lpSeconds = 0;
  double updateSeconds = 0;
  double strengthDeviation = 0;  // mean |h - strength| over stroke voxels
};

// A stroke file's content: the strokes and, when the file gives one, the reference colour.
struct EditStrokeFile {
  std::vector<EditStroke> strokes;
  std::optional<Vec3f> color;
};

// Stroke files: JSON, see docs/stroke-format.md. Throws InputError naming the file (and JSON path).
std::vector<EditStroke> readEditStrokes(const std::string& path);
EditStrokeFile readEditStrokeFile(const std::string& path);
// The same from JSON text; `source` names it in errors.
EditStrokeFile parseEditStrokes(std::string_view json, const std::string& source);

// Edits `solid` in place. Throws ParameterError("strokes" | "color" | "centres" | ...) for bad input.
EditReport editGradientSolid(GradientSolid& solid, const std::vector<EditStroke>& strokes, const EditOptions& options);

// The same edit applied voxel by voxel to a raster volume (the baseline the paper compares with).
EditReport editVolume(Volume& volume, const std::vector<EditStroke>& strokes, const EditOptions& options);

}  // namespace texsynth
