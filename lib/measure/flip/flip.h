// LDR-FLIP: the perceptual difference of Andersson et al. 2020, "FLIP: A
// Difference Evaluator for Alternating Images" (HPG 2020), for images with
// values in [0, 1] (docs/flip.md explains every step and constant).
//
// Protocol: flipMap(test, reference) returns one value per pixel in [0, 1]
// (0: no visible difference, 1: the largest difference, as between pure
// green and pure blue); meanFlip is its mean, the number reported by
// imgdiff and the sweep's `flip` column. Inputs are linear RGB images of the
// same size, clamped to [0, 1] first (LDR); the viewing condition is given
// in pixels per degree of visual angle (default: 67, a 0.7 m wide 4K screen
// seen from 0.7 m, the paper's default). The map is symmetric in its two
// arguments and a pure function of them.
//
// Precision: the cube roots, hypotenuses and powers per pixel are computed by range reduction and series, two
// pixels per instruction (flip_fastmath.h); the map is within about 1e-12 per pixel, and the mean within the
// documented tolerance of 1e-6, of the scalar definition with libm (flip_definition.h, the reference
// implementation the tests compare against). The convolutions are exact sums, the same bits on every path.
#pragma once
#include <array>
#include <vector>

#include "core/image.h"
#include "measure/flip/flip_planes.h"

namespace aliaslab {

inline constexpr double kFlipDefaultPixelsPerDegree = 67.0;

/// Per-pixel LDR-FLIP of `test` against `reference` (same size; throws
/// std::invalid_argument otherwise). Row-major like Image, values in [0, 1].
std::vector<float> flipMap(const Image& test, const Image& reference,
                           double pixelsPerDegree = kFlipDefaultPixelsPerDegree);

/// Mean of flipMap over the pixels.
double meanFlip(const Image& test, const Image& reference, double pixelsPerDegree = kFlipDefaultPixelsPerDegree);

/// One reference, prepared once (its filtered Lab and feature planes), then
/// compared against many test images: the sweep compares every seed's image
/// of every row against the same target, so half of each comparison's work
/// is done once per scene instead. map()/mean() give exactly the numbers of
/// flipMap()/meanFlip() with this reference (same arithmetic, same order).
/// Read-only after construction, so one object may serve many threads.
/// meanFlips compares one image with several such targets, preparing the
/// image's side once (the sweep's row against its three targets).
class FlipReference {
 public:
  explicit FlipReference(const Image& reference, double pixelsPerDegree = kFlipDefaultPixelsPerDegree);
  std::vector<float> map(const Image& test) const;
  double mean(const Image& test) const;

 private:
  friend std::vector<double> meanFlips(const Image&, const std::vector<const FlipReference*>&);
  FlipPlanes prepare(const Image& test) const;  ///< the test image's planes (checks its size)
  double ppd_;
  FlipPlanes planes_;
};

/// mean(test) against each target, in order: the same numbers as targets[j]->mean(test), the image's stages 1
/// and 2 done once. Targets must share size and viewing condition (std::invalid_argument otherwise).
std::vector<double> meanFlips(const Image& test, const std::vector<const FlipReference*>& targets);

/// The separable convolution behind both pipelines, exposed for tests: kx along x, then ky along y, of a
/// w x h row-major plane, kernels of odd length centred on the pixel, indices clamped at the edges; every
/// output is the textbook sum over k = -r .. r in that order, started at 0, bit for bit.
std::vector<double> convolveClamped(const std::vector<double>& in, int w, int h, const std::vector<double>& kx,
                                    const std::vector<double>& ky);

}  // namespace aliaslab
