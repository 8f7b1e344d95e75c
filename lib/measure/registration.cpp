// Band-limited shift of an image (measure/registration.h).
#include "measure/registration.h"

#include <algorithm>
#include <cmath>
#include <complex>
#include <stdexcept>
#include <unsupported/Eigen/FFT>

namespace aliaslab {
namespace {
using Complex = std::complex<double>;
constexpr double kPi = 3.14159265358979323846;

// Shifts n values of `v` (stride `stride`) by s in place: mirror extension to 2 n, phase ramp, back.
class LineShifter {
 public:
  LineShifter(int n, double s) : n_(n), ramp_(2 * size_t(n)), in_(2 * size_t(n)), out_(2 * size_t(n)) {
    const int m = 2 * n;
    for (int k = 0; k < m; ++k) {
      const int signedK = k < n ? k : k - m;  // k = n (Nyquist) counted as -n: its ramp is made real below
      ramp_[k] = k == n ? Complex(std::cos(kPi * s), 0.0) : std::polar(1.0, -2 * kPi * signedK * s / m);
    }
  }
  void shift(double* v, size_t stride) {
    if (n_ == 1) return;  // one value: a constant line, which no shift changes
    const int m = 2 * n_;
    for (int i = 0; i < n_; ++i) in_[i] = in_[m - 1 - i] = Complex(v[i * stride], 0.0);
    fft_.fwd(out_.data(), in_.data(), m);
    for (int k = 0; k < m; ++k) out_[k] *= ramp_[k];
    fft_.inv(in_.data(), out_.data(), m);  // Eigen's inverse divides by m
    for (int i = 0; i < n_; ++i) v[i * stride] = in_[i].real();
  }

 private:
  int n_;
  std::vector<Complex> ramp_, in_, out_;
  Eigen::FFT<double> fft_;
};

}  // namespace

int registrationMargin(double dx, double dy) {
  return static_cast<int>(std::ceil(std::max(std::abs(dx), std::abs(dy)))) + kRegistrationGuard;
}

std::vector<double> shiftImage(const Image& image, double sx, double sy) {
  if (!std::isfinite(sx) || !std::isfinite(sy)) throw std::invalid_argument("shiftImage: the shift must be finite");
  const int w = image.width(), h = image.height();
  std::vector<double> out(image.data(), image.data() + size_t(w) * h * 3);
  if (sx != 0) {
    LineShifter rows(w, sx);
    for (int y = 0; y < h; ++y)
      for (int c = 0; c < 3; ++c) rows.shift(out.data() + 3 * size_t(y) * w + c, 3);
  }
  if (sy != 0) {
    LineShifter columns(h, sy);
    for (int x = 0; x < w; ++x)
      for (int c = 0; c < 3; ++c) columns.shift(out.data() + 3 * size_t(x) + c, 3 * size_t(w));
  }
  return out;
}

}  // namespace aliaslab
