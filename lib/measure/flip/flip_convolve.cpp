// The separable convolutions of FLIP (flip.h convolveClamped; flip_planes.h stage 1): exact textbook sums,
// the same bits on the SSE2 and the AVX2 path.
#include <algorithm>
#include <functional>
#include <stdexcept>
#include <vector>

#include "core/cpu.h"
#include "measure/flip/flip.h"
#include "measure/flip/flip_planes.h"

// 256-bit vectors are passed only between functions inlined into one built for AVX2 (GCC's -Wpsabi note).
#pragma GCC diagnostic ignored "-Wpsabi"

namespace aliaslab {
namespace {

// dst[x] = sum_k c[k] src[k][x] for x in [0, n), each sum started at 0 and taken in the order of k (the
// textbook loop's operations: a multiply, then an add, per tap). Blocks of 8 vectors of x stay in registers
// across the taps; 2 lanes per SSE2 vector, 4 per AVX one where the CPU has AVX2 (chosen at run time, built
// without FMA, so nothing is contracted): the same IEEE operations per element on either path, so the same
// bits.
using D2 = double __attribute__((vector_size(16)));
using D4 = double __attribute__((vector_size(32)));
template <class V>
[[gnu::always_inline]] inline V load(const double* p) {
  V v;
  __builtin_memcpy(&v, p, sizeof v);
  return v;
}
// A vectors of x from x on: A independent chains of adds, enough to cover the add's latency.
template <class V, int A>
[[gnu::always_inline]] inline void weightedBlock(double* dst, const double* const* src, const double* c, int taps,
                                                 int x) {
  constexpr int L = sizeof(V) / sizeof(double);
  V a[A] = {};
  for (int k = 0; k < taps; ++k) {
    V ck;
    for (int l = 0; l < L; ++l) ck[l] = c[k];
    const double* p = src[k] + x;
#pragma GCC unroll 8
    for (int j = 0; j < A; ++j) a[j] += ck * load<V>(p + j * L);
  }
#pragma GCC unroll 8
  for (int j = 0; j < A; ++j) __builtin_memcpy(dst + x + j * L, &a[j], sizeof(V));
}
template <class V>
[[gnu::always_inline]] inline void weightedSum(double* dst, const double* const* src, const double* c, int taps,
                                               int n) {
  constexpr int L = sizeof(V) / sizeof(double);
  int x = 0;
  for (; x + 8 * L <= n; x += 8 * L) weightedBlock<V, 8>(dst, src, c, taps, x);
  for (; x + L <= n; x += L) weightedBlock<V, 1>(dst, src, c, taps, x);
  for (; x < n; ++x) {
    double sum = 0;
    for (int k = 0; k < taps; ++k) sum += c[k] * src[k][x];
    dst[x] = sum;
  }
}
void weightedSumSse2(double* dst, const double* const* src, const double* c, int taps, int n) {
  weightedSum<D2>(dst, src, c, taps, n);
}
[[gnu::target("avx2")]] void weightedSumAvx(double* dst, const double* const* src, const double* c, int taps, int n) {
  weightedSum<D4>(dst, src, c, taps, n);
}
void weightedRows(double* dst, const double* const* src, const double* c, int taps, int n) {
  (cpuFeatures().avx2 ? weightedSumAvx : weightedSumSse2)(dst, src, c, taps, n);
}

// The taps of a kernel that are not zero, in order. A sum started at +0 is never -0 (round to nearest), and
// adding c * x = +-0 to it for finite x changes nothing, so leaving the zero taps out keeps every bit of the
// textbook sum: FLIP's second-derivative kernels are zero on most of their support (d2n is non-zero only for
// |k| <= sd, d2p only beyond), the first derivative at k = 0.
struct NonZeroTaps {
  std::vector<int> offset;  ///< k + r of each tap kept
  std::vector<double> c;
  explicit NonZeroTaps(const std::vector<double>& kernel) {
    for (size_t k = 0; k < kernel.size(); ++k)
      if (kernel[k] != 0) offset.push_back(static_cast<int>(k)), c.push_back(kernel[k]);
  }
  int size() const { return static_cast<int>(c.size()); }
};

/// One row's x pass: the row copied with its edge values repeated rx times on either side, so every pixel
/// (border ones too) is one weightedRows sum over the kernel's taps in order, starting from 0.
class XPass {
 public:
  XPass(const std::vector<double>& kx, int w)
      : nz_(kx), rx_(static_cast<int>(kx.size()) / 2), w_(w), padded_(static_cast<size_t>(w) + 2 * rx_),
        taps_(nz_.size()) {
    for (int j = 0; j < nz_.size(); ++j) taps_[j] = padded_.data() + nz_.offset[j];
  }
  void row(const double* in, double* out) {
    std::fill(padded_.begin(), padded_.begin() + rx_, in[0]);
    std::copy(in, in + w_, padded_.begin() + rx_);
    std::fill(padded_.begin() + rx_ + w_, padded_.end(), in[w_ - 1]);
    weightedRows(out, taps_.data(), nz_.c.data(), nz_.size(), w_);
  }

 private:
  NonZeroTaps nz_;
  int rx_, w_;
  std::vector<double> padded_;
  std::vector<const double*> taps_;
};

}  // namespace

/// The rows of the separable sums (kx along x, then ky[j] along y) for every j, made one output row at a time:
/// the x pass's rows are made as the y passes first need them, into a ring of min(2 ry + 1, h) rows (the
/// clamped window of any output row spans no more), so no intermediate plane is allocated and the ring stays
/// in cache; every sum is the one the two passes over whole planes would take.
void convolveClampedRows(const std::vector<double>& in, int w, int h, const std::vector<double>& kx,
                         const std::vector<const std::vector<double>*>& ky,
                         const std::function<void(int y, const double* const* rows)>& sink) {
  bool odd = kx.size() % 2 == 1;
  size_t ryMax = 0;
  for (const auto* k : ky) odd = odd && k->size() % 2 == 1, ryMax = std::max(ryMax, k->size() / 2);
  if (!odd || in.size() != static_cast<size_t>(w) * h)
    throw std::invalid_argument("convolveClamped: kernels of odd length and a w x h plane expected");
  if (w == 0 || h == 0) return;  // no rows, or rows without an edge value to repeat
  const int slots = std::min(2 * static_cast<int>(ryMax) + 1, h);
  std::vector<NonZeroTaps> nz;
  for (const auto* k : ky) nz.emplace_back(*k);
  XPass pass(kx, w);
  std::vector<double> ring(static_cast<size_t>(slots) * w), outRows(ky.size() * static_cast<size_t>(w));
  std::vector<double*> outs(ky.size());
  for (size_t j = 0; j < ky.size(); ++j) outs[j] = outRows.data() + j * w;
  std::vector<const double*> rows;
  const auto ringRow = [&](int j) { return ring.data() + static_cast<size_t>(j % slots) * w; };
  int made = 0;  // rows of the x pass made so far
  for (int y = 0; y < h; ++y) {
    for (; made <= std::min<int>(h - 1, y + ryMax); ++made)
      pass.row(in.data() + static_cast<size_t>(made) * w, ringRow(made));
    for (size_t j = 0; j < ky.size(); ++j) {  // taps over the x pass's rows, clamped at the edges
      const int ry = static_cast<int>(ky[j]->size()) / 2;
      rows.resize(nz[j].size());
      for (int t = 0; t < nz[j].size(); ++t) rows[t] = ringRow(std::clamp(y + nz[j].offset[t] - ry, 0, h - 1));
      weightedRows(outs[j], rows.data(), nz[j].c.data(), nz[j].size(), w);
    }
    sink(y, outs.data());
  }
}

std::vector<double> convolveClamped(const std::vector<double>& in, int w, int h, const std::vector<double>& kx,
                                    const std::vector<double>& ky) {
  std::vector<double> out(in.size());
  convolveClampedRows(in, w, h, kx, {&ky}, [&](int y, const double* const* rows) {
    std::copy(rows[0], rows[0] + w, out.begin() + static_cast<size_t>(y) * w);
  });
  return out;
}

}  // namespace aliaslab
