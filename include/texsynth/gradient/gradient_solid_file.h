#pragma once
// The .tsgs file: a GradientSolid stored as 8-bit quantized values (gradient-solid-textures §5.2).
//
// Every value is one byte. Each stored array has, per channel, a value range [lo, hi] (values) and a
// gradient bound g (gradients, quantized with a square-root companding so small slopes keep
// precision). Layout and checks: docs/gradient-solids.md. A missing, truncated, corrupted (CRC-32),
// lying or absurd file raises one InputError naming the file and the problem.
#include <cstdint>
#include <string>

#include "texsynth/gradient/gradient_solid.h"

namespace texsynth {

inline constexpr const char* kGradientSolidExtension = "tsgs";

// Rounds every value of `solid` to what a .tsgs file stores, so that errors measured on the result
// are the errors of the file.
void quantizeGradientSolid(GradientSolid& solid);

// Encodes / decodes the file's bytes. decode throws InputError("<where>: ...") naming `where`.
std::string encodeGradientSolid(const GradientSolid& solid);
GradientSolid decodeGradientSolid(const std::string& bytes, const std::string& where);

// Reads / writes a file (written atomically, as every output).
GradientSolid readGradientSolid(const std::string& path);
void writeGradientSolid(const std::string& path, const GradientSolid& solid);

// Bytes of the file for `solid`, and of its raw 8-bit voxel volume (voxels x channels), for the
// compression ratio reports quote (paper: 6.5% without regions, 15% with).
std::uint64_t gradientSolidFileBytes(const GradientSolid& solid);
std::uint64_t rawVolumeBytes(const GradientSolid& solid);

}  // namespace texsynth
