// Ground truth: high-sample references for many (filter, radius) pairs at
// once, streamed, with their own error estimate, cached by content.
//
// renderReferences() traces refSpp samples per pixel in batches of
// batchSpp from a scrambled low-discrepancy sampler (each batch an
// independent scramble: seed hashWords(seed, batch)). Even batches go into
// accumulator a, odd ones into b (film/film.h Accumulator, double
// precision): two independent halves. The reference is their mean
// G = (Ga + Gb) / 2, and it keeps the half-difference D = (Ga - Gb) / 2:
// per pixel and channel D^2 is an unbiased estimate of Var G, and for two
// references of one pass (same samples, same halves) D_G D_T estimates
// Cov(G, T) (docs/science.md, "The reference is an estimate too"). Its
// scalar error estimate is
//   ref_error = mean over pixels and channels of D^2 = mean (Ga - Gb)^2 / 4,
// the mean variance of G. No sample outlives its batch, so memory is
// independent of refSpp: 2 x width x height x filters x 4 doubles plus one
// batch of samples.
//
// The cache key hashes the scene's content hash (scene and OBJ bytes, size,
// tracing flags), the filter's describe(), refSpp, the sampler, the seed and
// the batch size, and kReferenceAlgorithm, a number raised whenever a code
// change alters what a cache entry holds (so a cache made by older code is
// not reused; 2 since the batched splat, which moved Gaussian and
// Blackman-Harris weights by float ulps; 3 since entries keep D). Each
// reference is stored as <cache>/<key>.exr (G) and <key>.diff.exr (D) beside
// <key>.json (its manifest, study/reference/manifest.h); study/reference/reference_cache.cpp. cachedReferences()
// loads what is there and renders the missing ones together in one pass;
// files are written to a temporary name and renamed, so concurrent shards
// can share a cache. Each manifest records the content hashes of both EXRs
// ("image_hash", "diff_hash"); an entry whose files do not match them
// (replaced, damaged, unreadable, or made before the hash) is not trusted: a note says
// so on stderr and the reference is rendered again.
//
// The filters come as the study's objects (StudyFilter, study/filter_cache.h): a reference splats the very Filter
// it is given, and its describe() keys the cache entry; the (name, radius) is only the manifest's key.
#pragma once
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include "core/files.h"  // writeTextFile
#include "core/image.h"
#include "film/film.h"
#include "study/filter_cache.h"  // StudyFilter: the filters a reference pass splats
#include "study/study_scene.h"

namespace aliaslab {

/// The one default reference sample count of every front end (sweep --ref-spp,
/// reference --spp): 1024 samples per pixel, a reference error well below the
/// measured aliasing at the study's 4..64 spp (see the manifests' error fields).
inline constexpr int kDefaultReferenceSpp = 1024;

struct ReferenceOptions {
  int spp = kDefaultReferenceSpp;                ///< samples per pixel in total (even; a multiple of 2 * batchSpp when >= that)
  std::string sampler = "sobol";  ///< scrambled low-discrepancy sampler
  uint64_t seed = 0x5eed2026;     ///< base seed of the batch scrambles
  int batchSpp = 16;              ///< samples per pixel per batch (memory of one batch)
  int threads = 0;                ///< worker threads (0: all cores)
  bool progress = true;           ///< progress bar on stderr
};

struct ReferenceImage {
  FilterSpec filter;     ///< the (name, radius) of the StudyFilter it was made with: the manifest's key
  std::string describe;  ///< Filter::describe()
  Image image;           ///< G = (Ga + Gb) / 2
  Image halfDiff;        ///< D = (Ga - Gb) / 2: per value, D^2 estimates Var G without bias
  double error = 0;      ///< ref_error: mean (Ga - Gb)^2 / 4
  ReconStats stats;      ///< pixel counts of the resolve (both halves summed)
  std::string key;       ///< cache key, 16 hex digits
  bool fromCache = false;
};

struct ReferenceSet {
  std::vector<ReferenceImage> images;  ///< in the requested order
  double seconds = 0;                  ///< time spent rendering (0 when all came from the cache)
  int spp = 0;
  std::string sampler;
  uint64_t seed = 0;
  size_t accumulatorBytes = 0;         ///< memory held by the accumulators during the pass
  /// Thread-seconds of the pass (0 from the cache): tracing the batches, splatting them into every filter's
  /// two halves, resolving the images (the sweep prints them as the references' phase line).
  double traceSeconds = 0, splatSeconds = 0, resolveSeconds = 0;
};

/// Checks the options (OptionError keyed "ref-spp" / "ref-batch" / the factory's "sampler"): the one check of every front end
/// (study/validate.h validateStudy, the reference program), before any work. renderReferences repeats it as its
/// precondition (cachedReferences through it, when anything is missing).
void validateReferenceOptions(const ReferenceOptions& options);

/// An estimate of the bytes one reference pass over `specs` filters needs at width x height (two batches of samples
/// in flight, the two halves' accumulators, and per reference its mean, half-difference and halves' images), for
/// requireMemory (core/files.h) before any allocation.
double referenceMemoryBytes(int width, int height, size_t specs, const ReferenceOptions& options);

/// The cache key of one reference.
std::string referenceKey(const StudyScene& scene, const std::string& filterDescribe, const ReferenceOptions& options);

/// Renders every filter in one streamed pass (no cache); `keys[i]` is filters[i]'s referenceKey (computed once by
/// the caller).
ReferenceSet renderReferences(const StudyScene& scene, const std::vector<StudyFilter>& filters,
                              const ReferenceOptions& options, const std::vector<std::string>& keys);
/// The same, with the keys computed here.
ReferenceSet renderReferences(const StudyScene& scene, const std::vector<StudyFilter>& filters,
                              const ReferenceOptions& options);

/// Loads cached references from `cacheDir`, renders the missing ones in one
/// pass and stores them. Throws FileError when the cache cannot be written.
ReferenceSet cachedReferences(const StudyScene& scene, const std::vector<StudyFilter>& filters,
                              const ReferenceOptions& options, const std::string& cacheDir);

/// The content hash stored in a cache manifest ("image_hash"): 16 hex digits of hashBytes over the file's bytes.
std::string imageContentHash(const std::string& path);

/// The scene path a manifest stores: relative to the repository (e.g.
/// "scenes/fence.txt") for a scene inside it, so manifests do not carry the
/// machine's absolute paths; a scene elsewhere keeps the path as given.
std::string manifestScenePath(const std::string& path);

/// `git rev-parse HEAD` of the source tree at run time, else "unknown".
std::string gitRevision();


}  // namespace aliaslab
