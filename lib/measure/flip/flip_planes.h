// The three stages of LDR-FLIP (flip.h, docs/flip.md), shared by the fast implementation (flip.cpp) and the
// scalar definition (flip_definition.cpp):
//   1. flipLinear: the linear part of both pipelines: the contrast sensitivity filters of the opponent channels
//      (back in linear RGB, clamped) and the four Gaussian-derivative responses of the luminance. Exact
//      textbook sums (flip_convolve.cpp), one code for both implementations, the same bits on every CPU path.
//   2. planes: per pixel, Hunt-adjusted CIELab of the filtered colour (three cube roots) and the edge and
//      point magnitudes (two hypotenuses) of one image. A target's planes are made once and reused for every
//      image compared with it; an image's planes once for all the targets it is compared with.
//   3. combine: per pixel, HyAB between the Lab planes of the two images raised to 0.7, normalised, and
//      colour^(1 - feature) with the feature difference raised to 0.5.
// Stages 2 and 3 exist twice: the definition (libm's cbrt, hypot, pow in double, one pixel at a time: the
// reference implementation) and the fast one (flip_fastmath.h: the same formulas with cube roots, logarithms
// and powers computed by range reduction and series, several pixels per instruction; stage 3 in single
// precision after the planes' differences), which agrees with the definition to about 1e-7 per pixel
// (documented tolerance: 1e-6 per image mean and per pixel, docs/flip.md, tests/unit/measure/flip/flip_test).
#pragma once
#include <array>
#include <functional>
#include <vector>

#include "core/image.h"

namespace aliaslab {

/// Stage 1 of one image.
struct FlipLinear {
  int width = 0, height = 0;
  std::array<std::vector<double>, 3> rgb;  ///< CSF-filtered colour in linear RGB, clamped to [0, 1]
  std::vector<double> gx, gy, px, py;      ///< normalised edge (first) and point (second derivative) responses
};
FlipLinear flipLinear(const Image& img, double ppd);

/// Stage 1's kernels at ppd pixels per degree. A channel's CSF is (A1 e1(x) e1(y) + A2 e2(x) e2(y)) / total;
/// the edge planes are the sums with d1 along one axis and g along the other divided by edge, the point planes
/// the sums with d2p divided by pos plus those with d2n divided by neg.
struct FlipCsfKernel {
  std::vector<double> e1, e2;
  double A1, A2, total;
};
std::array<FlipCsfKernel, 3> flipCsfKernels(double ppd);
struct FlipFeatureKernels {
  std::vector<double> g, d1, d2p, d2n;
  double edge, pos, neg;
};
FlipFeatureKernels flipFeatureKernels(double ppd);

/// Stage 2 of one image (row-major planes).
struct FlipPlanes {
  int width = 0, height = 0;
  std::vector<double> L, a, b;   ///< Hunt-adjusted CIELab
  std::vector<double> edge, point;
};
FlipPlanes flipPlanesDefinition(const FlipLinear& lin);
FlipPlanes flipPlanesFast(const FlipLinear& lin);

/// Stage 3: out[i] for every pixel of two images' planes (same size).
void flipCombineDefinition(const FlipPlanes& test, const FlipPlanes& ref, float* out);
void flipCombineFast(const FlipPlanes& test, const FlipPlanes& ref, float* out);

/// The largest colour difference of the gamut, pure green against pure blue, raised to 0.7 (the definition's).
double flipColourMax();

/// convolveClamped(in, w, h, kx, *ky[j]) for every j, one output row y = 0 .. h - 1 at a time: sink(y, rows) gets
/// row y of each (rows[j], valid during the call), the same bits, without a plane for any of them.
void convolveClampedRows(const std::vector<double>& in, int w, int h, const std::vector<double>& kx,
                         const std::vector<const std::vector<double>*>& ky,
                         const std::function<void(int y, const double* const* rows)>& sink);

}  // namespace aliaslab
