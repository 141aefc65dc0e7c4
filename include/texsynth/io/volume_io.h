#pragma once
// Volume files: read and write NRRD (attached data, raw or gzip, any endianness) and OpenVDB
// (for Blender/Houdini).
//
// NRRD layout: dimension 3 (sizes X Y Z) holds a scalar volume; dimension 4 with the channel
// axis first (sizes C X Y Z) holds C interleaved channels, which is exactly Volume's layout.
// Any missing, empty, truncated, malformed or absurd file (a side over 65536, over 2^31
// values, more data than the file could hold) raises one InputError naming the file and the
// problem. Writers go through writeAtomically: a failed write never leaves a partial file.
#include <string>

#include "texsynth/core/atomic_file.h"
#include "texsynth/core/volume.h"

namespace texsynth {

// Reads a .nrrd volume. Sample types: uint8, uint16, float (also int8, int16, int32, uint32,
// double). Integer samples are divided by their type's maximum (uint8 by 255, int16 by 32767
// ...), so 8/16-bit volumes come back in [0,1] like images; float and double are as stored,
// but a NaN, an infinity or a magnitude over kMaxColorMagnitude (1e6, see color_values.h) in
// any format is an InputError naming the file and the first such voxel.
// Detached data files ("data file:"), "line skip" and "byte skip" are rejected, and so is a
// file that contradicts itself: more data than 'sizes' says (raw, gzip or after the gzip
// stream), an unknown or repeated header field, a per-axis field ('kinds', 'spacings' ...)
// with the wrong number of axes, or a 'kinds' entry that does not fit its axis (RGB-color on
// a 3-D scalar volume, a channel kind whose size is not the channel count).
//
// Reads a .vdb volume: a vec3s (or vec3d) grid named "color" gives 3 channels; else the float
// (or double) grid "density", else the first float or double grid, gives 1 channel; other
// grids are ignored, and a file without a fitting grid is an error listing the grids it holds.
// Index coordinate (x,y,z) becomes voxel (x - x0, y - y0, z - z0); the transform is ignored.
// The dense box, with corner (x0,y0,z0): from 0 to the size writeVolume records in the grid's
// "texsynth_size" metadata when the active voxels lie inside it (so black borders survive a
// round trip), else the active voxels' bounding box, widened to start at index 0 when its
// corner is >= 0 on every axis.
// Inactive voxels inside the box take the grid's background value. A corrupt or truncated
// file, an empty grid or an absurd box (same limits as NRRD) is one InputError.
Volume readVolume(const std::string& path);

struct VolumeWriteOptions {
  bool gzip = true;          // NRRD only: gzip-encode the samples (else raw)
  bool floatSamples = true;  // NRRD only: 32-bit float samples; false: uint8, clipped to [0,1]
  // Inside an OutputBatch: with the run (default), or at once (scratch files the run reads back
  // itself, such as the studio's exported volume).
  Staging staging = Staging::WithRun;
};

// Writes a volume; the format comes from the extension:
//   .nrrd  little-endian NRRD0004; 1 channel as dimension 3, else dimension 4 (C X Y Z)
//   .vdb   OpenVDB: a FloatGrid "density" (Rec. 709 luminance of RGB(A) volumes, else
//          channel 0; grid class fog volume) and, for 3+ channels, a Vec3SGrid "color"
//          (channels 0..2). Voxel (x,y,z) is index coordinate (x,y,z); the voxel size is
//          1/max(nx,ny,nz) with a half-voxel offset, so the volume spans [0,1] along its
//          longest axis. Voxels equal to 0 stay inactive background; each grid's vec3i
//          metadata "texsynth_size" records nx ny nz for readVolume. Blender loads these.
// Throws ParameterError for an unknown extension or an empty volume; OutputError if the file
// cannot be written.
void writeVolume(const std::string& path, const Volume& volume, const VolumeWriteOptions& options = {});

}  // namespace texsynth
