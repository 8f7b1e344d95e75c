// The reference cache: <cache>/<key>.exr (G), <key>.diff.exr (D = (Ga - Gb) / 2) and <key>.json (the manifest
// with both images' content hashes); see study/reference/reference.h.
#include <cstdio>
#include <filesystem>
#include <string>
#include <vector>

#include "core/error.h"
#include "core/files.h"
#include "core/format.h"
#include "core/parallel.h"
#include "study/reference/manifest.h"
#include "study/reference/reference.h"

namespace aliaslab {

namespace fs = std::filesystem;

ReferenceSet cachedReferences(const StudyScene& scene, const std::vector<StudyFilter>& filters,
                              const ReferenceOptions& o, const std::string& cacheDir) {
  std::error_code ec;
  fs::create_directories(cacheDir, ec);
  ReferenceSet set;
  set.spp = o.spp, set.sampler = o.sampler, set.seed = o.seed;
  set.images.resize(filters.size());
  std::vector<std::string> describe, keys;  // each filter's, computed once
  for (const StudyFilter& f : filters) {
    describe.push_back(f.filter->describe());
    keys.push_back(referenceKey(scene, describe.back(), o));
  }

  // A folder, FIFO or device where an entry's file should be is refused before anything reads or renders (a FIFO
  // would block the reader; a folder cannot be replaced).
  for (const std::string& key : keys)
    for (const char* ext : {".exr", ".diff.exr", ".json"})
      requireRegularFile((fs::path(cacheDir) / (key + ext)).string(),
                         "the reference cache keeps an entry there; remove it or give another cache folder");
  // Load what the cache holds: one task per entry (each reads two files and writes only its own slot).
  std::vector<char> cached(filters.size(), 0);
  parallelFor(int(filters.size()), o.threads, [&](int i) {
    const std::string& key = keys[i];
    const fs::path exr = fs::path(cacheDir) / (key + ".exr"), json = fs::path(cacheDir) / (key + ".json");
    const fs::path diff = fs::path(cacheDir) / (key + ".diff.exr");
    if (!fs::exists(exr) || !fs::exists(json)) return;
    try {
      ReferenceImage& r = set.images[i];
      const Manifest manifest = readManifest(readFileBytes(json.string()), json.string());
      if (manifest.filters.size() != 1) throw FileError(json.string(), "a cache manifest holds one filter entry");
      const ManifestFields& entry = manifest.filters[0];
      const std::string stored = manifestValue(entry, "image_hash"), actual = imageContentHash(exr.string());
      if (stored != actual) {
        std::fprintf(stderr, "note: cached reference %s does not match its manifest %s (%s); rendering it again\n",
                     exr.string().c_str(), json.string().c_str(),
                     stored.empty() ? "no content hash" : "content hash differs");
        return;
      }
      const std::string storedDiff = manifestValue(entry, "diff_hash");
      if (!fs::exists(diff) || storedDiff != imageContentHash(diff.string())) {
        std::fprintf(stderr, "note: cached reference %s has no matching half-difference image %s (%s); rendering it again\n",
                     exr.string().c_str(), diff.string().c_str(),
                     storedDiff.empty() ? "made before references kept their halves" : "content hash differs");
        return;
      }
      r.image = readImage(exr.string());
      r.halfDiff = readImage(diff.string());
      r.error = parseFiniteNumber(manifestValue(entry, "ref_error"));
      if (r.error >= 0 && r.image.width() == scene.width && r.image.height() == scene.height &&
          r.halfDiff.width() == scene.width && r.halfDiff.height() == scene.height) {
        r.filter = filters[i].spec, r.describe = describe[i], r.key = key, r.fromCache = true;
        cached[i] = 1;
      }
    } catch (const InputError& e) {  // an unreadable entry: rendered again (its slot is overwritten below)
      std::fprintf(stderr, "note: cached reference %s is unreadable (%s); rendering it again\n", exr.string().c_str(),
                   e.what());
    }
  });
  std::vector<StudyFilter> missing;
  std::vector<std::string> missingKeys;
  std::vector<size_t> missingIndex;
  for (size_t i = 0; i < filters.size(); ++i)
    if (!cached[i]) missing.push_back(filters[i]), missingKeys.push_back(keys[i]), missingIndex.push_back(i);
  if (missing.empty()) return set;

  // Render the missing ones together and store each with its manifest.
  ReferenceSet fresh = renderReferences(scene, missing, o, missingKeys);
  set.seconds = fresh.seconds;
  set.accumulatorBytes = fresh.accumulatorBytes;
  set.traceSeconds = fresh.traceSeconds, set.splatSeconds = fresh.splatSeconds, set.resolveSeconds = fresh.resolveSeconds;
  for (size_t m = 0; m < missing.size(); ++m) {
    ReferenceImage& r = fresh.images[m];
    const std::string exr = (fs::path(cacheDir) / (r.key + ".exr")).string();
    const std::string diff = (fs::path(cacheDir) / (r.key + ".diff.exr")).string();
    writeImage(exr, r.image);
    writeImage(diff, r.halfDiff);
    ReferenceSet one;
    one.spp = fresh.spp, one.sampler = fresh.sampler, one.seed = fresh.seed, one.seconds = fresh.seconds;
    one.images = {r};
    writeTextFile((fs::path(cacheDir) / (r.key + ".json")).string(),
                  referenceManifest(scene, one, {r.key + ".exr"}, {imageContentHash(exr)}, {imageContentHash(diff)}));
    set.images[missingIndex[m]] = std::move(r);
  }
  return set;
}

}  // namespace aliaslab
