// The batch kernels behind FilterBatch (internal to lib/filter): the loops
// over a batch of samples for the two kinds of filter, built from the
// concrete filter class so its profile in lanes (g4, g8) is inlined. A filter
// file hands FilterBatch its kernel through the registry's batch function
// (filter_impl.h), usually batchFor<TheFilter>; a filter without one gets
// FilterBatch's loop over eval().
#pragma once
#include <cstddef>
#include <memory>
#include <type_traits>
#include <vector>

#include "filter/filter_impl.h"

namespace aliaslab::filterimpl {

/// One filter's batch evaluation (FilterBatch::eval's contract).
class BatchKernel {
 public:
  explicit BatchKernel(bool unitWeights = false) : unit_(unitWeights) {}
  virtual ~BatchKernel() = default;
  virtual void eval(int count, const float* x, const float* y, const float* cx, const float* cy, int n,
                    float* out) const = 0;
  bool unitWeights() const { return unit_; }

 private:
  bool unit_;
};

/// Entries per weight of a batch: count rounded up to a multiple of 4.
inline size_t batchStride(int count) { return static_cast<size_t>((count + 3) & ~3); }

/// Scratch floats for one batch, on the stack unless large.
class Scratch {
 public:
  explicit Scratch(size_t n) {
    if (n > kSmall) big_.resize(n);
  }
  float* data() { return big_.empty() ? small_ : big_.data(); }

 private:
  static constexpr size_t kSmall = 8192;
  alignas(16) float small_[kSmall];
  std::vector<float> big_;
};

/// out[a * stride + s] = (p[s] - (c[s] + a))^2 for a < n, from sample `from` on.
inline void squaredOffsets(const float* p, const float* c, int n, size_t stride, float* out, size_t from = 0) {
  for (int a = 0; a < n; ++a)
    for (size_t s = from; s < stride; s += 4)
      lanes(out + a * stride + s) = (lanes(p + s) - (lanes(c + s) + float(a))).square();
}
/// The same in 8 lanes for the first stride rounded down to 8 samples (returned).
[[gnu::target("avx2")]] inline size_t squaredOffsets8(const float* p, const float* c, int n, size_t stride,
                                                      float* out) {
  const size_t end = stride & ~size_t(7);
  for (int a = 0; a < n; ++a)
    for (size_t s = 0; s < end; s += 8) {
      const Pack8 d = load8(p + s) - (load8(c + s) + static_cast<float>(a));
      store8(out + a * stride + s, d * d);
    }
  return end;
}
/// The largest dx^2 + dy^2 with sqrt(dx^2 + dy^2) <= r in float (the disc test without the sqrt).
inline float discBound(float r) {
  float s = r * r;
  while (s > 0 && !(std::sqrt(s) <= r)) s = std::nextafter(s, 0.f);
  while (std::sqrt(std::nextafter(s, kInf)) <= r) s = std::nextafter(s, kInf);
  return s;
}

/// A SeparableFilter's batch: n profile values per axis and sample, then the n x n products. F may define g4
/// (g in 4 lanes, bit for bit g; also called beyond r and on padding) and g8 (the same in 8 lanes,
/// ALIASLAB_AVX2) to use AVX2 where the CPU has it.
template <class F>
class SeparableBatch final : public BatchKernel {
 public:
  SeparableBatch(const F& f, bool unit) : BatchKernel(unit), f_(f) {}
  void eval(int count, const float* x, const float* y, const float* cx, const float* cy, int n,
            float* out) const override {
    const size_t stride = batchStride(count);
    Scratch scratch(2 * n * stride);
    float *gx = scratch.data(), *gy = gx + n * stride;
    size_t done = 0;  // samples done in 8 lanes
    if constexpr (requires(const F& f, const Pack8& v) { f.g8(v); })
      if (eightLanes()) done = eval8(x, y, cx, cy, n, stride, gx, gy, out);
    profiles(x, cx, n, stride, done, gx), profiles(y, cy, n, stride, done, gy);
    for (int b = 0; b < n; ++b)
      for (int a = 0; a < n; ++a)
        for (size_t s = done; s < stride; s += 4)
          lanes(out + (b * n + a) * stride + s) = lanes(gx + a * stride + s) * lanes(gy + b * stride + s);
  }

 private:
  /// eval in 8 lanes for the first stride rounded down to 8 samples (returned), the same operations.
  [[gnu::target("avx2")]] size_t eval8(const float* x, const float* y, const float* cx, const float* cy, int n,
                                       size_t stride, float* gx, float* gy, float* out) const {
    const size_t end = stride & ~size_t(7);
    const float r = f_.radius();
    for (size_t s = 0; s < end; s += 8)
      for (int a = 0; a < n; ++a) {
        const Pack8 dx = load8(x + s) - (load8(cx + s) + static_cast<float>(a));
        const Pack8 dy = load8(y + s) - (load8(cy + s) + static_cast<float>(a));
        store8(gx + a * stride + s, keepLe8(abs8(dx), r, f_.g8(dx)));
        store8(gy + a * stride + s, keepLe8(abs8(dy), r, f_.g8(dy)));
      }
    for (int b = 0; b < n; ++b)
      for (int a = 0; a < n; ++a)
        for (size_t s = 0; s < end; s += 8)
          store8(out + (b * n + a) * stride + s, load8(gx + a * stride + s) * load8(gy + b * stride + s));
    return end;
  }
  /// out[a * stride + s] = profile(p[s] - (c[s] + a)) for a < n, from sample `from` on.
  void profiles(const float* p, const float* c, int n, size_t stride, size_t from, float* out) const {
    const float r = f_.radius();
    for (size_t s = from; s < stride; s += 4)
      for (int a = 0; a < n; ++a) {
        const Lanes d = lanes(p + s) - (lanes(c + s) + static_cast<float>(a));
        Lanes g;
        if constexpr (requires(const F& f, const Lanes& l) { f.g4(l); }) g = f_.g4(d);
        else
          for (int l = 0; l < 4; ++l) g[l] = f_.g(d[l]);
        lanes(out + a * stride + s) = keepLe(d.abs(), r, g);
      }
  }
  const F& f_;
};

/// A RadialFilter's batch: squared offsets per axis, then d and g(d) per pixel, cut to the disc as eval()
/// rounds it. F may define g4 and g8 as above (g4 defaults to g lane by lane).
template <class F>
class RadialBatch final : public BatchKernel {
 public:
  explicit RadialBatch(const F& f, bool unit) : BatchKernel(unit), f_(f), disc_(discBound(f.radius())) {}
  void eval(int count, const float* x, const float* y, const float* cx, const float* cy, int n,
            float* out) const override {
    const size_t stride = batchStride(count);
    Scratch scratch(2 * n * stride);
    float *dx2 = scratch.data(), *dy2 = dx2 + n * stride;
    size_t done = 0;  // samples done in 8 lanes
    if constexpr (requires(const F& f, const Pack8& v) { f.g8(v); })
      if (eightLanes()) {
        done = squaredOffsets8(x, cx, n, stride, dx2), squaredOffsets8(y, cy, n, stride, dy2);
        weights8(dx2, dy2, n, stride, out);
      }
    squaredOffsets(x, cx, n, stride, dx2, done), squaredOffsets(y, cy, n, stride, dy2, done);
    for (int b = 0; b < n; ++b)
      for (int a = 0; a < n; ++a)
        for (size_t s = done; s < stride; s += 4) {
          const Lanes d2 = lanes(dx2 + a * stride + s) + lanes(dy2 + b * stride + s);
          lanes(out + (b * n + a) * stride + s) = keepLe(d2, disc_, g4(sqrt4(d2)));
        }
  }

 private:
  /// The weights loop in 8 lanes (F::g8) for the first stride rounded down to 8 samples, the same operations.
  [[gnu::target("avx2")]] void weights8(const float* dx2, const float* dy2, int n, size_t stride, float* out) const {
    const size_t end = stride & ~size_t(7);
    for (int b = 0; b < n; ++b)
      for (int a = 0; a < n; ++a)
        for (size_t s = 0; s < end; s += 8) {
          const Pack8 d2 = load8(dx2 + a * stride + s) + load8(dy2 + b * stride + s);
          store8(out + (b * n + a) * stride + s, keepLe8(d2, disc_, f_.g8(sqrt8(d2))));
        }
  }
  /// g(d) in 4 lanes (F::g4, else lane by lane; also called beyond r).
  Lanes g4(const Lanes& d) const {
    if constexpr (requires(const F& f, const Lanes& l) { f.g4(l); }) return f_.g4(d);
    Lanes v;
    for (int l = 0; l < 4; ++l) v[l] = f_.g(d[l]);
    return v;
  }
  const F& f_;
  float disc_;  ///< discBound(radius())
};

/// The kernel of F (a SeparableFilter or RadialFilter) for `filter` when it is an F, else null.
template <class F>
std::shared_ptr<const BatchKernel> batchFor(const Filter& filter, bool unitWeights = false) {
  const F* f = dynamic_cast<const F*>(&filter);
  if (!f) return nullptr;
  if constexpr (std::is_base_of_v<SeparableFilter<F>, F>) return std::make_shared<SeparableBatch<F>>(*f, unitWeights);
  else return std::make_shared<RadialBatch<F>>(*f, unitWeights);
}

}  // namespace aliaslab::filterimpl
