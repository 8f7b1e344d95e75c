// Rendering a whole image: sample generation and tracing over tiles in
// parallel. Each tile writes only its own pixels' samples, so the result is
// bit-identical for any thread count.
#pragma once
#include <functional>

#include "film/film.h"
#include "render/tracer.h"
#include "sampling/sampler.h"

namespace aliaslab {

/// Progress report: (tiles done, tiles total). Called from worker threads,
/// one call at a time, after each 16 x 16 tile.
using Progress = std::function<void(int done, int total)>;

/// Traces sampler.spp() samples in every pixel: positions (i + u, j + v)
/// from the sampler, weight 1, radiance from tracer.radianceAt.
/// `threads`: 0 = all cores. `progress`: optional, empty by default.
SampleBuffer traceSamples(const Tracer& tracer, const Sampler& sampler, int width, int height,
                          int threads = 0, const Progress& progress = {});

/// Filter importance sampling: each pixel's sampler point u is mapped
/// through FilterSampler::sample(u) (filter/filter_sampler.h, its table built
/// once per call) to an offset around the pixel centre; the sample keeps the
/// returned weight.
/// Position = pixel centre (i + 0.5, j + 0.5) + offset.
SampleBuffer traceImportanceSamples(const Tracer& tracer, const Sampler& sampler, const Filter& filter,
                                    int width, int height, int threads = 0, const Progress& progress = {});

/// Depth (grey, (dmax - t) / (dmax - dmin) clamped to [0,1], background 0) and
/// normal (|n| per channel, background 0) images of the first hit of the
/// primary ray through each pixel centre (t in units of the camera's unit
/// ray direction; n the geometric normal).
Image renderDepth(const Tracer& tracer, int width, int height, float dmin, float dmax, int threads = 0);
Image renderNormals(const Tracer& tracer, int width, int height, int threads = 0);

}  // namespace aliaslab
