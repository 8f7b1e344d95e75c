// Internal pieces of the film shared by reconstruct() and the Accumulator
// (not an interface: only lib/film includes this).
#pragma once
#include "film/film.h"

namespace aliaslab::filmimpl {

inline bool finiteSample(const FilmSample& s) {
  return std::isfinite(s.x) && std::isfinite(s.y) && s.L.allFinite();
}
size_t countNonFinite(const SampleBuffer& samples);

/// Adds (f L, f) of every finite sample into `sums` (r, g, b, weight per
/// pixel, width x height) for every pixel whose centre is within the
/// support: the fast splat, banded over output rows so each pixel's sum
/// runs in the same order for any thread count. Weights from
/// Filter::evalFootprint (eval() up to a few float ulps); per source pixel
/// the products are summed exactly in double in a small tile, then added to
/// `sums` (float tiles measured no faster and lose the 1e-6 agreement where
/// negative lobes cancel).
void splatWeighted(const SampleBuffer& samples, const Filter& filter, double* sums, int threads);

/// Adds (L, 1) of each pixel's own finite samples into `plain` (r, g, b, count per pixel).
void addPlainSums(const SampleBuffer& samples, double* plain);

/// Turns weighted sums into an image with the documented degenerate outcomes.
Reconstruction resolveSums(int width, int height, const double* sums, const double* plain, double tolerance,
                           size_t nonFiniteSamples);

/// 1e-8 * |f(0, 0)| (at least 1e-30).
double weightTolerance(const Filter& filter);

Reconstruction reconstructSupersample(const SampleBuffer& samples, int threads);

}  // namespace aliaslab::filmimpl
