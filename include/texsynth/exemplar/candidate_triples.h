#pragma once
// Candidate triples for lazy solid synthesis (Dong et al. 2008; sketch-guided solid texturing
// §2, §4.3): for every pixel of each of the three plane exemplars, the N_T coordinate triples
// (one pixel in each of I_xy, I_yz, I_zx) containing that pixel whose crossbars agree best,
// filtered for spatial consistency with a neighbouring pixel. The correction step draws its
// candidate set S(v) from these lists; initialization tiles the candidate slabs.
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "texsynth/core/image.h"
#include "texsynth/core/progress.h"

namespace texsynth {

// Pixel indices (y * width + x) into the exemplars of the three planes. Plane axes (eq. 4):
// I_xy has (u, v) = (x, y), I_yz has (u, v) = (y, z), I_zx has (u, v) = (z, x).
struct CoordinateTriple {
  std::int32_t xy = 0, yz = 0, zx = 0;
  friend bool operator==(const CoordinateTriple&, const CoordinateTriple&) = default;
};

enum class Plane { XY = 0, YZ = 1, ZX = 2 };

struct CandidateTripleOptions {
  int count = 12;            // N_T (paper)
  int neighborhoodSize = 9;  // N: crossbars have N samples, `spacing` apart (odd)
  int searchWidth = 24;      // k nearest crossbars tried per axis when pairing (speed/quality knob; capped at
                             // the pixel count)
  // The best `refineTriples` triples of each pixel get each partner re-searched with both of its
  // crossbars at once (the other two coordinates fixed); 0 turns this off (faster, worse).
  int refineTriples = 2;
  // Spatial consistency (the paper asks for triples "spatially consistent with at least one
  // neighbouring pixel"; our concrete rule): a triple T of pixel p in plane P is consistent if
  // for one of the four in-plane directions e, the shifted triple T + h e (eq. 4), which is a
  // triple of the neighbour q = p + h e, has crossbar error <= consistencyFactor * (best error
  // found for q) + 1e-6. Inconsistent triples only fill the list when fewer than `count` pass.
  // Must be >= 1; infinity turns the filter off.
  float consistencyFactor = 2.0f;
};

struct CandidateTriples {
  int width = 0, height = 0, count = 0;
  int neighborhoodSize = 0;                  // N the crossbars were compared with (bounds slab offsets)
  std::vector<CoordinateTriple> triples[3];  // per plane: pixelCount * count, best first
  std::vector<float> errors[3];              // matching crossbar error of each entry (L1 RGB, mean per sample)

  std::int64_t pixelCount() const { return std::int64_t(width) * height; }
  // The `count` triples whose `plane` coordinate is `pixel` (the pixel itself), best first.
  const CoordinateTriple* at(Plane plane, std::int32_t pixel) const;
  const float* errorsAt(Plane plane, std::int32_t pixel) const;
};

// Candidate triples of one Gaussian-stack level: xy, yz, zx are that level's images (same size and channels; one
// image may serve all three), crossbars sampled `spacing` (h_l) apart, toroidally. The error compares every channel
// equally (RGB, plus a feature channel when the images carry one: scale it beforehand to weight it).
// Per pixel: the 2 * count lowest-error triples the search finds (partners shortlisted by approximate KD search on
// 8-D PCA crossbar vectors, ranked by the exact error, best 2 refined), then the `count` best that pass the
// consistency rule, topped up with the best that fail it, ascending by error. Deterministic, thread-count
// independent. ParameterError for mismatched sizes / bad options.
CandidateTriples computeCandidateTriples(const Image& xy, const Image& yz, const Image& zx, int spacing,
                                         const CandidateTripleOptions& options = {}, Progress& progress = noProgress());

// Throws ParameterError naming the bad argument: an empty image, images of different sizes or channel counts,
// spacing < 1, or options out of range (count < 1, even or non-positive N, searchWidth < 1, a consistency
// factor below 1 or NaN, or more triples asked for than searchWidth^2 pairs can provide).
void validateCandidateTripleInputs(const Image& xy, const Image& yz, const Image& zx, int spacing,
                                   const CandidateTripleOptions& options);

// Pixel index `pixel` moved by (du, dv), wrapped toroidally in a width x height exemplar.
std::int32_t offsetPixel(std::int32_t pixel, int width, int height, int du, int dv);

// Eq. 4 on pixel indices: T + (dx, dy, dz) = (T_xy + (dx, dy), T_yz + (dy, dz), T_zx + (dz, dx)), each wrapped
// toroidally in a width x height exemplar.
CoordinateTriple offsetTriple(const CoordinateTriple& triple, int width, int height, int dx, int dy, int dz);

// Crossbar error of any triple: the mean over the 3N crossbar samples (N per axis, `spacing` apart) of the L1
// distance over all channels, exactly as computeCandidateTriples stores it. Same validation.
float crossbarError(const Image& xy, const Image& yz, const Image& zx, const CoordinateTriple& triple, int spacing,
                    int neighborhoodSize);

// The candidate slab of a pixel: the first triple of `pixel` in `plane` thickened along the plane's normal axis by
// the stick orthogonal to it (see paper §2). Returns the triple at offset t (in units of `spacing`, |t| <= N/2)
// along the normal: i.e. the coordinate triple of voxel v + t*normal in a slab built from that first triple.
// The normals are z for XY, x for YZ and y for ZX; ParameterError for a pixel out of range or
// |t| > triples.neighborhoodSize / 2.
CoordinateTriple slabTriple(const CandidateTriples& triples, Plane plane, std::int32_t pixel, int t, int spacing);

// ---- Cache: files keyed by the images' pixels, spacing and options, next to the exemplar analyses
// ("<dir>/triples-<16 hex>.tsxt"), versioned and checksummed; anything that fails a check is recomputed.

// Bump whenever the results or the file layout change.
inline constexpr std::uint32_t kCandidateTriplesFormatVersion = 1;

std::uint64_t candidateTriplesCacheKey(const Image& xy, const Image& yz, const Image& zx, int spacing,
                                       const CandidateTripleOptions& options);
std::string candidateTriplesCachePath(const std::string& cacheDirectory, std::uint64_t key);
std::string serializeCandidateTriples(const CandidateTriples& triples, std::uint64_t key);
// nullopt if the bytes are truncated, corrupted, of another version or stored under another key.
std::optional<CandidateTriples> deserializeCandidateTriples(std::string_view bytes, std::uint64_t expectedKey);
std::optional<CandidateTriples> loadCachedCandidateTriples(const std::string& path, std::uint64_t expectedKey);
// computeCandidateTriples through the cache; (re)writes the file atomically on a miss. Creates cacheDirectory;
// OutputError if it cannot be created or written.
CandidateTriples computeCandidateTriplesCached(const Image& xy, const Image& yz, const Image& zx, int spacing,
                                               const CandidateTripleOptions& options, const std::string& cacheDirectory,
                                               Progress& progress = noProgress());

}  // namespace texsynth
