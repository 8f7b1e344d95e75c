#include "study/reference.h"

#include "aliaslab_paths.h"

#include <algorithm>
#include <chrono>
#include <cinttypes>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <memory>
#include <sstream>

#include "core/parallel.h"
#include "core/error.h"
#include "core/hash.h"
#include "core/format.h"
#include "core/progress.h"
#include "core/stopwatch.h"
#include "film/film.h"
#include "filter/filter.h"
#include "measure/metrics.h"
#include "render/render.h"
#include "sampling/sampler.h"

namespace aliaslab {

namespace fs = std::filesystem;

namespace {
std::string hex16(uint64_t v) {
  char buf[20];
  std::snprintf(buf, sizeof buf, "%016" PRIx64, v);
  return buf;
}

std::string jsonString(const std::string& s) {
  std::string out = "\"";
  for (char c : s) {
    if (c == '"' || c == '\\') out += '\\', out += c;
    else if (static_cast<unsigned char>(c) < 0x20) out += ' ';
    else out += c;
  }
  return out + "\"";
}

std::string jsonNumber(double v) { return formatNumber(v, "%.9g"); }

// The batch size actually used: at most half the total, so there are two halves.
int effectiveBatch(const ReferenceOptions& o) { return std::min(o.batchSpp, o.spp / 2); }

}  // namespace

double referenceMemoryBytes(int width, int height, size_t specs, const ReferenceOptions& o) {
  const double pixels = double(width) * height;
  const double batches = 2.0 * std::max(1, effectiveBatch(o)) * sizeof(FilmSample);  // two halves trace at once
  const double accumulators = 2.0 * double(specs + 1) * 4 * sizeof(double);
  const double images = double(specs) * 4 * 3 * sizeof(float);  // mean, half-difference, the two halves
  return pixels * (batches + accumulators + images);
}

void validateReferenceOptions(const ReferenceOptions& o) {
  if (o.spp < 2 || o.spp % 2) throw OptionError("ref-spp", "must be an even number >= 2, found " + std::to_string(o.spp));
  if (o.batchSpp < 1) throw OptionError("ref-batch", "must be >= 1");
  const int batch = effectiveBatch(o);
  if (o.spp % batch || (o.spp / batch) % 2)
    throw OptionError("ref-spp", "must be a multiple of 2 x " + std::to_string(o.batchSpp) +
                                       " (two equal halves of whole batches), found " + std::to_string(o.spp));
  makeSampler(o.sampler, batch, o.seed);  // names the valid samplers when unknown
}

std::string referenceKey(const StudyScene& scene, const std::string& filterDescribe, const ReferenceOptions& o) {
  constexpr uint64_t kReferenceAlgorithm = 3;  // see reference.h
  uint64_t h = hashWords(scene.contentHash, o.spp, o.seed, effectiveBatch(o), kReferenceAlgorithm);
  h = hashBytes(filterDescribe, h);
  h = hashBytes(o.sampler, h);
  return hex16(h);
}

std::string gitRevision() {
  const std::string cmd = std::string("git -C '") + ALIASLAB_SOURCE_DIR + "' rev-parse HEAD 2>/dev/null";
  std::unique_ptr<FILE, int (*)(FILE*)> pipe(::popen(cmd.c_str(), "r"), ::pclose);
  if (!pipe) return "unknown";
  char buf[128] = {0};
  if (!std::fgets(buf, sizeof buf, pipe.get())) return "unknown";
  std::string rev(buf);
  while (!rev.empty() && (rev.back() == '\n' || rev.back() == '\r')) rev.pop_back();
  return rev.size() == 40 ? rev : "unknown";
}

ReferenceSet renderReferences(const StudyScene& scene, const std::vector<FilterSpec>& specs,
                              const ReferenceOptions& o) {
  validateReferenceOptions(o);
  const auto start = std::chrono::steady_clock::now();
  std::vector<std::unique_ptr<Filter>> filters;
  std::vector<const Filter*> raw;
  for (const auto& [name, r] : specs) {
    filters.push_back(makeFilter(name, static_cast<float>(r)));
    raw.push_back(filters.back().get());
  }

  // Two independent halves: even batches into a, odd batches into b.
  Accumulator a(scene.width, scene.height, raw), b(scene.width, scene.height, raw);
  const int batch = effectiveBatch(o);
  const int batches = o.spp / batch;
  ProgressBar progress(batches, "reference " + scene.stem, o.progress);
  // Batches k (even, into a) and k + 1 (odd, into b) run as two concurrent tasks, each on half the threads:
  // each half still receives its batches in k order, so the sums are those of the serial loop, bit for bit.
  const int inner = std::max(1, resolveThreads(o.threads) / 2);
  double traced[2] = {0, 0}, splatted[2] = {0, 0};  // thread-seconds per half (each task writes its own)
  for (int k = 0; k < batches; k += 2) {
    parallelFor(std::min(2, batches - k), std::min(2, resolveThreads(o.threads)), [&](int half) {
      const auto sampler = makeSampler(o.sampler, batch, hashWords(o.seed, k + half));
      const Stopwatch trace;
      const SampleBuffer samples = traceSamples(*scene.tracer, *sampler, scene.width, scene.height, inner);
      traced[half] += trace.seconds() * inner;
      const Stopwatch splat;
      (half ? b : a).add(samples, inner);
      splatted[half] += splat.seconds() * inner;
    });
    progress.advance(std::min(2, batches - k));
  }
  progress.finish();

  // G = (Ga + Gb) / 2 with the variance of that mean as its error.
  const Stopwatch resolve;
  ReferenceSet set;
  set.spp = o.spp, set.sampler = o.sampler, set.seed = o.seed;
  set.traceSeconds = traced[0] + traced[1], set.splatSeconds = splatted[0] + splatted[1];
  set.accumulatorBytes = a.bytes() + b.bytes();
  for (size_t i = 0; i < specs.size(); ++i) {
    Reconstruction ra = a.resolve(i), rb = b.resolve(i);
    ReferenceImage ref;
    ref.filter = specs[i];
    ref.describe = filters[i]->describe();
    ref.image = averageImages(ra.image, rb.image);
    ref.halfDiff = halfDifference(ra.image, rb.image);
    ref.error = halvesError(ra.image, rb.image);
    ref.stats = ra.stats;
    ref.stats += rb.stats;
    ref.key = referenceKey(scene, ref.describe, o);
    if (ref.stats.nonFiniteSamples > 0)  // left out of the sums, so the pixels may look finite (often black)
      throw InputError(scene.path + ": the reference (" + ref.describe + ") met " +
                       std::to_string(ref.stats.nonFiniteSamples) + " NaN or infinite samples (lights or colours "
                       "whose products exceed float range, about 3.4e38?); nothing can be measured against it");
    if (const size_t bad = countNonFinitePixels(ref.image))
      throw InputError(scene.path + ": the reference (" + ref.describe + ") has " + std::to_string(bad) +
                       " NaN or infinite pixels (lights or colours whose products exceed float range, about "
                       "3.4e38?); nothing can be measured against it");
    set.images.push_back(std::move(ref));
  }
  set.resolveSeconds = resolve.seconds();
  set.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return set;
}

std::string manifestScenePath(const std::string& path) {
  namespace fs = std::filesystem;
  std::error_code ec;
  const fs::path repo = fs::weakly_canonical(ALIASLAB_SOURCE_DIR, ec);
  const fs::path p = ec ? fs::path() : fs::weakly_canonical(fs::absolute(path), ec);
  if (ec || p.empty()) return path;
  const fs::path rel = p.lexically_relative(repo);
  const bool inside = !rel.empty() && *rel.begin() != "..";
  return inside ? rel.generic_string() : path;
}

std::string imageContentHash(const std::string& path) { return hex16(hashBytes(readFileBytes(path), 0x1a6e)); }

std::string referenceManifest(const StudyScene& scene, const ReferenceSet& set,
                              const std::vector<std::string>& imageNames,
                              const std::vector<std::string>& imageHashes,
                              const std::vector<std::string>& diffHashes) {
  std::ostringstream j;
  j << "{\n  \"scene\": " << jsonString(scene.stem) << ",\n  \"scene_path\": " << jsonString(manifestScenePath(scene.path))
    << ",\n  \"width\": " << scene.width << ",\n  \"height\": " << scene.height
    << ",\n  \"tracing\": " << jsonString(describeTraceOptions(scene.options));
  if (scene.filmOffset[0] != 0 || scene.filmOffset[1] != 0)  // a shifted camera (study/alignment.h)
    j << ",\n  \"film_offset\": [" << jsonNumber(scene.filmOffset[0]) << ", " << jsonNumber(scene.filmOffset[1]) << "]";
  j << ",\n  \"spp\": " << set.spp
    << ",\n  \"sampler\": " << jsonString(set.sampler) << ",\n  \"seed\": " << set.seed
    << ",\n  \"git_revision\": " << jsonString(gitRevision()) << ",\n  \"seconds\": " << jsonNumber(set.seconds)
    << ",\n  \"filters\": [";
  for (size_t i = 0; i < set.images.size(); ++i) {
    const ReferenceImage& r = set.images[i];
    j << (i ? "," : "") << "\n    {\"filter\": " << jsonString(r.filter.first) << ", \"radius\": "
      << jsonNumber(r.filter.second) << ", \"describe\": " << jsonString(r.describe)
      << ", \"ref_error\": " << jsonNumber(r.error) << ", \"undefined_pixels\": " << r.stats.undefinedPixels
      << ", \"key\": " << jsonString(r.key) << ", \"image\": " << jsonString(i < imageNames.size() ? imageNames[i] : "");
    if (i < imageHashes.size()) j << ", \"image_hash\": " << jsonString(imageHashes[i]);
    if (i < diffHashes.size()) j << ", \"diff_hash\": " << jsonString(diffHashes[i]);
    j << "}";
  }
  j << "\n  ]\n}\n";
  return j.str();
}

}  // namespace aliaslab
