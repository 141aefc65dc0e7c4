// Volume file dispatch by extension, plus the checks every volume writer shares.
#include "texsynth/io/volume_io.h"

#include "texsynth/core/atomic_file.h"
#include "texsynth/core/error.h"
#include "texsynth/io/color_values.h"
#include "texsynth/io/readable_file.h"
#include "volume_codecs.h"

namespace texsynth {

Volume readVolume(const std::string& path) {
  requireReadableFile(path);  // a directory is that, not an unsupported format
  std::string ext = fileExtension(path);
  if (ext != "nrrd" && ext != "vdb")
    throw InputError(path, "unsupported volume format '." + ext + "' (readable: .nrrd .vdb)");
  std::string bytes = readFileBytes(path);
  if (bytes.empty()) throw InputError(path, "file is empty");
  Volume volume =
      ext == "vdb" ? volume_codec::decodeVdb(path, std::move(bytes)) : volume_codec::decodeNrrd(path, bytes);
  // Float samples come as stored: refuse what no colour (or mask) value can be.
  checkColorValues(path, volume);
  return volume;
}

void writeVolume(const std::string& path, const Volume& volume, const VolumeWriteOptions& options) {
  std::string ext = fileExtension(path);
  if (ext != "nrrd" && ext != "vdb")
    throw ParameterError("output file '" + path + "'",
                         "unsupported volume format '." + ext + "' (writable: .nrrd .vdb)");
  if (volume.empty()) throw ParameterError("volume", "cannot write an empty volume to '" + path + "'");
  if (volume.voxels.size() != volume.voxelCount() * volume.channels)
    throw ParameterError("volume", "voxel buffer size does not match " + std::to_string(volume.nx) + "x" +
                                       std::to_string(volume.ny) + "x" + std::to_string(volume.nz));
  if (ext == "nrrd")
    writeAtomically(
        path, [&](const std::string& temp) { volume_codec::writeNrrd(temp, path, volume, options); }, options.staging);
  else
    writeFileAtomically(path, volume_codec::encodeVdb(path, volume), options.staging);
}

}  // namespace texsynth
