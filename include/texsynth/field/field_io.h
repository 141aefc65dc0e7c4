#pragma once
// Field files (.tsfield): a rotation field and its scale field, documented in
// docs/sketch-format.md. Layout: the 8 bytes "TSFIELD1", a uint32 little-endian length, that
// many bytes of JSON header {"format":"texsynth-field","version":1,"nodes":[nx,ny,nz],
// "origin":[x,y,z],"spacing":h,"has_scale":bool}, then nx*ny*nz quaternions as float32 LE
// (w, x, y, z; x index fastest, then y, then z), then (if has_scale) nx*ny*nz float32 scales.
#include <string>
#include <string_view>

#include "texsynth/field/rotation_field.h"
#include "texsynth/field/scale_field.h"

namespace texsynth {

struct FieldFile {
  RotationField rotations;
  ScaleField scales;  // scale 1 everywhere when the file has none
  bool hasScale = false;
};

std::string encodeField(const FieldFile& field);
// Throws InputError(source, ...) for a wrong magic, a bad header, a truncated or oversized
// body, or values that are not unit quaternions / positive scales.
FieldFile decodeField(std::string_view bytes, const std::string& source);
// Atomic write (OutputError on failure) and read (InputError).
void writeField(const std::string& path, const FieldFile& field);
FieldFile readField(const std::string& path);

}  // namespace texsynth
