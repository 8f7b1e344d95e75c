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
// (adaptive.cpp: names and parameters; adaptive_trace.cpp: the methods; adaptive_work.h, adaptive_work.cpp:
// their shared state and rounds.)
//
// Protocol (all three methods):
// - Budget: exactly B = spp * width * height samples are traced in total, so
//   the mean spent is spp (well within the 1 % asked of the study). Work goes
//   in rounds over the whole image; a round never takes more than what is
//   left, and the last one takes exactly what is left. Budget the refinement
//   does not use (nothing exceeds a threshold, every candidate at its cap) is
//   spent evenly at the end: floor(R / N) more samples in every pixel, one
//   more in the R mod N pixels that rank first. So on a flat image every
//   pixel gets exactly spp samples.
// - Positions: every sample lies inside its own pixel, [i, i+1) x [j, j+1).
//   A round's points come from the base sampler built for that round's count
//   with a seed hashed from (seed, round): round 0 uses the run's seed, so
//   the first pass IS the base sampler at the first-pass count. Subdivision
//   cells are sampled as pixels of a 2^d-times finer film (base sampler at 4
//   points, seed hashed from (seed, depth)).
// - Determinism: decisions are made between rounds from the samples traced
//   so far, ranking pixels by (priority descending, count ascending,
//   hash(seed, pixel) ascending): a strict order, so results are identical
//   for any thread count (only the tracing inside a round runs in parallel).
//
// Methods (shape parameters in AdaptiveParams, keys in brackets):
// - contrast (Mitchell 1987): a first pass of n0 = round(first * spp)
//   samples per pixel (at least 1), then rounds of n0 more samples to every
//   pixel whose neighbourhood (the pixel and its 8 neighbours) has, in some
//   channel c, contrast C_c = (Imax - Imin) / (Imax + Imin) above the
//   threshold t_c (Mitchell's 0.4, 0.3, 0.6 for R, G, B), highest C_c / t_c
//   first, until each is at the cap (cap * spp samples).
// - error: first pass n0 = round(first * spp) (at least 2 where spp allows,
//   to estimate a variance); then rounds, each spending at most `round` of
//   the total budget, giving min(n0, ceil(R / N)) samples each to the
//   pixels with the largest estimated standard error of the mean,
//   sqrt(mean over channels of s_c^2 / n) (s_c^2 the unbiased sample
//   variance of the pixel's own samples). Pixels with zero estimated error
//   are not refined (a pixel whose first samples all agree is never looked
//   at again: the method's blind spot).
// - subdiv (Whitted 1980): 4 samples per pixel (the base sampler at 4
//   points, stratified bases put one in each quadrant: the "corners"); a
//   cell whose samples differ by more than `threshold` in some channel
//   (max - min, radiance units) is split into 4 quadrants, each sampled at
//   4 new points; recursively, level by level over the image (largest
//   difference first), down to `depth` levels. At spp < 4 the first pass is
//   spp samples and nothing is refined.
//
// Bias, measured rather than hidden: the decision to refine uses the same
// samples that are averaged, and the reconstruction weights samples by
// density (a filter sums f L / sum f over whatever samples fall in its
// support), so refined regions count more. Both show in the study's
// aliasing term (the error of the mean image against the reference).
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
  double round = 0.125;  ///< [round] share of the total budget one error round may spend, in (0, 1]
  double threshold = 0.1;  ///< [threshold] subdiv: max - min of a cell's samples (radiance) that splits it
  int depth = 3;         ///< [depth] subdiv: levels of splitting below the pixel, 0 .. 8
};

class AdaptiveSampler {
 public:
  AdaptiveSampler(AdaptiveMethod method, std::string base, int spp, uint64_t seed, AdaptiveParams params);
  AdaptiveMethod method() const { return method_; }
  const std::string& base() const { return base_; }
  int spp() const { return spp_; }
  uint64_t seed() const { return seed_; }
  const AdaptiveParams& params() const { return params_; }
  /// The name it was made from, canonical ("adaptive-error:jittered+round=0.25").
  std::string name() const;
  /// One line for logs and CSV rows.
  std::string describe() const;
  /// The base sampler at `count` points for round `round` (seed hashed from (seed, round), round 0: seed).
  std::unique_ptr<Sampler> baseSampler(int count, uint64_t round) const;

 private:
  AdaptiveMethod method_;
  std::string base_;
  int spp_;
  uint64_t seed_;
  AdaptiveParams params_;
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
