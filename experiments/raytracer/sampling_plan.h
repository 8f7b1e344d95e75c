// How the raytracer samples and reconstructs, resolved from its options.
//
// Classic flags (-random_samples n, -uniform_samples n, -jittered_samples n,
// -box_filter r, -tent_filter r, -gaussian_filter sigma) select the
// classic gather (ReconMode::Classic); the general ones (--sampler, --spp,
// --filter, --radius, --filter-param, --seed) the weighted average unless
// --reconstruction says otherwise. A classic and a general flag for the same
// thing conflict. Without any sampler one sample sits at each pixel centre
// (the uniform pattern with spp 1). Without a filter: with --spp above 1 the
// pixel-area average (box of radius 0.5, weighted); with a classic sampler
// flag each pixel takes its first sample, as the course says (the front end
// prints a note then). --filter without --radius uses the filter's natural
// radius (defaultFilterRadius).
// An adaptive sampler (--sampler adaptive-contrast:jittered, render/adaptive/adaptive.h)
// spends --spp samples per pixel on average where the image needs them
// (without a filter: the box of radius 0.5, each pixel's area-weighted mean);
// -render_samples then shows where they went.
#pragma once
#include <memory>
#include <string>

#include "film/film.h"
#include "options.h"
#include "render/render_image.h"
#include "render/sample_source.h"
#include "render/tracer.h"

namespace aliaslab {

struct SamplingPlan {
  std::unique_ptr<SampleSource> source;  ///< never null: the sampler of --sampler or a classic flag, maybe adaptive
  std::unique_ptr<Filter> filter;    ///< null: each pixel takes its first sample
  ReconMode mode = ReconMode::WeightedAverage;
  bool defaultFilter = false;        ///< the filter is the default box 0.5 (no filter option given)
  std::string note;                  ///< a remark for stderr (several classic samples, no filter), or ""
  std::string describe() const;
};

/// Resolves and checks the sampling options; throws OptionError naming the flag.
SamplingPlan makeSamplingPlan(const CLI::App& app, const RaytracerOptions& o);

/// Traces and reconstructs the colour image (render/render_image.h, with a progress line on stderr for long
/// renders; deterministic for any thread count).
RenderedImage renderImage(const Tracer& tracer, const SamplingPlan& plan, int width, int height, int threads);

/// The classic -render_samples picture of the traced samples.
Image renderSamplesImage(const RenderedImage& rendered, const RaytracerOptions& o);

/// The -render_filter picture of the plan's filter: the course's picture
/// (blue grid, grey weights) for the classic reconstruction, else
/// renderFilterSigned (the filter as used, negative lobes in blue, colour bar).
Image renderFilterImage(const SamplingPlan& plan, const RaytracerOptions& o);

}  // namespace aliaslab
