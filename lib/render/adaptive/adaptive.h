// Adaptive sampling: spend an average budget of spp samples per pixel where
// the image needs them, on top of any registered base sampler.
//
// Names: "adaptive-<method>:<base>[+key=value...]", e.g.
// "adaptive-contrast:jittered" or "adaptive-subdiv:sobol+threshold=0.05+depth=4".
// <base> is any name of samplerNames(). These are not part of makeSampler():
// a Sampler is a pure function of (seed, pixel) and never sees radiance,
// while an adaptive method decides where to sample from what it has traced,
// so it needs the tracer and lives in the render layer. Callers take any
// sampler name, adaptive or not, from the one factory makeSampleSource()
// (render/sample_source.h), which builds on makeAdaptiveSampler() here, and
// trace what it gives; everything downstream (reconstruction with any
// filter, the study's metrics) takes the result like any sample set.
// (adaptive.cpp: names and parameters; adaptive_trace.cpp: contrast, error and the entry point;
// adaptive_subdiv.cpp: subdivision; adaptive_work.h, adaptive_work.cpp: their shared state and rounds.)
//
// Protocol (all three methods):
// - Budget: exactly B = spp * width * height samples are traced in total, so
//   the mean spent is spp. On a flat image every pixel gets exactly spp
//   samples, each of weight 1/spp (the base sampler's plain mean).
// - Positions: every sample lies inside its own pixel, [i, i+1) x [j, j+1).
//   A round's points come from the base sampler built for that round's count
//   with a seed hashed from (seed, round): round 0 uses the run's seed, so
//   the pilot IS the base sampler at the pilot's count. Subdivision cells are
//   sampled as pixels of a 2^d-times finer film (seed hashed from (seed, round)).
// - Unbiased, two ways (docs/adaptive.md, "Bias"). With a progressive base
//   (sampling/progressive.h: random, halton, sobol, pmj02, and jittered through
//   progressive jittered), contrast and error continue every pixel's own
//   sequence: the pilot is its points 0 .. n0-1, the fresh samples its points
//   n0 .. n0+m-1, and the estimate the plain mean of all n0 + m; a pixel's
//   count is decided from its neighbours' pilots only (never its own), so it
//   is independent of the pixel's own points up to the shared budget, and a
//   pixel that gets exactly spp samples holds the base's own spp-point set.
//   Otherwise (and for subdivision) every decision reads only samples whose
//   share of the pixel's estimate (FilmSample::weight; a pixel's shares add
//   up to 1, the buffer is areaWeighted) was fixed before they were traced,
//   and every share a decision moves goes to samples traced after it.
// - Determinism: decisions are made between rounds, ranking pixels by
//   (priority descending, count ascending, hash(seed, pixel) ascending): a
//   strict order, so results are identical for any thread count.
//
// Methods (shape parameters in AdaptiveParams, keys in brackets):
// - contrast (Mitchell 1987): a pilot of n0 = round(first * spp) samples per
//   pixel (1 .. spp); from it alone, pixels whose neighbourhood (the pixel
//   and its 8 neighbours) has, in some channel c, contrast
//   C_c = (Imax - Imin) / (Imax + Imin) above the threshold t_c (Mitchell's
//   0.4, 0.3, 0.6) get fresh samples up to the cap (cap * spp in all),
//   highest C_c / t_c first; every pixel at least one; the rest evenly.
//   Pilot weight n0/spp in all, fresh 1 - n0/spp.
// - error: a pilot of n0 (at least 2); fresh samples in proportion to the
//   pilot's standard deviation (the largest over the 3 x 3 neighbourhood),
//   between floor * (spp - n0) (at least 1) and the cap; the rest evenly.
//   Weights as contrast.
// - subdiv (Whitted 1980): 4 decision samples per pixel; a cell whose
//   samples differ by more than `threshold` in some channel (max - min,
//   radiance) is split into 4 quadrants with 4 decision samples each,
//   level by level (largest difference first) down to `depth`, while the
//   budget pays for it; then fresh samples in every leaf (at least one).
//   A cell's estimate is alpha * mean(its decision samples) + (1 - alpha) *
//   (its children's mean, or its fresh samples' mean), alpha = 4/spp for the
//   pixel and 1/2 below. At spp < 5: the base sampler, nothing decided.
#pragma once
#include <array>
#include <memory>
#include <string>
#include <vector>

#include "film/film.h"
#include "render/render.h"
#include "sampling/sampler.h"

namespace aliaslab {

enum class AdaptiveMethod { Contrast, Error, Subdivision };

/// Shape parameters; keys as written in a name after '+'.
struct AdaptiveParams {
  double first = 0.25;   ///< [first] share of spp spent in the first pass (contrast, error), in (0, 1]
  double cap = 4;        ///< [cap] no pixel refined beyond cap * spp samples (contrast, error), >= 1
  std::array<double, 3> contrast = {0.4, 0.3, 0.6};  ///< [threshold, or tr tg tb] Mitchell's per-channel thresholds
  double floor = 0.25;   ///< [floor] error: fresh samples every pixel keeps, as a share of spp - pilot, in [0, 1]
  double threshold = 0.1;  ///< [threshold] subdiv: max - min of a cell's samples (radiance) that splits it
  int depth = 2;         ///< [depth] subdiv: levels of splitting below the pixel, 0 .. 8
};

class AdaptiveSampler {
 public:
  AdaptiveSampler(AdaptiveMethod method, std::string base, int spp, uint64_t seed, AdaptiveParams params);
  AdaptiveMethod method() const { return method_; }
  const std::string& base() const { return base_; }
  int spp() const { return spp_; }
  uint64_t seed() const { return seed_; }
  const AdaptiveParams& params() const { return params_; }
  /// The name it was made from, canonical ("adaptive-error:jittered+floor=0.5").
  std::string name() const;
  /// One line for logs and CSV rows.
  std::string describe() const;
  /// The base sampler at `count` points for round `round` (seed hashed from (seed, round), round 0: seed).
  std::unique_ptr<Sampler> baseSampler(int count, uint64_t round) const;
  /// True when contrast or error continue each pixel's own progressive sequence (the base has one,
  /// sampling/progressive.h); subdivision never does.
  bool progressive() const { return progressive_; }
  /// The base's progressive sequence at `count` points with the run's seed (progressive() only).
  std::unique_ptr<Sampler> progressiveSampler(int count) const;

 private:
  AdaptiveMethod method_;
  std::string base_;
  int spp_;
  uint64_t seed_;
  AdaptiveParams params_;
  bool progressive_ = false;
};

/// "contrast", "error", "subdiv".
const std::vector<std::string>& adaptiveMethodNames();

/// True for names starting "adaptive-" (which makeAdaptiveSampler then accepts or rejects).
bool isAdaptiveSamplerName(const std::string& name);

/// Parses a name (see the top of this file). Throws OptionError("sampler") for an unknown method, base or
/// key or a bad value (listing the valid ones) and OptionError("spp") for spp < 1.
std::unique_ptr<AdaptiveSampler> makeAdaptiveSampler(const std::string& name, int spp, uint64_t seed);

/// Traces exactly spp * width * height samples chosen by the method; the buffer has a variable count per pixel
/// (every pixel at least one sample). `progress`: (samples traced, total) after each round, scaled to int.
SampleBuffer traceAdaptive(const Tracer& tracer, const AdaptiveSampler& sampler, int width, int height,
                           int threads = 0, const Progress& progress = {});

/// Samples actually spent: mean and maximum per pixel (both spp for a fixed-count buffer).
struct SpentSamples {
  double mean = 0;
  int max = 0;
};
SpentSamples spentSamples(const SampleBuffer& samples);

/// Samples per pixel as an image (every channel the count).
Image sampleDensity(const SampleBuffer& samples);

}  // namespace aliaslab
