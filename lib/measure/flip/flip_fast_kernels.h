// The fast stages 2 and 3 of LDR-FLIP (flip_planes.h) on L pixels at a time, for flip_fast.cpp (SSE2, built
// for any x86-64-v2 CPU: stage 2 on 2 doubles, stage 3 on 4 floats per instruction) and flip_fast_avx2.cpp
// (built with -mavx2, called only where the CPU has AVX2: 4 doubles, 8 floats). Stage 2 is in double; stage 3
// in single precision after the planes' differences. Every lane takes the same IEEE operations (no FMA), so a
// pixel gets the same bits on either path and at either position (blocks of L, then single pixels).
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
constexpr float kMinNormalF = 1.17549435e-38f;

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
/// x^p for x >= 0 and p > 0 in single precision (0 for x = 0 or below float's normal range).
template <int L>
[[gnu::always_inline]] inline Fv<L> powPositiveF(const Fv<L>& x, const Fv<L>& p) {
  const Fv<L> safe = x < kMinNormalF ? splatF<L>(1.0f) : x;
  const Fv<L> r = exp2OfF<L>(p * log2PositiveF<L>(safe));
  return x < kMinNormalF ? splatF<L>(0.0f) : r;
}
template <int L>
[[gnu::always_inline]] inline Fv<L> vsqrtF(const Fv<L>& v) {
  if constexpr (L == 8) {
#ifdef __AVX__
    return _mm256_sqrt_ps(v);
#endif
  } else if constexpr (L == 4) {
    return _mm_sqrt_ps(v);
  } else {
    return Fv<1>{_mm_cvtss_f32(_mm_sqrt_ss(_mm_set_ss(v[0])))};
  }
}
template <int L>
[[gnu::always_inline]] inline Fv<L> toFloat(const Dv<L>& v) {
  return __builtin_convertvector(v, Fv<L>);
}

/// Stage 3's constants in single precision, from the definition's colour maximum (flipColourMax).
struct CombineConstants {
  explicit CombineConstants(double cmax)
      : knee(static_cast<float>(kPc * cmax)), below(static_cast<float>(kPt / (kPc * cmax))),
        above(static_cast<float>((1 - kPt) / (cmax - kPc * cmax))) {}
  float knee, below, above;
};

/// Stage 2 of pixels i .. i + L - 1: Hunt-adjusted Lab and the edge and point magnitudes.
template <int L>
[[gnu::always_inline]] inline void planesAt(const LinearIn& in, const Planes& out, size_t i) {
  const auto x = rgbToXyz(load<L>(in.r + i), load<L>(in.g + i), load<L>(in.b + i));
  const auto lab = huntFromF(labF<L>(x[0] / kWx), labF<L>(x[1] / kWy), labF<L>(x[2] / kWz));
  store<L>(out.L + i, lab[0]), store<L>(out.a + i, lab[1]), store<L>(out.b + i, lab[2]);
  const Dv<L> gx = load<L>(in.gx + i), gy = load<L>(in.gy + i), px = load<L>(in.px + i), py = load<L>(in.py + i);
  store<L>(out.edge + i, vsqrt<L>(gx * gx + gy * gy)), store<L>(out.point + i, vsqrt<L>(px * px + py * py));
}

/// Stage 3 of pixels i .. i + L - 1: colour^(1 - feature) of test t against reference r. The planes'
/// differences are taken in double (no cancellation), everything after them in single precision (the
/// tolerance in docs/flip.md).
template <int L>
[[gnu::always_inline]] inline void combineAt(const PlanesIn& t, const PlanesIn& r, float* out, size_t i,
                                             const CombineConstants& k) {
  const Fv<L> dL = toFloat<L>(vabs<L>(load<L>(t.L + i) - load<L>(r.L + i)));
  const Fv<L> da = toFloat<L>(load<L>(t.a + i) - load<L>(r.a + i));
  const Fv<L> db = toFloat<L>(load<L>(t.b + i) - load<L>(r.b + i));
  const Fv<L> dc = powPositiveF<L>(dL + vsqrtF<L>(da * da + db * db), splatF<L>(static_cast<float>(kQc)));
  const Fv<L> ec = dc < k.knee ? dc * k.below : static_cast<float>(kPt) + (dc - k.knee) * k.above;
  const Dv<L> de = vabs<L>(load<L>(t.edge + i) - load<L>(r.edge + i));
  const Dv<L> dp = vabs<L>(load<L>(t.point + i) - load<L>(r.point + i));
  const Fv<L> ef = vsqrtF<L>(toFloat<L>(de > dp ? de : dp) * 0.707106781f);
  const Fv<L> one = splatF<L>(1.0f);
  const Fv<L> base = ec < 1.0f ? ec : one, p = 1.0f - (ef < 1.0f ? ef : one);
  Fv<L> v = powPositiveF<L>(base, p);
  v = p == 0.0f ? one : v;  // x^0 = 1, 0^0 included
  v = v < 0.0f ? splatF<L>(0.0f) : (v > 1.0f ? one : v);
  std::memcpy(out + i, &v, sizeof v);
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
  const CombineConstants k(cmax);
  size_t i = 0;
  for (; i + L <= n; i += L) combineAt<L>(t, r, out, i, k);
  for (; i < n; ++i) combineAt<1>(t, r, out, i, k);
}

}  // namespace

/// The AVX2 instantiations (flip_fast_avx2.cpp); call only where cpuFeatures().avx2 (core/cpu.h).
void planesAvx2(const LinearIn& in, const Planes& out, size_t n);
void combineAvx2(const PlanesIn& t, const PlanesIn& r, float* out, size_t n, double cmax);

}  // namespace aliaslab::flipkernels
