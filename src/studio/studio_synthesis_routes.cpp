// Routes that synthesize: previews on the model and cuts through it (jobs in the "preview" and
// "cut" lanes, results announced on the event stream and fetched from /api/results), and exports.
#include <filesystem>
#include <optional>
#include <sstream>

#include "studio_state.h"
#include "texsynth/core/atomic_file.h"
#include "texsynth/core/error.h"
#include "texsynth/core/temporary_files.h"
#include "texsynth/field/field_io.h"
#include "texsynth/geometry/mesh_cut.h"
#include "texsynth/io/image_io.h"
#include "texsynth/io/mesh_io.h"
#include "texsynth/io/volume_io.h"
#include "texsynth/render/glyph_mesh.h"
#include "texsynth/solid/solid_consumers.h"

namespace texsynth::studio {

namespace {

using Clock = std::chrono::steady_clock;
const Vec3f kUntextured{0.72f, 0.72f, 0.72f};

// What a job needs, taken under the state's lock when the request comes in.
struct JobInputs {
  std::shared_ptr<StudioScene> scene;
  std::shared_ptr<const RotationField> field;
  int sceneSerial = 0, fieldRevision = 0;
  TextureSettings texture;
  CatalogEntry exemplar;
};

JobInputs takeInputs(StudioState& state, const nlohmann::json& body) {
  std::lock_guard<std::mutex> lock(state.mutex);
  JobInputs inputs;
  inputs.scene = state.requireScene();
  inputs.field = inputs.scene->field();
  inputs.sceneSerial = state.sceneSerial;
  inputs.fieldRevision = inputs.scene->revision();
  inputs.texture = TextureSettings::fromJson(body, state.texture);
  if (inputs.texture.exemplarId.empty()) throw HttpError(409, "no exemplar chosen yet");
  inputs.exemplar = state.catalog.exemplar(inputs.texture.exemplarId);
  return inputs;
}

// The kept solid for these inputs with `method`: the factory's recipe as the command line makes it.
std::shared_ptr<KeptSolid> solidFor(StudioState& state, const JobInputs& inputs, const std::string& method,
                                    Progress& progress) {
  const bool lazy = method == "lazy";
  std::ostringstream key;
  key << method << '|' << inputs.exemplar.id << '|' << inputs.texture.tiles << '|' << inputs.texture.seed << '|'
      << inputs.sceneSerial << '|' << (lazy ? inputs.fieldRevision : -1);
  return state.solids.get(
      key.str(), inputs.exemplar.id,
      [&] {
        SolidRecipe recipe;
        recipe.method = parseSolidMethod(method);
        recipe.exemplars = {readImage(inputs.exemplar.path)};
        recipe.box = inputs.scene->bounds();
        recipe.tiles = inputs.texture.tiles;
        recipe.seed = inputs.texture.seed;
        recipe.lazy.levels = 0;
        recipe.lazy.cacheDirectory = state.options.cacheDirectory;
        if (lazy) recipe.field = inputs.field;
        return recipe;
      },
      progress);
}

std::string rgb8(const std::vector<Vec3f>& colors) {
  std::string bytes(colors.size() * 3, '\0');
  for (std::size_t i = 0; i < colors.size(); ++i)
    for (int c = 0; c < 3; ++c)
      bytes[i * 3 + std::size_t(c)] = char(std::lround(std::clamp(colors[i][c], 0.0f, 1.0f) * 255.0f));
  return bytes;
}

// Colours of display vertices by `method`: all of them, or those listed in `subset`.
std::vector<Vec3f> displayColors(StudioState& state, const JobInputs& inputs, const std::string& method,
                                 Progress& progress, const std::vector<std::size_t>* subset = nullptr) {
  const Mesh& display = inputs.scene->display();
  const auto solid = solidFor(state, inputs, method, progress);
  if (!subset) return solid->colors(display.positions, display.normals, progress);
  std::vector<Vec3f> points, normals;
  for (std::size_t v : *subset) points.push_back(display.positions[v]), normals.push_back(display.normals[v]);
  return solid->colors(points, normals, progress);
}

void publishPreview(StudioState& state, const JobInputs& inputs, const std::string& method, const std::string& stage,
                    const std::vector<Vec3f>& colors, Clock::time_point started, const std::string& jobId) {
  const std::string id = state.results.put("application/octet-stream", rgb8(colors));
  state.events.publish("result", {{"job", jobId},
                                  {"kind", "preview"},
                                  {"stage", stage},
                                  {"method", method},
                                  {"url", "/api/results/" + id},
                                  {"format", "rgb8"},
                                  {"vertices", colors.size()},
                                  {"mesh", inputs.scene->meshId()},
                                  {"field_revision", inputs.fieldRevision},
                                  {"seconds", std::chrono::duration<double>(Clock::now() - started).count()}});
}

// The preview job: tile-deform at once ("fast"); a slower method then refines, with a camera the
// vertices facing it first ("visible", the others keep the fast colours), then all ("final").
void runPreview(StudioState& state, const JobInputs& inputs, const std::optional<Vec3f>& camera, Progress& progress,
                const std::string& jobId) {
  const auto started = Clock::now();
  const std::string& method = inputs.texture.method;
  std::vector<Vec3f> colors = displayColors(state, inputs, "tile-deform", progress);
  if (method == "tile-deform") return publishPreview(state, inputs, method, "final", colors, started, jobId);
  publishPreview(state, inputs, "tile-deform", "fast", colors, started, jobId);
  if (camera && method == "lazy") {
    const Mesh& display = inputs.scene->display();
    std::vector<std::size_t> facing;
    for (std::size_t v = 0; v < display.vertexCount(); ++v)
      if (display.normals[v].dot(*camera - display.positions[v]) > 0) facing.push_back(v);
    const std::vector<Vec3f> front = displayColors(state, inputs, method, progress, &facing);
    for (std::size_t i = 0; i < facing.size(); ++i) colors[facing[i]] = front[i];
    publishPreview(state, inputs, method, "visible", colors, started, jobId);
  }
  publishPreview(state, inputs, method, "final", displayColors(state, inputs, method, progress), started, jobId);
}

// The display mesh cut open at `fraction` of its box along `axis`, coloured by the texture.
Mesh cutMesh(StudioState& state, const JobInputs& inputs, int axis, float fraction, Progress& progress) {
  const StudioScene& scene = *inputs.scene;
  MeshCut cut = cutOpenMesh(coloredCopy(scene.display(), kUntextured), axis, fraction,
                            scene.bounds().size().maxCoeff() / 256.0f, kUntextured);
  const auto solid = solidFor(state, inputs, inputs.texture.method, progress);
  cut.mesh.colors = solid->colors(cut.mesh.positions, cut.mesh.normals, progress);
  return std::move(cut.mesh);
}

// The volume as the command line's writer puts it in a .vdb file. The file is a scratch file the
// export reads back at once, so it is moved into place now, not with the run's outputs
// (output_batch.h) that `texsynth studio`, as every command, runs inside. Errors name it
// "volume.vdb" (answer() drops its private folder).
std::string volumeFileBytes(const Volume& volume) {
  ScratchDirectory scratch("the exported volume");
  const std::string path = scratch.path() + "/volume.vdb";
  VolumeWriteOptions options;
  options.staging = Staging::Immediately;
  writeVolume(path, volume, options);
  return readFileBytes(path);
}

int parseAxis(const nlohmann::json& value) {
  if (value.is_string()) {
    const std::string a = value.get<std::string>();
    if (a == "x" || a == "y" || a == "z") return a[0] - 'x';
  }
  if (value.is_number_integer() && value.get<int>() >= 0 && value.get<int>() <= 2) return value.get<int>();
  throw HttpError(400, "axis: give \"x\", \"y\" or \"z\"");
}

}  // namespace

void addSynthesisRoutes(StudioRouter& router, StudioState& state) {
  const std::size_t json = state.options.limits.jsonBytes;
  router.post("/api/preview", json, [&state](const httplib::Request& request, httplib::Response& response) {
    answer(response, [&] {
      nlohmann::json body = jsonBody(request);
      std::optional<Vec3f> camera;  // where the page looks from: the lazy solid refines what faces it first
      if (body.is_object() && body.contains("camera")) {
        const nlohmann::json& c = body["camera"];
        if (!c.is_array() || c.size() != 3 || !c[0].is_number() || !c[1].is_number() || !c[2].is_number())
          throw HttpError(400, "camera: give the camera's position as [x, y, z]");
        camera = Vec3f(c[0].get<float>(), c[1].get<float>(), c[2].get<float>());
        if (!camera->allFinite()) throw HttpError(400, "camera: give finite coordinates");
        body.erase("camera");
      }
      const JobInputs inputs = takeInputs(state, body);
      {
        std::lock_guard<std::mutex> lock(state.mutex);
        state.texture = inputs.texture;  // what later cuts and exports use
        state.keepSceneInUse();
      }
      const std::string job =
          state.jobs->submit("preview", [&state, inputs, camera](Progress& progress, const std::string& jobId) {
            runPreview(state, inputs, camera, progress, jobId);
          });
      sendJson(response, {{"job", job}, {"texture", inputs.texture.toJson()}}, 202);
    });
  });
  router.post("/api/cut", json, [&state](const httplib::Request& request, httplib::Response& response) {
    answer(response, [&] {
      nlohmann::json body = jsonBody(request);
      if (!body.is_object() || !body.contains("axis") || !body.contains("position"))
        throw HttpError(400, "give {\"axis\": \"x\"|\"y\"|\"z\", \"position\": fraction in (0, 1)}");
      const int axis = parseAxis(body["axis"]);
      const nlohmann::json& position = body["position"];
      if (!position.is_number() || !(position.get<double>() > 0 && position.get<double>() < 1))
        throw HttpError(400, "position: give a fraction of the box in (0, 1)");
      const float fraction = position.get<float>();
      body.erase("axis"), body.erase("position");
      const JobInputs inputs = takeInputs(state, body);
      const std::string job = state.jobs->submit("cut", [&state, inputs, axis, fraction](Progress& progress,
                                                                                         const std::string& jobId) {
        const auto started = std::chrono::steady_clock::now();
        const Mesh opened = cutMesh(state, inputs, axis, fraction, progress);
        const std::string id = state.results.put("model/gltf-binary", encodeGltf(opened, true));
        state.events.publish(
            "result", {{"job", jobId},
                       {"kind", "cut"},
                       {"method", inputs.texture.method},
                       {"axis", std::string(1, char('x' + axis))},
                       {"position", fraction},
                       {"url", "/api/results/" + id},
                       {"format", "glb"},
                       {"vertices", opened.vertexCount()},
                       {"mesh", inputs.scene->meshId()},
                       {"seconds", std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count()}});
      });
      sendJson(response, {{"job", job}}, 202);
    });
  });
  router.get(R"(/api/results/([A-Za-z0-9-]+))", [&state](const httplib::Request& request, httplib::Response& response) {
    answer(response, [&] {
      const auto result = state.results.get(request.matches[1]);
      if (!result) throw notFound("result '" + std::string(request.matches[1]) + "'");
      response.set_content(result->bytes, result->contentType);
    });
  });
  router.post("/api/export", json, [&state](const httplib::Request& request, httplib::Response& response) {
    answer(response, [&] {
      nlohmann::json body = jsonBody(request);
      if (!body.is_object() || !body.contains("format") || !body["format"].is_string())
        throw HttpError(400, "give {\"format\": \"glb\"|\"tsfield\"|\"vdb\"|\"sketch\"}");
      const std::string format = body["format"].get<std::string>();
      int resolution = 64;
      if (body.contains("resolution")) {
        if (!body["resolution"].is_number_integer() || body["resolution"].get<std::int64_t>() < 2 ||
            body["resolution"].get<std::int64_t>() > 256)
          throw HttpError(400, "resolution: give a whole number in [2, 256]");
        resolution = body["resolution"].get<int>();
      }
      body.erase("format"), body.erase("resolution");
      std::string bytes, type = "application/octet-stream";
      if (format == "tsfield" || format == "sketch") {
        std::lock_guard<std::mutex> lock(state.mutex);
        const auto scene = state.requireScene();
        bytes = format == "tsfield" ? encodeField(scene->fieldFile()) : encodeSketch(scene->sketch());
        if (format == "sketch") type = "application/json";
      } else if (format == "glb" || format == "vdb") {
        const JobInputs inputs = takeInputs(state, body);
        const auto solid = solidFor(state, inputs, inputs.texture.method, noProgress());
        if (format == "glb") {  // the textured model, as `texsynth solid --mesh M -o model.glb` writes it
          Mesh textured = inputs.scene->display();
          textured.colors = solid->colors(textured.positions, textured.normals, noProgress());
          bytes = encodeGltf(textured, true);
          type = "model/gltf-binary";
        } else {  // the volume over the mesh's box, written by the command line's volume writer
          const Box3f box = inputs.scene->bounds();
          const Volume volume =
              solid->consume(noProgress(), [&](const SolidTexture& s) { return sampleVolume(s, box, resolution); });
          bytes = volumeFileBytes(volume);
        }
      } else {
        throw HttpError(400, "format '" + format + "': give glb, tsfield, vdb or sketch");
      }
      response.set_header("Content-Disposition", "attachment; filename=\"texsynth-studio." +
                                                     std::string(format == "sketch" ? "json" : format) + "\"");
      response.set_content(bytes, type);
    });
  });
}

}  // namespace texsynth::studio
