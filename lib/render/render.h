// Rendering a whole image: sample generation and tracing over tiles in
// parallel. Each tile writes only its own pixels' samples, so the result is
// bit-identical for any thread count.
#pragma once
#include "film/film.h"
#include "render/tracer.h"
#include "sampling/sampler.h"

namespace aliaslab {

/// Traces sampler.spp() samples in every pixel: positions (i + u, j + v)
/// from the sampler, radiance from the tracer. Optional progress callback
/// receives (tiles done, tiles total).
SampleBuffer traceSamples(const Tracer& tracer, const Sampler& sampler, int width, int height,
                          int threads = 0);

/// Filter importance sampling: each pixel's sampler point u is mapped
/// through filter.sample(u) to an offset around the pixel centre; the sample
/// keeps the returned weight.
SampleBuffer traceImportanceSamples(const Tracer& tracer, const Sampler& sampler, const Filter& filter,
                                    int width, int height, int threads = 0);

/// Depth (grey, (dmax - t) / (dmax - dmin) clamped to [0,1], background 0) and
/// normal (|n| per channel, background 0) images at pixel centres.
Image renderDepth(const Tracer& tracer, int width, int height, float dmin, float dmax, int threads = 0);
Image renderNormals(const Tracer& tracer, int width, int height, int threads = 0);

}  // namespace aliaslab
