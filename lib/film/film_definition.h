// The film's definition: the weighted-average reconstruction of film.h written as it reads in docs/science.md
// ("Reconstruction"), one pixel at a time over every sample, in double. It is the reference every fast path
// (reconstruct's banded splat with its AVX2 and SSE kernels, the Accumulator) is tested against; slow on
// purpose (pixels x samples filter evaluations), so not used by the programs. pbrt-v4's film.h (AddSample) and
// Nori's ImageBlock::put are the models: a pixel is sum f(x_k - p) L_k / sum f(x_k - p).
#pragma once
#include "film/film.h"

namespace aliaslab {

/// Pixel (i, j), centre p = (i + 0.5, j + 0.5), is sum_k w_k L_k / sum_k w_k over every finite sample k of the
/// buffer, w_k = f(x_k - p) (times FilmSample::weight when the buffer is areaWeighted()), summed in double, with
/// the degenerate outcomes of film.h: non-finite samples skipped and counted; |sum w| below
/// 1e-8 |f(0, 0)| (at least 1e-30), or a result not finite in float, gives the plain mean of the pixel's own
/// finite samples (0 if none; undefinedPixels or nanPixels); a negative channel is kept and counted.
Reconstruction reconstructDefinition(const SampleBuffer& samples, const Filter& filter);

}  // namespace aliaslab
