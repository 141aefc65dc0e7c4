#pragma once
// Internal: the pieces evaluateImage and evaluateVolume share.
#include <string>

#include "texsynth/core/image.h"
#include "texsynth/eval/metrics.h"
#include "texsynth/eval/patch_index.h"

namespace texsynth::eval_detail {

// Throws ParameterError for options no metric can use.
void validateOptions(const MetricOptions& options);

// `image` as RGB on 0..255. Throws ParameterError naming `what` if it is empty, smaller than
// the patch, or holds non-finite values.
Image toRgb255(const Image& image, const std::string& what, int patchSize);

// All four metrics of an RGB 0..255 output against an indexed RGB 0..255 exemplar
// (`seconds` left 0).
QualityMetrics evaluateRgb255(const PatchIndex& exemplarIndex, const Image& output, const MetricOptions& options);

}  // namespace texsynth::eval_detail
