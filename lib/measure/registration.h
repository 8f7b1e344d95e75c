// Registering a frame to the content (docs/science.md, "Motion"): a camera translating by d = (dx, dy) pixels
// per frame shows in frame t + 1 at film position p what frame t showed at p + d (scene/camera.h). Frame t + 1
// moved by +d, R(p) = I_{t+1}(p - d), is then frame t wherever the content is the same: the change left is
// what the eye following the content sees change.
//
// Interpolation: band-limited, separable. Each row (then each column) of N values is extended by its mirror
// image to 2 N values (even about the border, so the extension is continuous there and has no jump to ring
// from), transformed by a DFT of length 2 N, multiplied by the phase ramp exp(-2 pi i k s / 2N) (k the signed
// frequency index; the Nyquist bin k = N by cos(pi s), which keeps the result real) and transformed back; the
// first N values are the shifted row. A signal band-limited below Nyquist and symmetric at the border (or
// negligible there) moves exactly; otherwise the border's slope discontinuity leaves an error that decays as
// the square of the distance from the border.
//
// Border: compared pixels keep registrationMargin(dx, dy) pixels from every side: the content entering the
// picture (ceil(|d|) pixels, absent from frame t) and kRegistrationGuard more for the interpolation's border
// error.
#pragma once
#include <vector>

#include "core/image.h"

namespace aliaslab {

/// Pixels kept clear of the interpolation's border error beyond the motion itself.
constexpr int kRegistrationGuard = 8;

/// Pixels left out on every side where registered frames are compared: ceil(max(|dx|, |dy|)) + kRegistrationGuard.
int registrationMargin(double dx, double dy);

/// `image` moved by (sx, sy) pixels, out(p) = image(p - s), by band-limited interpolation (above); interleaved
/// RGB in double precision, bottom row first like Image::data(). Throws std::invalid_argument for a non-finite
/// shift.
std::vector<double> shiftImage(const Image& image, double sx, double sy);

}  // namespace aliaslab
