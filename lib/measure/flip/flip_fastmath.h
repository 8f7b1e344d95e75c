// Cube root, base-2 logarithm and power of 2 for the fast FLIP stages (flip_planes.h), on GCC vectors of 1, 2
// or 4 doubles with only IEEE-exact operations (add, multiply, divide, square root, conversions, bit
// operations, selections), so each lane gives the same bits whatever the vector width. Accuracy (relative, on
// the ranges FLIP uses; checked against libm in tests/unit/measure/flip/flip_test):
//   cbrtPositive(t), t > 0 normal: a guess from the float exponent divided by 3 (a few per cent), then three
//     Halley steps (cubic convergence: 1e-4, 1e-12, rounding): within a few ulp.
//   log2Positive(x), x > 0 normal: x = m 2^e with m in [sqrt(1/2), sqrt 2), ln m = 2 atanh(s), s = (m-1)/(m+1),
//     |s| <= 0.172, series to s^15 (next term < 3e-14): within 1e-13 absolute.
//   exp2Of(z), z <= 1000: 2^round(z) from the exponent bits, 2^f for |f| <= 1/2 by Taylor to degree 12 (next
//     term < 4e-16); z < -1022 gives 2^-1022 (not 0): within 1e-14 relative, 1e-307 absolute.
// And in single precision, on GCC vectors of 1, 4 or 8 floats, for stage 3 (flip_fast_kernels.h):
//   log2PositiveF(x), x > 0 normal: the same atanh series to s^9 (next term < 7e-9): within 2e-7 absolute
//     plus 2 ulp of the result.
//   exp2OfF(z), z <= 127: Taylor to degree 7 (next term < 5e-9); z < -126 gives 2^-126: within 3e-7 relative.
#pragma once
#include <cstdint>
#include <cstring>

// The vectors may be wider than the translation unit's registers (8 doubles where AVX2 is on, 4 or 8 floats
// where it is not); they pass only between always-inlined functions of an unnamed namespace, so no call takes
// them across the ABI that GCC's -Wpsabi note is about.
#pragma GCC diagnostic ignored "-Wpsabi"

// (An unnamed namespace: each translation unit has its own copy, so the one built for AVX2 never lends its
// code to the others.)
namespace aliaslab::flipmath {
namespace {

// (GCC ignores vector_size on an alias template whose size depends on its parameter: one struct per width.)
template <int L> struct Lanes;
#define ALIASLAB_FLIP_LANES(L)                                    \
  template <> struct Lanes<L> {                                   \
    using D = double __attribute__((vector_size(8 * L)));         \
    using U = uint64_t __attribute__((vector_size(8 * L)));       \
    using F = float __attribute__((vector_size(4 * L)));          \
    using I = int32_t __attribute__((vector_size(4 * L)));        \
    using UF = uint32_t __attribute__((vector_size(4 * L)));      \
  };
ALIASLAB_FLIP_LANES(1)
ALIASLAB_FLIP_LANES(2)
ALIASLAB_FLIP_LANES(4)
ALIASLAB_FLIP_LANES(8)
#undef ALIASLAB_FLIP_LANES
template <int L> using Dv = typename Lanes<L>::D;
template <int L> using Uv = typename Lanes<L>::U;
template <int L> using Fv = typename Lanes<L>::F;
template <int L> using Iv = typename Lanes<L>::I;

template <class To, class From>
[[gnu::always_inline]] inline To bits(const From& f) {
  static_assert(sizeof(To) == sizeof(From));
  To t;
  std::memcpy(&t, &f, sizeof t);
  return t;
}
template <int L>
[[gnu::always_inline]] inline Dv<L> splat(double v) {
  return Dv<L>{} + v;
}

template <int L>
[[gnu::always_inline]] inline Dv<L> cbrtPositive(Dv<L> t) {
  // Kahan's guess: the float's bits divided by 3 plus a bias that re-centres the exponent (integer arithmetic
  // done in float, exact enough for a guess)
  const Fv<L> f = __builtin_convertvector(t, Fv<L>);
  const Fv<L> i = __builtin_convertvector(bits<Iv<L>>(f), Fv<L>) * (1.0f / 3.0f) + 709921077.0f;
  Dv<L> y = __builtin_convertvector(bits<Fv<L>>(__builtin_convertvector(i, Iv<L>)), Dv<L>);
  for (int k = 0; k < 3; ++k) {
    const Dv<L> y3 = y * y * y;
    y = y * (y3 + 2 * t) / (2 * y3 + t);
  }
  return y;
}

template <int L>
[[gnu::always_inline]] inline Dv<L> log2Positive(Dv<L> x) {
  const Uv<L> u = bits<Uv<L>>(x);
  // the biased exponent as a double: its 11 bits placed in the mantissa of 2^52
  Dv<L> e = bits<Dv<L>>(((u >> 52) & 0x7ff) | 0x4330000000000000ull) - (4503599627370496.0 + 1023.0);
  Dv<L> m = bits<Dv<L>>((u & 0x000fffffffffffffull) | 0x3ff0000000000000ull);  // in [1, 2)
  const auto big = m > 1.4142135623730951;
  m = big ? m * 0.5 : m;
  e = big ? e + 1.0 : e;
  const Dv<L> s = (m - 1.0) / (m + 1.0), s2 = s * s;
  const Dv<L> series =
      1.0 + s2 * (1.0 / 3 + s2 * (1.0 / 5 + s2 * (1.0 / 7 + s2 * (1.0 / 9 + s2 * (1.0 / 11 + s2 * (1.0 / 13 + s2 / 15))))));
  return e + (2.0 * 1.4426950408889634) * s * series;  // 2 s series = ln m; / ln 2
}

template <int L>
[[gnu::always_inline]] inline Dv<L> exp2Of(Dv<L> z) {
  z = z < -1022.0 ? splat<L>(-1022.0) : z;
  constexpr double kRound = 6755399441055744.0;  // 1.5 * 2^52: adding it rounds to an integer in the low bits
  const Dv<L> t = z + kRound, n = t - kRound, w = (z - n) * 0.6931471805599453;
  const Dv<L> scale = bits<Dv<L>>((bits<Uv<L>>(t) + 1023) << 52);  // 2^n, n in [-1022, 1000]
  Dv<L> p = splat<L>(1.0 / 479001600);  // 1/12!
  constexpr double kInvFact[12] = {1.0 / 39916800, 1.0 / 3628800, 1.0 / 362880, 1.0 / 40320, 1.0 / 5040, 1.0 / 720,
                                   1.0 / 120,      1.0 / 24,      1.0 / 6,      1.0 / 2,     1.0,          1.0};
  for (double c : kInvFact) p = p * w + c;
  return p * scale;
}

template <int L> using Uf = typename Lanes<L>::UF;

template <int L>
[[gnu::always_inline]] inline Fv<L> splatF(float v) {
  return Fv<L>{} + v;
}

template <int L>
[[gnu::always_inline]] inline Fv<L> log2PositiveF(Fv<L> x) {
  const Iv<L> u = bits<Iv<L>>(x);
  Fv<L> e = __builtin_convertvector(((u >> 23) & 0xff) - 127, Fv<L>);
  Fv<L> m = bits<Fv<L>>((u & 0x007fffff) | 0x3f800000);  // in [1, 2)
  const auto big = m > 1.41421356f;
  m = big ? m * 0.5f : m;
  e = big ? e + 1.0f : e;
  const Fv<L> s = (m - 1.0f) / (m + 1.0f), s2 = s * s;
  const Fv<L> series = 1.0f + s2 * (1.0f / 3 + s2 * (1.0f / 5 + s2 * (1.0f / 7 + s2 * (1.0f / 9))));
  return e + (2.0f * 1.44269504f) * s * series;
}

template <int L>
[[gnu::always_inline]] inline Fv<L> exp2OfF(Fv<L> z) {
  z = z < -126.0f ? splatF<L>(-126.0f) : z;
  constexpr float kRound = 12582912.0f;  // 1.5 * 2^23
  const Fv<L> t = z + kRound, n = t - kRound, w = (z - n) * 0.693147181f;
  const Fv<L> scale = bits<Fv<L>>((bits<Uf<L>>(t) + 127u) << 23);  // 2^n, n in [-126, 127]
  Fv<L> p = splatF<L>(1.0f / 5040);  // 1/7!
  constexpr float kInvFact[7] = {1.0f / 720, 1.0f / 120, 1.0f / 24, 1.0f / 6, 1.0f / 2, 1.0f, 1.0f};
  for (float c : kInvFact) p = p * w + c;
  return p * scale;
}

}  // namespace
}  // namespace aliaslab::flipmath
