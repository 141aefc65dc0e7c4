#include "texsynth/surface/surface_coordinates.h"

#include <algorithm>
#include <cmath>

#include "texsynth/core/error.h"

namespace texsynth {
namespace {

void requireSize(int width, int height) {
  if (width < 1) throw ParameterError("width", "must be at least 1, not " + std::to_string(width));
  if (height < 1) throw ParameterError("height", "must be at least 1, not " + std::to_string(height));
}

const std::vector<float>& attributeValues(const Mesh& mesh, const char* name, const std::string& source) {
  auto found = mesh.attributes.find(name);
  if (found == mesh.attributes.end() || found->second.components != 1 ||
      found->second.values.size() != mesh.vertexCount())
    throw InputError(source,
                     std::string("has no '") + name +
                         "' vertex property: not a coordinates file (write one with texsynth surface --coords)");
  return found->second.values;
}

}  // namespace

void storeSourceCoordinates(Mesh& mesh, std::span<const std::int32_t> sources, int width, int height) {
  requireSize(width, height);
  if (sources.size() != mesh.vertexCount())
    throw ParameterError(
        "sources", std::to_string(sources.size()) + " sources for " + std::to_string(mesh.vertexCount()) + " vertices");
  const std::int64_t pixels = std::int64_t(width) * height;
  VertexAttribute u{1, std::vector<float>(sources.size())}, v{1, std::vector<float>(sources.size())};
  for (std::size_t i = 0; i < sources.size(); ++i) {
    if (sources[i] < 0 || sources[i] >= pixels)
      throw ParameterError("sources", "source " + std::to_string(sources[i]) + " of vertex " + std::to_string(i) +
                                          " is outside a " + std::to_string(width) + "x" + std::to_string(height) +
                                          " exemplar");
    // Pixel centres: exact under float rounding for any width up to 2^22, and they stay inside the
    // same pixel when the map has another resolution.
    u.values[i] = float((double(sources[i] % width) + 0.5) / width);
    v.values[i] = float((double(sources[i] / width) + 0.5) / height);
  }
  mesh.attributes[kSourceUAttribute] = std::move(u);
  mesh.attributes[kSourceVAttribute] = std::move(v);
}

std::vector<std::int32_t> sourcesFromCoordinates(const Mesh& mesh, int width, int height, const std::string& source) {
  requireSize(width, height);
  const std::vector<float>& u = attributeValues(mesh, kSourceUAttribute, source);
  const std::vector<float>& v = attributeValues(mesh, kSourceVAttribute, source);
  std::vector<std::int32_t> sources(mesh.vertexCount());
  for (std::size_t i = 0; i < sources.size(); ++i) {
    if (!(u[i] >= 0.0f && u[i] <= 1.0f && v[i] >= 0.0f && v[i] <= 1.0f))
      throw InputError(source, "vertex " + std::to_string(i) + " has source coordinates (" + std::to_string(u[i]) +
                                   ", " + std::to_string(v[i]) + ") outside [0, 1]");
    const int x = std::min(width - 1, int(std::floor(double(u[i]) * width)));
    const int y = std::min(height - 1, int(std::floor(double(v[i]) * height)));
    sources[i] = std::int32_t(std::int64_t(y) * width + x);
  }
  return sources;
}

}  // namespace texsynth
