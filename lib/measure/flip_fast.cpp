// Stages 2 and 3 of LDR-FLIP, fast (flip_planes.h): the definition's formulas on two pixels per SSE2
// instruction, with flip_fastmath.h's cube root, logarithm and power instead of libm's. The last odd pixel
// takes the same operations on one lane, so every pixel gets the same bits wherever it lies.
#include <emmintrin.h>

#include <algorithm>
#include <cmath>

#include "measure/flip_colour.h"
#include "measure/flip_fastmath.h"
#include "measure/flip_planes.h"

namespace aliaslab {
namespace {

using namespace flipcolour;
using namespace flipmath;

constexpr double kQc = 0.7, kPc = 0.4, kPt = 0.95;
constexpr double kMinNormal = 2.2250738585072014e-308;

template <int L>
[[gnu::always_inline]] inline Dv<L> load(const double* p) {
  Dv<L> v;
  std::memcpy(&v, p, sizeof v);
  return v;
}
template <int L>
[[gnu::always_inline]] inline void store(double* p, const Dv<L>& v) {
  std::memcpy(p, &v, sizeof v);
}
template <int L>
[[gnu::always_inline]] inline Dv<L> vsqrt(const Dv<L>& v) {
  if constexpr (L == 2) {
    return _mm_sqrt_pd(v);
  } else {
    static_assert(L == 1);
    return Dv<1>{_mm_cvtsd_f64(_mm_sqrt_sd(_mm_setzero_pd(), _mm_set_sd(v[0])))};
  }
}
template <int L>
[[gnu::always_inline]] inline Dv<L> vabs(const Dv<L>& v) {
  return v < 0.0 ? -v : v;
}
template <int L>
[[gnu::always_inline]] inline Dv<L> labF(const Dv<L>& t) {
  return t > kLabD3 ? cbrtPositive<L>(t) : labLinear(t);
}
/// x^p for x >= 0 and p > 0 (0 for x = 0 or below the normal range).
template <int L>
[[gnu::always_inline]] inline Dv<L> powPositive(const Dv<L>& x, const Dv<L>& p) {
  const Dv<L> safe = x < kMinNormal ? splat<L>(1.0) : x;
  const Dv<L> r = exp2Of<L>(p * log2Positive<L>(safe));
  return x < kMinNormal ? splat<L>(0.0) : r;
}

template <int L>
[[gnu::always_inline]] inline void planes(const FlipLinear& in, FlipPlanes& out, size_t i) {
  const auto x = rgbToXyz(load<L>(&in.rgb[0][i]), load<L>(&in.rgb[1][i]), load<L>(&in.rgb[2][i]));
  const auto lab = huntFromF(labF<L>(x[0] / kWx), labF<L>(x[1] / kWy), labF<L>(x[2] / kWz));
  store<L>(&out.L[i], lab[0]), store<L>(&out.a[i], lab[1]), store<L>(&out.b[i], lab[2]);
  const Dv<L> gx = load<L>(&in.gx[i]), gy = load<L>(&in.gy[i]), px = load<L>(&in.px[i]), py = load<L>(&in.py[i]);
  store<L>(&out.edge[i], vsqrt<L>(gx * gx + gy * gy)), store<L>(&out.point[i], vsqrt<L>(px * px + py * py));
}

template <int L>
[[gnu::always_inline]] inline void combine(const FlipPlanes& t, const FlipPlanes& r, float* out, size_t i,
                                           double cmax) {
  const Dv<L> dL = vabs<L>(load<L>(&t.L[i]) - load<L>(&r.L[i]));
  const Dv<L> da = load<L>(&t.a[i]) - load<L>(&r.a[i]), db = load<L>(&t.b[i]) - load<L>(&r.b[i]);
  const Dv<L> dc = powPositive<L>(dL + vsqrt<L>(da * da + db * db), splat<L>(kQc));
  const Dv<L> ec = dc < kPc * cmax ? dc * (kPt / (kPc * cmax))
                                   : kPt + (dc - kPc * cmax) / (cmax - kPc * cmax) * (1 - kPt);
  const Dv<L> de = vabs<L>(load<L>(&t.edge[i]) - load<L>(&r.edge[i]));
  const Dv<L> dp = vabs<L>(load<L>(&t.point[i]) - load<L>(&r.point[i]));
  const Dv<L> ef = vsqrt<L>((de > dp ? de : dp) / 1.4142135623730951);
  const Dv<L> base = ec < 1.0 ? ec : splat<L>(1.0), p = 1.0 - (ef < 1.0 ? ef : splat<L>(1.0));
  Dv<L> v = powPositive<L>(base, p);
  v = p == 0.0 ? splat<L>(1.0) : v;  // x^0 = 1, 0^0 included
  v = v < 0.0 ? splat<L>(0.0) : (v > 1.0 ? splat<L>(1.0) : v);
  for (int l = 0; l < L; ++l) out[i + l] = static_cast<float>(v[l]);
}

}  // namespace

FlipPlanes flipPlanesFast(const FlipLinear& in) {
  FlipPlanes p;
  p.width = in.width, p.height = in.height;
  const size_t n = in.gx.size();
  p.L.resize(n), p.a.resize(n), p.b.resize(n), p.edge.resize(n), p.point.resize(n);
  size_t i = 0;
  for (; i + 2 <= n; i += 2) planes<2>(in, p, i);
  for (; i < n; ++i) planes<1>(in, p, i);
  return p;
}

void flipCombineFast(const FlipPlanes& t, const FlipPlanes& r, float* out) {
  const double cmax = flipColourMax();
  const size_t n = t.L.size();
  size_t i = 0;
  for (; i + 2 <= n; i += 2) combine<2>(t, r, out, i, cmax);
  for (; i < n; ++i) combine<1>(t, r, out, i, cmax);
}

}  // namespace aliaslab
