// The spectra's 2-D DFTs (spectrum_dft.h): Eigen's FFT along rows, then along columns.
#include "measure/spectrum_dft.h"

#include <algorithm>
#include <unsupported/Eigen/FFT>

namespace aliaslab::spectrumimpl {

namespace {

/// A 1-D forward FFT of n values; a 1-point DFT is the identity (Eigen's FFT has no plan for length 1 and
/// crashes), so an image 1 pixel wide or high transforms along its other side only.
void forward(Complex* to, const Complex* from, int n) {
  thread_local Eigen::FFT<double> fft;  // keeps its plans (twiddles) per length between calls
  if (n == 1) to[0] = from[0];
  else fft.fwd(to, from, n);
}

/// The column FFTs (length h) of the first `columns` columns of the row-major plane `out` (row stride
/// `stride`). Columns go through in blocks of kColumns adjacent ones, gathered and scattered a row of the block
/// at a time (whole cache lines instead of one value per line); every FFT sees the same input as a
/// column-by-column loop would give it, so the same bits.
void columnFfts(std::vector<Complex>& out, int stride, int columns, int h) {
  constexpr int kColumns = 8;
  thread_local std::vector<Complex> block, blockOut;
  block.resize(static_cast<size_t>(kColumns) * h), blockOut.resize(static_cast<size_t>(kColumns) * h);
  for (int u0 = 0; u0 < columns; u0 += kColumns) {
    const int m = std::min(kColumns, columns - u0);
    for (int y = 0; y < h; ++y)
      for (int k = 0; k < m; ++k) block[static_cast<size_t>(k) * h + y] = out[static_cast<size_t>(y) * stride + u0 + k];
    for (int k = 0; k < m; ++k)
      forward(blockOut.data() + static_cast<size_t>(k) * h, block.data() + static_cast<size_t>(k) * h, h);
    for (int v = 0; v < h; ++v)
      for (int k = 0; k < m; ++k) out[static_cast<size_t>(v) * stride + u0 + k] = blockOut[static_cast<size_t>(k) * h + v];
  }
}

/// Value x of row y of channel c: image - subtract, in double.
inline double value(const float* a, const float* b, int w, int x, int y, int c) {
  const size_t i = 3 * (static_cast<size_t>(y) * w + x) + c;
  return static_cast<double>(a[i]) - (b ? static_cast<double>(b[i]) : 0.0);
}

}  // namespace

void dft2(const Image& image, const Image* subtract, int c, std::vector<Complex>& out) {
  const int w = image.width(), h = image.height();
  thread_local std::vector<Complex> line;
  out.resize(static_cast<size_t>(w) * h);
  line.resize(w);
  const float* a = image.data();
  const float* b = subtract ? subtract->data() : nullptr;
  for (int y = 0; y < h; ++y) {
    for (int x = 0; x < w; ++x) line[x] = Complex(value(a, b, w, x, y, c), 0.0);
    forward(out.data() + static_cast<size_t>(y) * w, line.data(), w);
  }
  columnFfts(out, w, w, h);
}

void halfDft2(const Image& image, const Image* subtract, int c, std::vector<Complex>& out) {
  const int w = image.width(), h = image.height(), hw = halfWidth(w);
  thread_local std::vector<Complex> line, z;
  out.resize(static_cast<size_t>(hw) * h);
  line.resize(w), z.resize(w);
  const float* a = image.data();
  const float* b = subtract ? subtract->data() : nullptr;
  for (int y = 0; y < h; y += 2) {
    const bool pair = y + 1 < h;  // an odd last row goes alone (imaginary part 0)
    for (int x = 0; x < w; ++x) line[x] = Complex(value(a, b, w, x, y, c), pair ? value(a, b, w, x, y + 1, c) : 0.0);
    forward(z.data(), line.data(), w);
    // Z = A + i B with A, B the real rows' DFTs: A(u) = (Z(u) + conj Z(-u)) / 2, B(u) = (Z(u) - conj Z(-u)) / 2i
    Complex* first = out.data() + static_cast<size_t>(y) * hw;
    Complex* second = pair ? first + hw : nullptr;
    // Written out on the parts: the same operations as 0.5 (zu + zm) and Complex(0, -0.5) (zu - zm) in
    // std::complex (a full product, 0 x d_re - (-0.5) x d_im and 0 x d_im + (-0.5) x d_re, with its recovery
    // when both parts come out NaN), without the round trip through memory the compiler made of them.
    for (int u = 0; u < hw; ++u) {
      const Complex zu = z[u], zn = z[u == 0 ? 0 : w - u];  // z(-u): -u mod w without an integer division
      const double ar = zu.real(), ai = zu.imag(), br = zn.real(), bi = -zn.imag();  // zm = conj z(-u)
      first[u] = Complex(0.5 * (ar + br), 0.5 * (ai + bi));
      if (!pair) continue;
      const double dr = ar - br, di = ai - bi;
      const double re = 0.0 * dr - (-0.5) * di, im = 0.0 * di + (-0.5) * dr;
      second[u] = std::isnan(re) && std::isnan(im) ? Complex(0, -0.5) * Complex(dr, di) : Complex(re, im);
    }
  }
  columnFfts(out, hw, hw, h);
}

}  // namespace aliaslab::spectrumimpl
