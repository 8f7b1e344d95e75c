// How the raytracer samples and reconstructs, resolved from its options.
//
// Classic flags (-random_samples n, -uniform_samples n, -jittered_samples n,
// -box_filter r, -tent_filter r, -gaussian_filter sigma) select the
// classic gather (ReconMode::Classic); the general ones (--sampler, --spp,
// --filter, --radius, --filter-param, --seed) the weighted average unless
// --reconstruction says otherwise. A classic and a general flag for the same
// thing conflict. Without any sampler one sample sits at each pixel centre
// (the uniform pattern with spp 1); without a filter each pixel takes its
// first sample. An adaptive sampler (--sampler adaptive-contrast:jittered,
// render/adaptive.h) spends --spp samples per pixel on average where the
// image needs them (without a filter: the box of radius 0.5, each pixel's
// area-weighted mean, rather than a first sample); -render_samples then
// shows where they went.
#pragma once
#include <memory>
#include <string>

#include "film/film.h"
#include "options.h"
#include "render/adaptive.h"
#include "render/tracer.h"
#include "sampling/sampler.h"

namespace aliaslab {

struct SamplingPlan {
  std::unique_ptr<Sampler> sampler;  ///< never null (for an adaptive sampler: its base at 1 spp)
  std::unique_ptr<AdaptiveSampler> adaptive;  ///< null unless --sampler names an adaptive method
  std::unique_ptr<Filter> filter;    ///< null: each pixel takes its first sample
  ReconMode mode = ReconMode::WeightedAverage;
  std::string describe() const;
};

/// Resolves and checks the sampling options; throws OptionError naming the flag.
SamplingPlan makeSamplingPlan(const CLI::App& app, const RaytracerOptions& o);

struct RenderedImage {
  Image image;
  SampleBuffer samples;
};

/// Traces and reconstructs the colour image (deterministic for any thread count).
RenderedImage renderImage(const Tracer& tracer, const SamplingPlan& plan, int width, int height, int threads);

/// The classic -render_samples picture of the traced samples.
Image renderSamplesImage(const RenderedImage& rendered, const RaytracerOptions& o);

/// The classic -render_filter picture of the plan's filter.
Image renderFilterImage(const SamplingPlan& plan, const RaytracerOptions& o);

}  // namespace aliaslab
