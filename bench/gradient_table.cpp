// Table 1 of the gradient-solid paper on our volumes, next to two baselines at the same bytes, then
// evaluation speeds and the edit of §4.4 against its raster. Usage (bench/gradient_table.sh runs it on the test
// volumes):
//   gradient_table [--threads N] [--speed-points N] [--no-edit] NAME=VOLUME.nrrd[,MASK.nrrd] ...
#include <algorithm>
#include <cstdio>
#include <exception>
#include <memory>
#include <string>
#include <vector>

#include "gradient_baselines.h"
#include "gradient_edit_speed.h"
#include "gradient_eval_speed.h"
#include "texsynth/core/parallel.h"
#include "texsynth/gradient/gradient_solid_file.h"
#include "texsynth/gradient/vectorize.h"
#include "texsynth/io/volume_io.h"

namespace {

using namespace texsynth;

struct Entry {
  std::string name, volume, mask;
};

Entry parseEntry(const std::string& argument) {
  const auto equals = argument.find('='), comma = argument.find(',');
  if (equals == std::string::npos) throw ParameterError(argument, "expected NAME=VOLUME.nrrd[,MASK.nrrd]");
  Entry entry{argument.substr(0, equals), argument.substr(equals + 1, comma - equals - 1), ""};
  if (comma != std::string::npos) entry.mask = argument.substr(comma + 1);
  return entry;
}

// One table row; `notes` gets the settings behind its numbers. Returns the first-order solid.
GradientSolid measure(const Entry& entry, std::vector<std::string>& notes) {
  const Volume volume = readVolume(entry.volume);
  const Volume mask = entry.mask.empty() ? Volume() : readVolume(entry.mask);
  VectorizeReport first, optimized;
  GradientSolid solid = vectorizeVolume(volume, mask, VectorizeOptions{.optimize = false}, &first);
  vectorizeVolume(volume, mask, VectorizeOptions{.optimize = true}, &optimized);
  const std::uint64_t bytes = gradientSolidFileBytes(solid), raw = rawVolumeBytes(solid);
  const bench::BaselineResult down = bench::downsampleBaseline(volume, solid.channels, bytes);
  const bench::BaselineResult zfp = bench::zfpBaseline(volume, solid.channels, bytes);
  std::printf("| %s | %s | %.2f | %.2f | %.2f | %.2f | %.2f | %.2f | %.2f | %.3f |\n", entry.name.c_str(),
              entry.mask.empty() ? "no" : "yes", 100.0 * double(bytes) / double(raw), first.rms, first.totalSeconds,
              optimized.rms, optimized.totalSeconds, down.rms, zfp.rms, zfp.seconds);
  std::fflush(stdout);
  char note[512];
  std::snprintf(
      note, sizeof note,
      "%s: %dx%dx%d x %d channels, .tsgs %llu of %llu bytes, %lld boundary controls; downsampled to "
      "%s (%llu bytes); zfp at %s (%llu bytes)",
      entry.name.c_str(), volume.nx, volume.ny, volume.nz, solid.channels, static_cast<unsigned long long>(bytes),
      static_cast<unsigned long long>(raw), static_cast<long long>(first.boundaryControls), down.setting.c_str(),
      static_cast<unsigned long long>(down.bytes), zfp.setting.c_str(), static_cast<unsigned long long>(zfp.bytes));
  notes.emplace_back(note);
  return solid;
}

}  // namespace

int main(int argc, char** argv) {
  try {
    int threads = 0;
    std::int64_t speedPoints = 10'000'000;
    bool edit = true;  // time §4.4's edit on a volume's solid magnified to 512^3
    std::vector<Entry> entries;
    for (int i = 1; i < argc; ++i) {
      const std::string argument = argv[i];
      if (argument == "--threads" && i + 1 < argc)
        threads = std::stoi(argv[++i]);
      else if (argument == "--speed-points" && i + 1 < argc)
        speedPoints = std::stoll(argv[++i]);
      else if (argument == "--no-edit")
        edit = false;
      else
        entries.push_back(parseEntry(argument));
    }
    if (entries.empty()) {
      std::fprintf(stderr,
                   "usage: gradient_table [--threads N] [--speed-points N] [--no-edit] NAME=VOLUME[,MASK] ...\n");
      return 2;
    }
    const ThreadLimit limit(threads);
    std::printf(
        "Vectorization (spacing 4, 8-bit .tsgs), %d threads; RMS on 0..255; seconds: vectorization "
        "(first order / with eq. 3 refinement) and zfp compression\n\n",
        threadLimit());
    std::printf(
        "| volume | mask | bytes %% | RMS first-order | s | RMS optimized | s | RMS downsample | RMS zfp | "
        "zfp s |\n|---|---|---:|---:|---:|---:|---:|---:|---:|---:|\n");
    std::vector<std::string> notes;
    std::vector<std::unique_ptr<GradientSolid>> solids;
    for (const Entry& entry : entries) solids.push_back(std::make_unique<GradientSolid>(measure(entry, notes)));
    std::printf("\n");
    for (const std::string& note : notes) std::printf("- %s\n", note.c_str());
    if (speedPoints > 0) {
      std::vector<std::pair<std::string, const GradientSolid*>> named;
      for (std::size_t i = 0; i < entries.size(); ++i) named.emplace_back(entries[i].name, solids[i].get());
      std::printf("\n");
      bench::printEvaluationSpeeds(named, speedPoints);
    }
    if (edit) {
      std::printf("\n");
      // The first solid without regions (the magnified copy keeps one region).
      const auto plain = std::find_if(solids.begin(), solids.end(), [](const auto& s) { return !s->hasRegions(); });
      bench::printEditSpeeds(plain != solids.end() ? **plain : *solids.front());
    }
    return 0;
  } catch (const std::exception& error) {
    std::fprintf(stderr, "gradient_table: %s\n", error.what());
    return 1;
  }
}
