#pragma once
// What kind of data a path holds, judged by its extension: the CLI dispatches on it.
#include <string>

namespace texsynth {

enum class FileKind { Image, Mesh, Volume, Field, GradientSolid, Unknown };

FileKind fileKind(const std::string& path);
// Human-readable lists of the extensions texsynth reads, for error messages and --help.
std::string readableImageExtensions();
std::string readableMeshExtensions();
std::string readableVolumeExtensions();
std::string readableFieldExtensions();
std::string readableGradientSolidExtensions();

}  // namespace texsynth
