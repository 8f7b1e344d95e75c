// The reference manifest: the JSON beside every reference (the cache's <key>.json, the sweep's
// OUT/references/<scene>.json, the reference program's manifest.json), written and read here only.
//
// Layout (one field a line, one filter entry a line, so that a diff reads well):
//   {
//     "scene": "fence",
//     ...                       the study-wide fields, in order
//     "filters": [
//       {"filter": "box", "radius": 0.5, ...},
//       ...
//     ]
//   }
// A value is a JSON string ('"' and '\' escaped, control characters written as spaces), a number as written
// (reals by formatReal, core/format.h) or a list of numbers ("film_offset": [x, y]) kept as its text.
// referenceManifest() fills one from a reference set (the fields are listed in study/reference/reference.h);
// readManifest() is the one parser: the cache reads an entry's content hashes and error through it, the inspect
// program's summary (study/reference/manifest_summary.h) its fields.
#pragma once
#include <string>
#include <vector>

#include "study/reference/reference.h"
#include "study/study_scene.h"

namespace aliaslab {

struct ManifestField {
  std::string key;
  std::string value;    ///< a string's characters, or a number's (a number list's) text as written
  bool quoted = true;   ///< a JSON string (else a number or a list of numbers)
};
using ManifestFields = std::vector<ManifestField>;

struct Manifest {
  ManifestFields head;                  ///< the study-wide fields, in order
  std::vector<ManifestFields> filters;  ///< one entry per reference, in order
};

/// The value of `key` among `fields` ("" when absent).
std::string manifestValue(const ManifestFields& fields, const std::string& key);

/// The text of `manifest` in the layout above.
std::string writeManifest(const Manifest& manifest);

/// The manifest in `json`; throws FileError naming `path` and the character where the text stops being one.
Manifest readManifest(const std::string& json, const std::string& path);

/// The manifest of a reference set: scene, size, flags, spp, sampler, seed, git revision, seconds, and per filter
/// describe(), ref_error, key, image file. `imageNames[i]` is the image file of filter i as a path from the
/// manifest's folder ("" for none); `imageHashes` / `diffHashes` the cache's content hashes of both EXRs.
std::string referenceManifest(const StudyScene& scene, const ReferenceSet& set,
                              const std::vector<std::string>& imageNames,
                              const std::vector<std::string>& imageHashes = {},
                              const std::vector<std::string>& diffHashes = {});

}  // namespace aliaslab
