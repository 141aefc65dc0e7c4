#pragma once
// Mesh files: read OBJ, PLY (ascii and binary), OFF (with COFF colors), STL (ascii and binary)
// and glTF 2.0 (.glb / .gltf) into an indexed triangle Mesh; write PLY, OBJ and glTF 2.0.
//
// Readers triangulate polygons (fan), drop degenerate triangles (a repeated index), validate
// the result and compute normals when the file has none. Texture coordinates become the vertex
// attribute "uv" (OBJ vt, splitting vertices at UV seams; PLY u,v / s,t / texture_u,texture_v),
// other scalar PLY vertex properties attributes of their names (core/mesh.h). Any malformed, truncated, empty or
// absurd file raises one InputError naming the file and the problem (with the line number for
// text formats); absurd element counts are rejected before anything is allocated.
// Writers go through writeAtomically: a failed write never leaves a partial file.
#include <string>
#include <string_view>

#include "texsynth/core/mesh.h"

namespace texsynth {

// Reads a mesh, choosing the format by extension: .obj .ply .off .stl .glb .gltf.
Mesh readMesh(const std::string& path);

// Writes a mesh, choosing the format by extension:
//   .ply  binary little endian: float x,y,z, nx,ny,nz, uchar red,green,blue (if mesh.colors),
//         float attributes ("uv" as s,t; others by name, NAME_0.. for several components)
//   .obj  'v x y z [r g b]', 'vt u v' (if "uv") and 'vn' lines, faces 'f a/[a]/a ...'
//   .glb  binary glTF 2.0;  .gltf  glTF 2.0 JSON with the buffer embedded as a data URI
//         (POSITION, NORMAL, COLOR_0, TEXCOORD_0 from "uv")
// Normals are computed for the output when the mesh has none. Throws ParameterError for an
// unsupported extension or an inconsistent mesh, OutputError if the file cannot be written.
void writeMesh(const std::string& path, const Mesh& mesh);

// Parsers over bytes already in memory; `source` names the origin in error messages.
// They triangulate and drop degenerate triangles; readMesh then validates the mesh and
// computes missing normals.
Mesh parseObj(std::string_view bytes, const std::string& source);
Mesh parsePly(std::string_view bytes, const std::string& source);
Mesh parseOff(std::string_view bytes, const std::string& source);
Mesh parseStl(std::string_view bytes, const std::string& source);
// glTF 2.0, binary (.glb) or JSON (.gltf; buffers embedded, or files next to `source`): the
// triangle primitives of the default scene, placed by their nodes' transforms, with NORMAL (kept
// only when every primitive has it) and COLOR_0 (float or normalized integers; primitives without
// it white when another has it). Primitives keep their own vertices (no welding).
Mesh parseGltf(std::string_view bytes, const std::string& source);

// The bytes writeMesh would store for .ply / .obj (exposed for tests and in-memory use).
std::string encodePly(const Mesh& mesh);
std::string encodeObj(const Mesh& mesh);
// binary: true for .glb, false for .gltf with an embedded buffer.
std::string encodeGltf(const Mesh& mesh, bool binary);

}  // namespace texsynth
