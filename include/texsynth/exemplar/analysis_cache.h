#pragma once
// Disk cache of exemplar analyses. A file is keyed by a digest of the exemplar's pixels,
// every analysis option and the format version; on load its magic, version, key, sizes and
// a checksum of the whole payload are verified, and anything that does not match is
// recomputed, never trusted. Files are written atomically.
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>

#include "texsynth/exemplar/analysis.h"

namespace texsynth {

// Bump whenever the analysis results or the file layout change.
inline constexpr std::uint32_t kAnalysisCacheFormatVersion = 2;

// Digest of (format version, exemplar size and pixels, every field of `options`).
std::uint64_t analysisCacheKey(const Image& exemplar, const AnalysisOptions& options);

// "<cacheDirectory>/exemplar-<16 hex digits>.tsxa".
std::string analysisCachePath(const std::string& cacheDirectory, std::uint64_t key);

// The file image of an analysis (header + payload + checksum).
std::string serializeAnalysis(const ExemplarAnalysis& analysis, std::uint64_t key);

// Parses serializeAnalysis's bytes; nullopt if the bytes are truncated, corrupted, of
// another format version, or were stored under another key.
std::optional<ExemplarAnalysis> deserializeAnalysis(std::string_view bytes, std::uint64_t expectedKey);

// Reads a cache file; nullopt if it is missing or fails any check of deserializeAnalysis.
std::optional<ExemplarAnalysis> loadCachedAnalysis(const std::string& path, std::uint64_t expectedKey);

// analyzeExemplar through the cache: returns the cached result when a valid file exists,
// otherwise analyzes and (re)writes the file atomically. Creates cacheDirectory if needed;
// throws OutputError if it cannot be created or written, ParameterError for bad options.
ExemplarAnalysis analyzeExemplarCached(const Image& exemplar, const AnalysisOptions& options,
                                       const std::string& cacheDirectory, Progress& progress = noProgress());

}  // namespace texsynth
