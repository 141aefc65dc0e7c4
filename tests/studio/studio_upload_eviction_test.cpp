// A long session's uploads do not pile up: the studio keeps the most recently used few of each kind
// (--keep-uploads) and forgets the rest with their files and solids, except what the scene uses.
#include <gtest/gtest.h>
#include <malloc.h>
#include <unistd.h>

#include <fstream>
#include <set>

#include "studio_test_server.h"
#include "texsynth/io/image_io.h"

namespace texsynth::studio::test {
namespace {

// This process's resident memory, after handing freed heap back to the system.
double residentMiB() {
  malloc_trim(0);
  std::ifstream statm("/proc/self/statm");
  long pages = 0, resident = 0;
  statm >> pages >> resident;
  return double(resident) * double(::sysconf(_SC_PAGESIZE)) / (1 << 20);
}

int uploadsInCatalog(TestStudio& studio) {
  int uploads = 0;
  const nlohmann::json catalog = studio.get("/api/catalog");
  for (const char* kind : {"meshes", "exemplars"})
    for (const auto& entry : catalog[kind]) uploads += entry["group"] == "uploads";
  return uploads;
}

TEST(StudioUploadEviction, AHundredUploadsEndWhereTheyStarted) {
  TestStudio studio;
  const auto upload = [&](int i) {
    const std::string png = encodePngBytes(texsynth::test::makeTestPattern(64, 64, unsigned(i)));
    return studio.call("POST", "/api/uploads/exemplar?format=png&name=u" + std::to_string(i), png, 201)["id"]
        .get<std::string>();
  };
  const auto preview = [&](const std::string& exemplar) {
    studio.waitForResult(studio.post("/api/preview", {{"exemplar", exemplar}}, 202)["job"], "final");
  };
  for (int i = 0; i < 10; ++i) preview(upload(i));  // warm: thread pools, allocator arenas, kept solids
  const double before = residentMiB();
  const double filesBefore = studio.get("/api/health")["uploads_mib"].get<double>();
  std::vector<std::string> ids;
  for (int i = 0; i < 100; ++i) {
    ids.push_back(upload(100 + i));
    if (i % 10 == 9) preview(ids.back());
  }
  studio.server().jobs().waitIdle();
  const double after = residentMiB();
  const nlohmann::json health = studio.get("/api/health");
  std::printf("resident memory %.1f MiB before the 100 uploads, %.1f MiB after; upload files %.2f -> %.2f MiB\n",
              before, after, filesBefore, health["uploads_mib"].get<double>());
  // AddressSanitizer holds freed memory back (its quarantine, up to 256 MiB): there RSS is only shown.
#ifndef __SANITIZE_ADDRESS__
  EXPECT_LE(after, before * 1.2) << "within 20% of where it started";
#endif
  EXPECT_LE(health["uploads_mib"].get<double>(), filesBefore * 1.2 + 0.05);

  // The default --keep-uploads, besides the scene's exemplar (the last preview's, also among the newest).
  EXPECT_EQ(health["uploads"], 9);
  EXPECT_EQ(uploadsInCatalog(studio), 9);
  studio.get("/api/exemplars/" + ids.back() + "/image", 200);
  studio.get("/api/exemplars/" + ids.front() + "/image", 404);
}

TEST(StudioUploadEviction, TheLimitIsPerKindAndTheScenesUploadsStay) {
  UploadLimits limits;
  limits.keptUploads = 2;
  TestStudio studio(limits);
  const std::string box =
      "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nv 0 0 1\nv 1 0 1\nv 1 1 1\nv 0 1 1\n"
      "f 1 3 2\nf 1 4 3\nf 5 6 7\nf 5 7 8\nf 1 2 6\nf 1 6 5\nf 2 3 7\nf 2 7 6\nf 3 4 8\nf 3 8 7\nf 4 1 5\nf 4 5 8\n";
  const std::string png = encodePngBytes(texsynth::test::makeTestPattern(16, 16));
  std::vector<std::string> meshes, exemplars;
  const auto upload = [&](int count) {
    for (int i = 0; i < count; ++i) {
      meshes.push_back(studio.call("POST", "/api/uploads/mesh?format=obj", box, 201)["id"]);
      exemplars.push_back(studio.call("POST", "/api/uploads/exemplar?format=png", png, 201)["id"]);
    }
  };
  upload(2);
  studio.post("/api/scene", {{"mesh", meshes[0]}, {"exemplar", exemplars[0]}}, 200);
  upload(3);
  const auto kept = [&](const char* kind) {
    std::set<std::string> ids;
    const nlohmann::json catalog = studio.get("/api/catalog");
    for (const auto& entry : catalog[kind])
      if (entry["group"] == "uploads") ids.insert(entry["id"].get<std::string>());
    return ids;
  };
  EXPECT_EQ(kept("meshes"), (std::set<std::string>{meshes[0], meshes[3], meshes[4]})) << "the scene's, the newest two";
  EXPECT_EQ(kept("exemplars"), (std::set<std::string>{exemplars[0], exemplars[3], exemplars[4]}));
  EXPECT_EQ(studio.get("/api/health")["uploads"], 6);
  studio.post("/api/scene", {{"mesh", meshes[1]}}, 404);
  studio.get("/api/exemplars/" + exemplars[1] + "/image", 404);
  studio.get("/api/exemplars/" + exemplars[0] + "/image", 200);
}

}  // namespace
}  // namespace texsynth::studio::test
