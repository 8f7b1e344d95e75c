// Pre-filtering: texture values averaged over a pixel's footprint instead of
// point-sampled, so that frequencies a pixel cannot hold are removed before
// sampling (docs/prefiltering.md gives the derivations and approximations).
//
// A footprint reaches a procedural material as two texture-space vectors
// dqdx, dqdy (one pixel's parallelogram q + a dqdx + b dqdy, |a|, |b| <= 1/2).
// The functions below work on what the patterns need from it:
//   - the half-widths of the axis-aligned box that bounds the parallelogram,
//     h_i = (|dqdx_i| + |dqdy_i|) / 2: box averages are exact over this box;
//   - one width W = max(|dqdx|, |dqdy|) (the longer side) for frequency
//     clamping: a component of wavelength lambda is kept whole when
//     lambda >= 2 W, dropped (replaced by its mean) when lambda <= W, and
//     faded linearly in log2(lambda / W) in between.
// Every average is computed in double precision. With a zero width each
// function returns the point value.
#pragma once
#include "core/math.h"

namespace aliaslab {

/// Texture-space footprint: the two axes of one pixel's parallelogram.
struct TextureFootprint {
  Vec3 dqdx = Vec3::Zero(), dqdy = Vec3::Zero();
  /// Half-widths of the axis-aligned bounding box of the parallelogram.
  Vec3 halfWidths() const { return 0.5f * (dqdx.cwiseAbs() + dqdy.cwiseAbs()); }
  /// The longer axis, the width used for frequency clamping.
  float width() const { return std::max(dqdx.norm(), dqdy.norm()); }
};

/// Weight in [0, 1] of a component of wavelength `lambda` under clamping
/// with footprint width W: clamp(log2(lambda / W), 0, 1); 1 when W <= 0.
float octaveWeight(float lambda, float width);

/// Average over [t - h, t + h] of the checker sign s(t) = (-1)^floor(t).
double checkerSignAverage(double t, double h);

/// Average over [u - h, u + h] of the square wave that is 1 where
/// frac(u) < 1/2 and 0 elsewhere (period 1).
double squareWaveAverage(double u, double h);

/// Average over [t - h, t + h] of sinc(t) = sin(pi t) / (pi t).
double sincAverage(double t, double h);

/// The sine integral Si(x) = integral from 0 to x of sin(u)/u du
/// (power series up to |x| = 20, asymptotic expansion beyond; error about 1e-8).
double sineIntegral(double x);

/// sin(x) / x, 1 at 0: the factor a box of half-width h multiplies a
/// sinusoid of angular frequency k by, with x = k h.
double boxAttenuation(double x);

}  // namespace aliaslab
