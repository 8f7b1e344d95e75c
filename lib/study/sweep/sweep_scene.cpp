#include "study/sweep/sweep_scene.h"

#include <algorithm>
#include <filesystem>
#include <memory>
#include <string>

#include "core/files.h"
#include "core/image.h"
#include "study/reference/manifest.h"

namespace aliaslab {

namespace fs = std::filesystem;

namespace {
std::map<FilterSpec, const ReferenceImage*> byFilter(const ReferenceSet& set) {
  std::map<FilterSpec, const ReferenceImage*> of;
  for (const ReferenceImage& r : set.images) of[r.filter] = &r;
  return of;
}
}  // namespace

void writeSceneManifest(const StudyConfig& config, const StudyScene& scene, const ReferenceSet& refs,
                        const std::string& name) {
  // each image as a path from the manifest's folder to the cached EXR
  const fs::path path = fs::path(config.out) / "references" / name, manifests = path.parent_path();
  std::vector<std::string> names;
  for (const auto& r : refs.images)
    names.push_back((fs::absolute(fs::path(config.cache) / (r.key + ".exr")).lexically_normal())
                        .lexically_relative(fs::absolute(manifests).lexically_normal())
                        .string());
  fs::create_directories(manifests);
  writeTextFile(path.string(), referenceManifest(scene, refs, names));
}

ReferenceSet sceneReferences(const StudyConfig& config, const StudyScene& scene, const std::vector<StudyFilter>& specs,
                             const ReferenceOptions& options, bool images) {
  ReferenceSet refs = cachedReferences(scene, specs, options, config.cache);
  if (config.refsOnly) return refs;
  writeSceneManifest(config, scene, refs, scene.stem + ".json");
  if (images) {
    const fs::path imageDir = fs::path(config.out) / "images" / scene.stem;
    fs::create_directories(imageDir);
    writeImage((imageDir / "reference-area.png").string(), refs.images[0].image);  // specs[0] is the area
  }
  return refs;
}

RowReferences::RowReferences(const ReferenceSet& set, const std::vector<Target>& targets) : of_(byFilter(set)) {
  for (const Target& t : targets) {
    if (t.filter.spec == kAreaSpec) areaIndex_ = measured_.size();
    measured_.push_back(of_.at(t.filter.spec));
    flip_.push_back(std::make_unique<FlipReference>(measured_.back()->image));
  }
  if (std::find(measured_.begin(), measured_.end(), &area()) == measured_.end()) {
    areaIndex_ = measured_.size();
    measured_.push_back(&area());
  }
}

PhaseTime RowReferences::prepareSpectra(const std::vector<const ReferenceImage*>& own, int threads) const {
  std::vector<const ReferenceImage*> missing;
  for (const ReferenceImage* g : own)
    if (!spectra_.count(g) && std::find(missing.begin(), missing.end(), g) == missing.end()) missing.push_back(g);
  std::vector<std::shared_ptr<const SpectrumReference>> made(missing.size());
  const PhaseTime t = timedParallelFor(int(missing.size()), threads, 1,
                                       [&](int i) { made[i] = spectrumReference(*missing[i], measured_); });
  for (size_t i = 0; i < missing.size(); ++i) spectra_[missing[i]] = std::move(made[i]);
  return t;
}

PhaseTime startRows(std::vector<PendingRow>& rows, const RowReferences& refs, int threads) {
  std::vector<const ReferenceImage*> own;
  for (PendingRow& p : rows)
    own.push_back(p.reference = p.mode == ReconMode::Supersample ? &refs.area() : &refs.of(p.filter.spec));
  const PhaseTime spectra = refs.prepareSpectra(own, threads);
  PhaseTime rowsTime = timedParallelFor(int(rows.size()), threads, 1, [&](int i) {
    PendingRow& p = rows[i];
    p.measure = std::make_unique<RowMeasure>(*p.reference, refs.measured(), refs.spectrum(*p.reference));
    p.flipTargets.clear();
    for (size_t j = 0; j < refs.targets(); ++j) p.flipTargets.push_back(&refs.flipTarget(j));
    p.flipSums.assign(refs.targets(), 0.0);
  });
  rowsTime.work += spectra.work, rowsTime.idle += spectra.idle;
  return rowsTime;
}

}  // namespace aliaslab
