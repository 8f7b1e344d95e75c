// How two images differ, as one set of numbers (the imgdiff program prints them).
// A is the test image, B the reference, of the same size; over every pixel and
// channel with D = A - B:
//   mse      mean D^2
//   relmse   mean D^2 / (B^2 + 0.01)   (relative, for HDR data)
//   psnr_db  10 log10(1 / mse)         (peak 1; inf for identical images)
//   bias     mean D, spread its standard deviation (population): mse = bias^2 + spread^2
//   max_abs  largest |D|
// The FLIP map and its mean are measure/flip/flip.h.
#pragma once
#include "core/image.h"

namespace aliaslab {

struct ImageDifference {
  double mse = 0, relmse = 0, psnr = 0, bias = 0, spread = 0, maxAbs = 0;
};

/// The differences of `a` against the reference `b` (same size: the caller checks).
ImageDifference imageDifference(const Image& a, const Image& b);

/// The per-pixel difference a - b (an image of signed values, for a false-colour picture).
Image differenceImage(const Image& a, const Image& b);

}  // namespace aliaslab
