// makeSampleSource: the two kinds of source over their factories, the one place that tells them apart.
#include "render/sample_source.h"

#include <stdexcept>

#include "render/adaptive/adaptive.h"

namespace aliaslab {
namespace {

/// A pattern of lib/sampling, traced point by point.
class PatternSource final : public SampleSource {
 public:
  explicit PatternSource(std::unique_ptr<Sampler> sampler) : sampler_(std::move(sampler)) {}
  std::string name() const override { return sampler_->name(); }
  std::string describe() const override { return sampler_->describe(); }
  int spp() const override { return sampler_->spp(); }
  const Sampler& pixelSampler() const override { return *sampler_; }
  bool adaptive() const override { return false; }
  SampleBuffer trace(const Tracer& tracer, int width, int height, int threads,
                     const Progress& progress) const override {
    return traceSamples(tracer, *sampler_, width, height, threads, progress);
  }
  SampleBuffer traceImportance(const Tracer& tracer, const Filter& filter, int width, int height, int threads,
                               const Progress& progress) const override {
    return traceImportanceSamples(tracer, *sampler_, filter, width, height, threads, progress);
  }

 private:
  std::unique_ptr<Sampler> sampler_;
};

/// An adaptive method over its base pattern.
class AdaptiveSource final : public SampleSource {
 public:
  explicit AdaptiveSource(std::unique_ptr<AdaptiveSampler> adaptive)
      : adaptive_(std::move(adaptive)), first_(adaptive_->baseSampler(1, 0)) {}
  std::string name() const override { return adaptive_->name(); }
  std::string describe() const override { return adaptive_->describe(); }
  int spp() const override { return adaptive_->spp(); }
  const Sampler& pixelSampler() const override { return *first_; }
  bool adaptive() const override { return true; }
  SampleBuffer trace(const Tracer& tracer, int width, int height, int threads,
                     const Progress& progress) const override {
    return traceAdaptive(tracer, *adaptive_, width, height, threads, progress);
  }
  SampleBuffer traceImportance(const Tracer&, const Filter&, int, int, int, const Progress&) const override {
    // (front ends refuse the combination with their own message first)
    throw std::invalid_argument("importance sampling cannot take an adaptive sampler (" + name() +
                                "): an adaptive method places its own samples");
  }

 private:
  std::unique_ptr<AdaptiveSampler> adaptive_;
  std::unique_ptr<Sampler> first_;  ///< the base at 1 spp, round 0
};

}  // namespace

std::unique_ptr<SampleSource> makeSampleSource(const std::string& name, int spp, uint64_t seed) {
  if (isAdaptiveSamplerName(name)) return std::make_unique<AdaptiveSource>(makeAdaptiveSampler(name, spp, seed));
  return std::make_unique<PatternSource>(makeSampler(name, spp, seed));
}

const std::vector<std::string>& sampleSourceNames() {
  static const std::vector<std::string> names = [] {
    std::vector<std::string> v = allSamplerNames();
    for (const std::string& m : adaptiveMethodNames())
      for (const std::string& b : samplerNames()) v.push_back("adaptive-" + m + ":" + b);
    return v;
  }();
  return names;
}

}  // namespace aliaslab
