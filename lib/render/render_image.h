// One colour image from a sample source, a filter and a reconstruction mode:
// the raytracer's render (experiments/raytracer) and the Python module's
// render() (python/) both call renderImage, so they give the same pixels.
//
// Protocol: the source traces its sample set (or, in ImportanceSampled mode,
// places it by the filter), then the film reconstructs the image with the
// filter; without a filter each pixel takes its first sample. Deterministic
// for any thread count. Samples whose radiance is NaN or infinite are counted
// (a filter leaves them out, so their pixels look finite): callers refuse
// such an image rather than show it.
#pragma once
#include <cstddef>

#include "core/image.h"
#include "film/film.h"
#include "render/render.h"
#include "render/sample_source.h"

namespace aliaslab {

struct RenderedImage {
  Image image;
  SampleBuffer samples;
  size_t nonFiniteSamples = 0;  ///< samples whose radiance is NaN or infinite (a filter leaves them out)
};

/// Traces `source` over a width x height film and reconstructs it with `filter` (null: each pixel's first
/// sample) in `mode`; `progress` as traceSamples.
RenderedImage renderImage(const Tracer& tracer, const SampleSource& source, const Filter* filter, ReconMode mode,
                          int width, int height, int threads = 0, const Progress& progress = {});

}  // namespace aliaslab
