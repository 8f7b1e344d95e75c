// The fixed grid judged over alignments (study/sweep/alignment.h).
#include "study/sweep/alignment.h"

#include <cmath>
#include <cstdio>

#include "core/hash.h"
#include "core/parallel.h"
#include "film/film.h"
#include "render/sample_source.h"
#include "study/sweep/sweep_scene.h"

namespace aliaslab {

namespace {

// mean over values of (image - T)^2 - mean D_T^2: the image's mse against T with T's variance subtracted.
double correctedMse(const Image& image, const ReferenceImage& t) {
  const size_t n = size_t(image.width()) * image.height() * 3;
  const float* v = image.data();
  const float* m = t.image.data();
  const bool halves = t.halfDiff.width() == image.width() && t.halfDiff.height() == image.height();
  const float* d = halves ? t.halfDiff.data() : nullptr;
  double sse = 0, var = 0;
  for (size_t i = 0; i < n; ++i) {
    const double e = double(v[i]) - m[i];
    sse += e * e;
    if (d) var += double(d[i]) * d[i];
  }
  return (sse - var) / double(n);
}

// Mean, sd over the values (K - 1 in the denominator) and sd / sqrt K.
AlignColumns summarise(std::vector<double> values) {
  AlignColumns a;
  const double k = double(values.size());
  a.offsets = int(values.size());
  for (double v : values) a.mseTarget += v / k;
  double ss = 0;
  for (double v : values) ss += (v - a.mseTarget) * (v - a.mseTarget);
  a.mseTargetSd = values.size() > 1 ? std::sqrt(ss / (k - 1)) : NAN;
  a.mseTargetSe = a.mseTargetSd / std::sqrt(k);
  a.perOffset = std::move(values);
  return a;
}

}  // namespace

Vec2 alignmentOffset(int k) {
  constexpr uint64_t kTag = 0xa119e0ffULL;
  const double u = toUnitDouble(hashWords(uint64_t(k), kTag, 0)), v = toUnitDouble(hashWords(uint64_t(k), kTag, 1));
  return Vec2(static_cast<float>(u - 0.5), static_cast<float>(v - 0.5));
}

FilmOffsetCamera::FilmOffsetCamera(StudyScene& s) : s_(s), base_(std::move(s.scene.camera)), hash_(s.contentHash) {}

FilmOffsetCamera::~FilmOffsetCamera() {
  s_.scene.camera = std::move(base_), s_.contentHash = hash_;
  s_.filmOffset[0] = s_.filmOffset[1] = 0;
}

void FilmOffsetCamera::set(const Vec2& offset) {
  const float side = static_cast<float>(std::max(s_.width, s_.height));
  s_.scene.camera = makeShiftedCamera(*base_, offset / side);  // film pixels -> the camera's square screen
  char exact[96];  // %a: every bit of the offset, so no two offsets share a key
  std::snprintf(exact, sizeof exact, "film offset %a %a", double(offset.x()), double(offset.y()));
  s_.contentHash = offset.isZero(0.f) ? hash_ : hashBytes(exact, hash_);
  s_.filmOffset[0] = offset.x(), s_.filmOffset[1] = offset.y();
}

ReferenceOptions alignmentReferenceOptions(const StudyConfig& config) {
  ReferenceOptions o = referenceOptions(config);
  o.spp = config.alignRefSpp;
  return o;
}

std::vector<ReferenceSet> alignmentReferences(const StudyConfig& c, StudyScene& scene,
                                              const std::vector<StudyFilter>& targets, const ReferenceOptions& options) {
  FilmOffsetCamera camera(scene);
  std::vector<ReferenceSet> sets;
  for (int k = 0; k < c.alignOffsets; ++k) {
    camera.set(alignmentOffset(k));
    sets.push_back(cachedReferences(scene, targets, options, c.cache));
    if (!c.refsOnly) writeSceneManifest(c, scene, sets.back(), "alignment/" + scene.stem + "-" + std::to_string(k) + ".json");
  }
  return sets;
}

void measureGroupAlignment(StudyScene& scene, const Tracer& tracer, const SampleSetGroup& group,
                           std::vector<PendingRow>& rows, const std::vector<ReferenceSet>& refs, int threads) {
  const int K = int(refs.size());
  const size_t T = refs.empty() ? 0 : refs.front().images.size();
  // values[r][j][k]: row r, target j, offset k
  std::vector<std::vector<std::vector<double>>> values(rows.size(),
                                                       std::vector<std::vector<double>>(T, std::vector<double>(K)));
  std::vector<const Filter*> weighted;
  std::vector<size_t> weightedIndex(rows.size(), 0);
  for (size_t r = 0; r < rows.size(); ++r)
    if (rows[r].mode == ReconMode::WeightedAverage) weightedIndex[r] = weighted.size(), weighted.push_back(rows[r].filter.filter.get());
  bool shared = false;  // a row reconstructs the grid's own samples (importance rows trace their own)
  for (const PendingRow& p : rows) shared = shared || p.mode != ReconMode::ImportanceSampled;
  FilmOffsetCamera camera(scene);
  const auto source = makeSampleSource(group.sampler, group.spp, 0);  // the fixed grid: every seed the same
  for (int k = 0; k < K; ++k) {
    camera.set(alignmentOffset(k));
    SampleBuffer samples;
    std::unique_ptr<Accumulator> acc;
    if (shared) samples = source->trace(tracer, scene.width, scene.height, threads);
    if (!weighted.empty()) {
      acc = std::make_unique<Accumulator>(scene.width, scene.height, weighted);
      acc->add(samples, threads);
    }
    parallelFor(int(rows.size()), threads, [&](int r) {
      const PendingRow& p = rows[r];
      const Filter& filter = *p.filter.filter;
      Image image;
      if (p.mode == ReconMode::WeightedAverage) {
        image = acc->resolve(weightedIndex[r]).image;
      } else if (p.mode == ReconMode::ImportanceSampled) {
        const SampleBuffer own = source->traceImportance(tracer, filter, scene.width, scene.height, 1);
        image = reconstruct(own, filter, p.mode, 1).image;
      } else {
        image = reconstruct(samples, filter, p.mode, 1).image;
      }
      for (size_t j = 0; j < T; ++j) values[r][j][k] = correctedMse(image, refs[k].images[j]);
    });
  }
  for (size_t r = 0; r < rows.size(); ++r) {
    rows[r].align.clear();
    for (size_t j = 0; j < T; ++j) rows[r].align.push_back(summarise(std::move(values[r][j])));
  }
}

}  // namespace aliaslab
