// The fast stages 2 and 3 of LDR-FLIP (flip_planes.h) on L pixels at a time (L = 1, 2 or 4 doubles per GCC
// vector), for flip_fast.cpp (SSE2, built for any x86-64-v2 CPU) and flip_fast_avx2.cpp (built with -mavx2,
// called only where the CPU has AVX2). Every lane takes the same IEEE operations (no FMA), so a pixel gets the
// same bits on either path and at either position (blocks of L, then single pixels).
#pragma once
#include <immintrin.h>

#include <cstddef>

#include "measure/flip/flip_colour.h"
#include "measure/flip/flip_fastmath.h"

namespace aliaslab::flipkernels {

/// Raw planes (no library types cross into the AVX2 translation unit).
struct LinearIn { const double *r, *g, *b, *gx, *gy, *px, *py; };
struct Planes { double *L, *a, *b, *edge, *point; };
struct PlanesIn { const double *L, *a, *b, *edge, *point; };

namespace {  // one copy per translation unit (flip_fastmath.h says why)

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
  if constexpr (L == 4) {
#ifdef __AVX__
    return _mm256_sqrt_pd(v);
#endif
  } else if constexpr (L == 2) {
    return _mm_sqrt_pd(v);
  } else {
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

/// Stage 2 of pixels i .. i + L - 1: Hunt-adjusted Lab and the edge and point magnitudes.
template <int L>
[[gnu::always_inline]] inline void planesAt(const LinearIn& in, const Planes& out, size_t i) {
  const auto x = rgbToXyz(load<L>(in.r + i), load<L>(in.g + i), load<L>(in.b + i));
  const auto lab = huntFromF(labF<L>(x[0] / kWx), labF<L>(x[1] / kWy), labF<L>(x[2] / kWz));
  store<L>(out.L + i, lab[0]), store<L>(out.a + i, lab[1]), store<L>(out.b + i, lab[2]);
  const Dv<L> gx = load<L>(in.gx + i), gy = load<L>(in.gy + i), px = load<L>(in.px + i), py = load<L>(in.py + i);
  store<L>(out.edge + i, vsqrt<L>(gx * gx + gy * gy)), store<L>(out.point + i, vsqrt<L>(px * px + py * py));
}

/// Stage 3 of pixels i .. i + L - 1: colour^(1 - feature) of test t against reference r.
template <int L>
[[gnu::always_inline]] inline void combineAt(const PlanesIn& t, const PlanesIn& r, float* out, size_t i,
                                             double cmax) {
  const Dv<L> dL = vabs<L>(load<L>(t.L + i) - load<L>(r.L + i));
  const Dv<L> da = load<L>(t.a + i) - load<L>(r.a + i), db = load<L>(t.b + i) - load<L>(r.b + i);
  const Dv<L> dc = powPositive<L>(dL + vsqrt<L>(da * da + db * db), splat<L>(kQc));
  const Dv<L> ec = dc < kPc * cmax ? dc * (kPt / (kPc * cmax))
                                   : kPt + (dc - kPc * cmax) * ((1 - kPt) / (cmax - kPc * cmax));
  const Dv<L> de = vabs<L>(load<L>(t.edge + i) - load<L>(r.edge + i));
  const Dv<L> dp = vabs<L>(load<L>(t.point + i) - load<L>(r.point + i));
  const Dv<L> ef = vsqrt<L>((de > dp ? de : dp) * 0.70710678118654752);
  const Dv<L> base = ec < 1.0 ? ec : splat<L>(1.0), p = 1.0 - (ef < 1.0 ? ef : splat<L>(1.0));
  Dv<L> v = powPositive<L>(base, p);
  v = p == 0.0 ? splat<L>(1.0) : v;  // x^0 = 1, 0^0 included
  v = v < 0.0 ? splat<L>(0.0) : (v > 1.0 ? splat<L>(1.0) : v);
  for (int l = 0; l < L; ++l) out[i + l] = static_cast<float>(v[l]);
}

template <int L>
[[gnu::always_inline]] inline void planesRange(const LinearIn& in, const Planes& out, size_t n) {
  size_t i = 0;
  for (; i + L <= n; i += L) planesAt<L>(in, out, i);
  for (; i < n; ++i) planesAt<1>(in, out, i);
}
template <int L>
[[gnu::always_inline]] inline void combineRange(const PlanesIn& t, const PlanesIn& r, float* out, size_t n,
                                                double cmax) {
  size_t i = 0;
  for (; i + L <= n; i += L) combineAt<L>(t, r, out, i, cmax);
  for (; i < n; ++i) combineAt<1>(t, r, out, i, cmax);
}

}  // namespace

/// The AVX2 instantiations (flip_fast_avx2.cpp); call only where cpuFeatures().avx2 (core/cpu.h).
void planesAvx2(const LinearIn& in, const Planes& out, size_t n);
void combineAvx2(const PlanesIn& t, const PlanesIn& r, float* out, size_t n, double cmax);

}  // namespace aliaslab::flipkernels
