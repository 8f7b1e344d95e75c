// Internal pieces of the film shared by reconstruct() and the Accumulator
// (not an interface: only lib/film includes this).
#pragma once
#include <vector>

#include "film/film.h"
#include "filter/filter_batch.h"

namespace aliaslab::filmimpl {

/// Position and radiance finite: v - v is 0 for finite v, NaN for inf and NaN (no branches).
inline bool finiteSample(const FilmSample& s) {
  return (s.x - s.x) + (s.y - s.y) + (s.L[0] - s.L[0]) + (s.L[1] - s.L[1]) + (s.L[2] - s.L[2]) == 0;
}

/// Output rows per parallel work item of the splat (a band).
constexpr int kBand = 32;

/// Adds (f L, f) of every finite sample into `sums` (r, g, b, weight per
/// pixel, width x height) for every pixel whose centre is within the
/// support: the fast splat, banded over output rows so each pixel's sum
/// runs in sample order for any thread count. Weights from
/// FilterBatch (eval() bit for bit; Blackman-Harris and the Gaussian
/// within float rounding), summed in double: float x float products are
/// exact, so the AVX2 + FMA kernel used where the CPU has it sums exactly
/// like the SSE one (tests compare them under core/cpu.h's ScopedCpuFeatures,
/// which also forces the sample-by-sample set-up).
/// Float sums were measured no faster and lose the 1e-6 agreement where
/// negative lobes cancel.
void splatWeighted(const SampleBuffer& samples, const Filter& filter, double* sums, int threads);

/// Where a splat adds: sums[k] for filters[k] (r, g, b, weight per pixel each).
struct SplatTargets {
  const std::vector<const Filter*>& filters;
  const std::vector<double*>& sums;
  /// If not null (K entries, added to): each filter's own part of the work, in seconds summed over the threads.
  double* ownSeconds = nullptr;
  /// The sums need not be initialised: every value is set to 0.0 + this pass's sum, bit for bit what adding
  /// into zeroed sums gives (an Accumulator's first batch).
  bool overwrite = false;
};

/// splatWeighted for several filters at once, each exactly as on its own: filters of equal radius share one
/// pass, so each sample's finiteness test and footprint are computed once per radius and each filter adds
/// only its weights and accumulation.
void splatAll(const SampleBuffer& samples, const SplatTargets& targets, int threads);

/// Adds (L, 1) of each pixel's own finite samples into `plain` (r, g, b, count per pixel); returns the
/// number of samples skipped as non-finite.
size_t addPlainSums(const SampleBuffer& samples, double* plain);

/// Turns weighted sums into an image with the documented degenerate outcomes.
Reconstruction resolveSums(int width, int height, const double* sums, const double* plain, double tolerance,
                           size_t nonFiniteSamples);

/// 1e-8 * |f(0, 0)| (at least 1e-30).
double weightTolerance(const Filter& filter);

Reconstruction reconstructSupersample(const SampleBuffer& samples, int threads);

}  // namespace aliaslab::filmimpl
