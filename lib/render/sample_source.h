// One factory for every sampler name: where a film's samples come from.
//
// A caller asks makeSampleSource() for any name a front end accepts and
// traces what it gets, with no test of the name: the plain and composed
// patterns of lib/sampling (makeSampler: a pure function of seed and pixel,
// traced by traceSamples) and the adaptive methods of render/adaptive/adaptive.h
// ("adaptive-METHOD:BASE", which decide where to sample from what they have
// traced, so they need the tracer and live here, in the render layer).
// Everything downstream (reconstruction with any filter, the study's
// metrics) takes the traced buffer like any sample set.
//
// Capabilities differ, and are asked, never inferred from names: an
// adaptive source gives a variable count per pixel (SampleBuffer::variable)
// and cannot place samples by a filter (traceImportance throws).
//
// Protocol: made for one name, sample count and seed, immutable after that;
// trace() is deterministic for any thread count.
#pragma once
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "film/film.h"
#include "render/render.h"
#include "sampling/sampler.h"

namespace aliaslab {

class SampleSource {
 public:
  virtual ~SampleSource() = default;
  /// The name it was made from (adaptive: canonical, AdaptiveSampler::name).
  virtual std::string name() const = 0;
  /// One line for logs and CSV rows (the pattern's or the adaptive method's describe()).
  virtual std::string describe() const = 0;
  /// Samples per pixel: the fixed count, or the adaptive average budget.
  virtual int spp() const = 0;
  /// The fixed-count pixel pattern: the sampler itself; for an adaptive method its base at 1 sample per pixel
  /// with the run's seed (its first round's pattern).
  virtual const Sampler& pixelSampler() const = 0;
  /// True for an adaptive method (render/adaptive/adaptive.h): variable counts, no filter importance sampling.
  virtual bool adaptive() const = 0;
  /// Traces the sample set of a width x height film (`progress` as traceSamples / traceAdaptive).
  virtual SampleBuffer trace(const Tracer& tracer, int width, int height, int threads = 0,
                             const Progress& progress = {}) const = 0;
  /// Filter importance sampling through the pattern's points (traceImportanceSamples); throws
  /// std::invalid_argument for an adaptive method, which places its own samples.
  virtual SampleBuffer traceImportance(const Tracer& tracer, const Filter& filter, int width, int height,
                                       int threads = 0, const Progress& progress = {}) const = 0;
};

/// Makes the source for any sampler name: a name of allSamplerNames() (makeSampler) or an adaptive name
/// "adaptive-METHOD:BASE[+key=value...]" (makeAdaptiveSampler). Throws those factories' OptionErrors
/// ("sampler" naming the valid names, "spp").
std::unique_ptr<SampleSource> makeSampleSource(const std::string& name, int spp, uint64_t seed);

/// Every name makeSampleSource takes without shape parameters, in a fixed order: allSamplerNames(), then
/// "adaptive-METHOD:BASE" for every method of adaptiveMethodNames() and every plain name of samplerNames().
const std::vector<std::string>& sampleSourceNames();

}  // namespace aliaslab
