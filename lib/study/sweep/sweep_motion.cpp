// Frames in the sweep (study/sweep/sweep_motion.h).
#include "study/sweep/sweep_motion.h"

#include <algorithm>
#include <memory>
#include <stdexcept>

#include "film/film.h"
#include "measure/motion.h"
#include "render/sample_source.h"
#include "study/sweep/motion_frame.h"

namespace aliaslab {

namespace {

// Moves the scene's camera frame by frame and puts the still camera and hash back when it goes.
class FrameCamera {
 public:
  FrameCamera(StudyScene& s, const StudyConfig& c)
      : s_(s), c_(c), base_(std::move(s.scene.camera)), hash_(s.contentHash) {}
  ~FrameCamera() { s_.scene.camera = std::move(base_), s_.contentHash = hash_; }
  FrameCamera(const FrameCamera&) = delete;
  FrameCamera& operator=(const FrameCamera&) = delete;
  void set(int t) { setMotionFrame(s_, *base_, hash_, t, c_.motionDx, c_.motionDy); }

 private:
  StudyScene& s_;
  const StudyConfig& c_;
  std::unique_ptr<Camera> base_;
  uint64_t hash_;
};

RefEstimate estimate(const ReferenceSet& set, const FilterSpec& spec) {
  const auto r = std::find_if(set.images.begin(), set.images.end(), [&](const ReferenceImage& i) { return i.filter == spec; });
  if (r == set.images.end()) throw std::logic_error("motionReferences: no reference of a target");
  return {&r->image, &r->halfDiff, spec.second};
}

}  // namespace

std::vector<ReferenceSet> frameReferences(const StudyConfig& c, StudyScene& scene, const std::vector<StudyFilter>& specs,
                                          const ReferenceOptions& options) {
  FrameCamera camera(scene, c);
  std::vector<ReferenceSet> sets;
  for (int t = 1; t < c.frames; ++t) {
    camera.set(t);
    sets.push_back(cachedReferences(scene, specs, options, c.cache));
  }
  return sets;
}

MotionReferences motionReferences(const StudyConfig& c, const ReferenceSet& still,
                                  const std::vector<ReferenceSet>& later, const std::vector<Target>& targets) {
  MotionReferences m;
  for (const Target& target : targets) {
    std::vector<RefEstimate> T{estimate(still, target.filter.spec)};
    for (const ReferenceSet& r : later) T.push_back(estimate(r, target.filter.spec));
    m.targetShimmer.push_back(targetShimmer(T, c.motionDx, c.motionDy));
  }
  return m;
}

void measureGroupMotion(const StudyConfig& c, StudyScene& scene, const Tracer& tracer, const SampleSetGroup& group,
                        std::vector<PendingRow>& rows, const MotionReferences& refs,
                        const std::vector<Target>& targets, int threads) {
  const int F = c.frames, K = c.seeds;
  FrameCamera camera(scene, c);
  // images[r][k][t]: row r, seed k, frame t
  std::vector<std::vector<std::vector<Image>>> images(rows.size(),
                                                      std::vector<std::vector<Image>>(K, std::vector<Image>(F)));
  const bool shared = std::any_of(rows.begin(), rows.end(),  // a row reconstructs the shared sample set
                                  [](const PendingRow& p) { return p.mode != ReconMode::ImportanceSampled; });
  for (size_t r = 0; r < rows.size(); ++r) {  // frame 0: the still pass's images (study/sweep/sweep_group.h)
    if (rows[r].frame0.size() != size_t(K)) throw std::logic_error("measureGroupMotion: frame 0 images missing");
    for (int k = 0; k < K; ++k) images[r][k][0] = std::move(rows[r].frame0[k]);
    rows[r].frame0.clear();
  }
  for (int k = 0; k < K; ++k) {
    const auto source = makeSampleSource(group.sampler, group.spp, static_cast<uint64_t>(k));
    for (int t = 1; t < F; ++t) {
      camera.set(t);
      const SampleBuffer samples = shared ? source->trace(tracer, scene.width, scene.height, threads) : SampleBuffer();
      for (size_t r = 0; r < rows.size(); ++r) {
        const Filter& filter = *rows[r].filter.filter;
        if (rows[r].mode == ReconMode::ImportanceSampled) {
          const SampleBuffer own = source->traceImportance(tracer, filter, scene.width, scene.height, threads);
          images[r][k][t] = reconstruct(own, filter, rows[r].mode, threads).image;
        } else {
          images[r][k][t] = reconstruct(samples, filter, rows[r].mode, threads).image;
        }
      }
    }
  }
  for (size_t r = 0; r < rows.size(); ++r) {
    PendingRow& p = rows[r];
    const MotionMetrics m = computeMotionMetrics(images[r], c.motionDx, c.motionDy);
    p.motion.clear();
    for (size_t i = 0; i < targets.size(); ++i)
      p.motion.push_back({F, c.motionDx, c.motionDy, m.shimmer, m.shimmerSe, m.flickerSameSeed, m.flickerSameSeedSe,
                          m.flickerNewSeed, m.flickerNewSeedSe, refs.targetShimmer.at(i)});
    images[r].clear();
  }
}

}  // namespace aliaslab
