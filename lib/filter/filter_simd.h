// Lane types and exact vector maths shared by the filters' profiles and the
// batch evaluator (internal to lib/filter): a filter that writes its profile
// for 4 lanes (g4) and 8 lanes (g8) beside the scalar g uses these, so the
// three give the same bits (see filter_batch.h).
//
// trig: sin(pi t) / (pi t) and cos(pi t) for float or lanes by the same
// operations (no libm). Lanes: Eigen's 4 floats with SSE helpers. Pack8: GCC
// vector types in functions built for AVX2 by the target attribute, exp8 and
// cos8 bit for bit Eigen's 4-lane exp and cos.
#pragma once
#include <immintrin.h>

#include <array>
#include <cmath>

#include <Eigen/Core>

#include "core/cpu.h"

// The templated profiles below are instantiated for 8 lanes (Pack8) only to be inlined into functions built
// for AVX2, so no call passes a Pack8 across the ABI that GCC's -Wpsabi note is about.
#pragma GCC diagnostic ignored "-Wpsabi"

namespace aliaslab::filterimpl {

// sin(pi t) / (pi t) and cos(pi t) for float or Eigen float lanes: the same
// operations in both, so eval() and the vectorised fast path agree bit for
// bit (no libm). The reduction f = t - round(t) is exact, so the only error
// is the float evaluation of the Taylor series in f^2 (to f^14, within 1e-8
// on |f| <= 1/2): about an ulp. Valid for |t| < 2^22.
namespace trig {
constexpr float kRound = 12582912.f;  // 1.5 * 2^23: (v + kRound) - kRound rounds v to an integer
/// Taylor coefficients in f^2 of sin(pi f) / (pi f) (odd = 1) and of cos(pi f) (odd = 0): (-1)^k pi^2k / (2k + odd)!
constexpr std::array<float, 8> taylor(int odd) {
  std::array<float, 8> c{};
  double v = 1;
  for (int k = 0; k < 8; ++k) {
    c[k] = float(v);
    v *= -(M_PI * M_PI) / ((2 * k + odd + 1) * (2 * k + odd + 2));
  }
  return c;
}
inline constexpr std::array<float, 8> kSinc = taylor(1), kCos = taylor(0);
/// Sets f = t - round(t) and returns (-1)^round(t) times the series c in f^2.
template <class T>
[[gnu::always_inline]] inline T reduced(const T& t, T& f, const std::array<float, 8>& c) {
  const T n = (t + kRound) - kRound, half = n * 0.5f;
  f = t - n;
  const T f2 = f * f, sign = 1.f - 4.f * (half - ((half - 0.25f + kRound) - kRound));  // half - floor(half): 0 or 1/2
  T p = f2 * c[7] + c[6];
  for (int k = 5; k >= 0; --k) p = p * f2 + c[k];
  return sign * p;
}
/// sin(pi t) / (pi t), 1 at t = 0.
template <class T>
[[gnu::always_inline]] inline T sincPi(const T& t) {
  T f;
  const T q = reduced(t, f, kSinc);
  return q * ((f + 1e-30f) / (t + 1e-30f));  // f / t; exactly 1 while round(t) = 0 (then f = t)
}
template <class T>
[[gnu::always_inline]] inline T cosPi(const T& t) {
  T f;
  return reduced(t, f, kCos);
}
}  // namespace trig

// Vectorised helpers (FilterBatch): 4 lanes at a time.
using Lanes = Eigen::Array4f;
inline Eigen::Map<Lanes> lanes(float* p) { return Eigen::Map<Lanes>(p); }
inline Eigen::Map<const Lanes> lanes(const float* p) { return Eigen::Map<const Lanes>(p); }

/// Lane-wise a <= bound ? v : 0 (0 for NaN a): a compare and an and.
inline Lanes keepLe(const Lanes& a, float bound, const Lanes& v) {
  Lanes out;
  _mm_storeu_ps(out.data(), _mm_and_ps(_mm_cmple_ps(_mm_loadu_ps(a.data()), _mm_set1_ps(bound)), _mm_loadu_ps(v.data())));
  return out;
}
/// Lane-wise sqrt, correctly rounded like std::sqrt (Eigen's fast-math sqrt is not).
inline Lanes sqrt4(const Lanes& v) {
  Lanes out;
  _mm_storeu_ps(out.data(), _mm_sqrt_ps(_mm_loadu_ps(v.data())));
  return out;
}
/// Lane-wise a < bound ? v : w.
inline Lanes ifLess(const Lanes& a, float bound, const Lanes& v, const Lanes& w) {
  const __m128 m = _mm_cmplt_ps(_mm_loadu_ps(a.data()), _mm_set1_ps(bound));
  Lanes out;
  _mm_storeu_ps(out.data(), _mm_or_ps(_mm_and_ps(m, _mm_loadu_ps(v.data())), _mm_andnot_ps(m, _mm_loadu_ps(w.data()))));
  return out;
}

// 8 lanes where the CPU has AVX2: GCC vector types in functions built for AVX2 by the target attribute.
// Built without FMA, nothing is contracted, so lane by lane these are the float operations of the 4-lane
// path and of eval(): the same bits on any CPU. A filter opts in with g8 (see SeparableFilter).
#define ALIASLAB_AVX2 [[gnu::always_inline, gnu::target("avx2")]] inline
using Pack8 = float __attribute__((vector_size(32)));
using Mask8 = int __attribute__((vector_size(32)));
/// Whether FilterBatch takes its 8-lane path (core/cpu.h: a test compares the paths with ScopedCpuFeatures).
inline bool eightLanes() { return cpuFeatures().avx2; }
ALIASLAB_AVX2 Pack8 load8(const float* p) {
  Pack8 v;
  __builtin_memcpy(&v, p, sizeof v);
  return v;
}
ALIASLAB_AVX2 void store8(float* p, const Pack8& v) { __builtin_memcpy(p, &v, sizeof v); }
ALIASLAB_AVX2 Pack8 abs8(const Pack8& v) { return Pack8(Mask8(v) & 0x7fffffff); }
/// Lane-wise a <= bound ? v : 0 (0 for NaN a), as keepLe.
ALIASLAB_AVX2 Pack8 keepLe8(const Pack8& a, float bound, const Pack8& v) { return Pack8((a <= bound) & Mask8(v)); }
/// Lane-wise a < bound ? v : w, as ifLess.
ALIASLAB_AVX2 Pack8 ifLess8(const Pack8& a, float bound, const Pack8& v, const Pack8& w) { return a < bound ? v : w; }
ALIASLAB_AVX2 Pack8 sqrt8(const Pack8& v) { return _mm256_sqrt_ps(v); }
/// exp in 8 lanes, bit for bit Eigen's 4-lane Array4f::exp() (Eigen 3.4's pexp_float with pldexp_generic,
/// multiply-adds unfused as in an SSE build), which the Gaussian's 4-lane path uses.
ALIASLAB_AVX2 Pack8 exp8(const Pack8& in) {
  // Eigen's pmin(a, b) / pmax(a, b) are minps(b, a) / maxps(b, a): b < a ? b : a, b > a ? b : a
  const Pack8 x0 = 88.723f < in ? Pack8{} + 88.723f : in, x = -88.723f > x0 ? Pack8{} - 88.723f : x0;
  const Pack8 m = _mm256_floor_ps(x * 1.44269504088896341f + 0.5f);
  Pack8 r = m * -0.693359375f + x;
  r = m * 2.12194440e-4f + r;
  const Pack8 r2 = r * r, r3 = r2 * r;
  Pack8 y = 1.9875691500E-4f * r + 1.3981999507E-3f, y1 = 4.1665795894E-2f * r + 1.6666665459E-1f;
  const Pack8 y2 = r + 1.f;
  y = y * r + 8.3334519073E-3f;
  y1 = y1 * r + 5.0000001201E-1f;
  y = y * r3 + y1;
  y = y * r2 + y2;
  // pldexp_generic(y, m): 2^m in four factors
  const Pack8 e0 = -278.f > m ? Pack8{} - 278.f : m, ef = 278.f < e0 ? Pack8{} + 278.f : e0;
  const Mask8 e = __builtin_convertvector(ef, Mask8), b = e >> 2;
  Pack8 c = Pack8((b + 127) << 23), out = ((y * c) * c) * c;
  c = Pack8((((e - b) - b) - b + 127) << 23);
  out = out * c;
  return in > out ? in : out;
}

/// Eigen's 4-lane cos (Array4f::cos()) of 8 floats, two lanes of 4 at a time (cos8's path for huge inputs).
[[gnu::noinline]] inline void cosTwoByFour(const float* in, float* out) {
  lanes(out) = lanes(in).cos();
  lanes(out + 4) = lanes(in + 4).cos();
}
/// cos in 8 lanes, bit for bit Eigen 3.4's 4-lane Array4f::cos() in an SSE build (psincos_float<false>
/// without FMA: the four-step reduction by pi/2, both polynomials, the select and the sign); 8 inputs with
/// any |x| >= 18838 (Eigen's threshold for its slow reduction) go through Eigen's 4-lane cos itself.
ALIASLAB_AVX2 Pack8 cos8(const Pack8& in) {
  using U8 = unsigned __attribute__((vector_size(32)));
  const Pack8 ax = abs8(in);
  if (_mm256_movemask_ps(Pack8(ax >= 18838.f))) {
    float a[8], b[8];
    store8(a, in);
    cosTwoByFour(a, b);
    return load8(b);
  }
  Pack8 y = ax * 0.636619746685028076171875f;  // 2 / pi
  const Pack8 rounded = y + 12582912.f;        // 1.5 * 2^23: the nearest integer in the low bits
  const U8 n = U8(rounded);
  y = rounded - 12582912.f;
  Pack8 x = y * -1.5703125f + ax;
  x = y * -0.000483989715576171875f + x;
  x = y * 1.62865035235881805419921875e-07f + x;
  x = y * 5.5644315544167710640977020375430583953857421875e-11f + x;
  const U8 sign = ((n + 1u) << 30) & 0x80000000u;
  const Pack8 x2 = x * x;
  Pack8 c = 2.4372266125283204019069671630859375e-05f * x2 + -0.00138865201734006404876708984375f;
  c = c * x2 + 0.041666619479656219482421875f;
  c = c * x2 + -0.5f;
  c = c * x2 + 1.f;
  Pack8 sn = -0.0001959234114083702898469196984621021329076029360294342041015625f * x2 +
             0.0083326873655616851693794799871284340042620897293090820312500000f;
  sn = sn * x2 + -0.1666666203982298255503735617821803316473960876464843750000000000f;
  sn = sn * x2;
  sn = sn * x + x;
  const Pack8 r = (n & 1u) == 0u ? c : sn;
  return Pack8(U8(r) ^ sign);
}

}  // namespace aliaslab::filterimpl
