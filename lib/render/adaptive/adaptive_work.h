// Private to render/ (adaptive_trace.cpp, adaptive_work.cpp): the state the adaptive methods share, every
// pixel's samples so far and the budget, and the rounds that trace more of them (Work::trace). The methods
// read the samples through the inline accessors; each round is one call. Storage: each round's samples go
// into one flat buffer laid out pixel after pixel by that round's counts (prefix sums, known before the round
// is traced), so no per-pixel heap blocks. The method's last round is traced straight into the final
// SampleBuffer, each pixel's earlier rounds copied in ahead of it (round order, the order the methods add them
// in); gather() hands that buffer over.
#pragma once
#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <map>
#include <utility>
#include <vector>

#include "render/adaptive/adaptive.h"

namespace aliaslab::adaptiveimpl {

/// n points for one cell: the square [cx, cx+1) x [cy, cy+1) / 2^level of its pixel, each carrying `weight`
/// (FilmSample::weight: its share of the pixel's estimate, fixed before any of them is traced).
/// With first >= 0 (level 0 only): the points first .. first + n - 1 of the pixel's progressive sequence
/// (AdaptiveSampler::progressiveSampler), instead of a fresh draw of the base at n points.
struct Request {
  int level = 0, cx = 0, cy = 0, n = 0;
  float weight = 1.f;
  int first = -1;
};

/// 2^-level (level 0 .. 1022), exactly, without a division or a libm call.
inline double cellSide(int level) { return std::bit_cast<double>(static_cast<uint64_t>(1023 - level) << 52); }

/// The state shared by the methods: every pixel's samples so far and the budget.
class Work {
 public:
  Work(const Tracer& tracer, const AdaptiveSampler& a, int width, int height, int threads, const Progress& progress);

  long long pixels() const { return N_; }
  long long left() const { return B_ - spent_; }
  int count(long long p) const { return count_[p]; }
  /// Calls f(const FilmSample&) on every sample of pixel p so far, in the order traced.
  template <class F>
  void forSamples(long long p, F&& f) const {
    for (const Round& r : rounds_)
      for (size_t k = r.start[p]; k < r.start[p + 1]; ++k) f(r.samples[k]);
  }
  int width() const { return W_; }
  uint64_t hash(long long p) const { return hash_[p]; }

  /// Traces one round: the cells to sample as (pixel, cell) pairs; each pixel's cells in the order listed.
  /// `last`: the method's final round, traced straight into the final buffer after each pixel's earlier
  /// samples (the gather fused with the round: its samples are written once, not stored and then copied).
  void trace(const std::vector<std::pair<long long, Request>>& requests, bool last = false);

  /// One round giving add[p] samples to pixel p, drawn over the whole pixel, each of weight share[p] / add[p];
  /// with `first`, the points first[p] .. first[p] + add[p] - 1 of pixel p's progressive sequence.
  void tracePixels(const std::vector<int>& add, const std::vector<double>& share, bool last = false,
                   const std::vector<int>* first = nullptr);

  /// The weight every earlier sample of pixel p takes when the last round copies it into the final buffer
  /// (weights[p]); without it they keep the weight they were traced with.
  void setEarlierWeights(std::vector<float> weights) { earlierWeight_ = std::move(weights); }

  /// The first `first` pixels (all by default) by priority descending, then count ascending, then a hash of
  /// (seed, pixel): a strict order.
  std::vector<long long> rank(const std::vector<double>& priority, long long first = 1LL << 62) const;

  /// `amount` samples spread evenly: floor(amount/N) everywhere, one more in the first amount mod N pixels of
  /// rank(priority).
  std::vector<int> evenly(long long amount, const std::vector<double>& priority) const;

  /// How n points of one cell are drawn: as parts of counts at which the base sampler has its full quality
  /// (no warning(): jittered at squares, zsobol at powers of two), largest first (jittered, 47: 36 + 9 + 1 + 1),
  /// each from its own base sampler. A stratified base at another count degrades (jittered at 47: 1 x 47
  /// strips), while a union of independent full-quality sets keeps most of the stratification; every point
  /// keeps the same weight, so the union is unbiased like each part.
  std::vector<int> parts(int n) const;

  /// Per pixel, per channel, the least and greatest radiance of its samples.
  void pixelRanges(std::vector<Color>& lo, std::vector<Color>& hi) const;

  /// Every pixel's samples, in round order, as one variable-count buffer (area-weighted): the buffer the
  /// `last` round wrote (every method ends with one), moved out, so call once.
  SampleBuffer gather();

 private:
  /// v as a float inside [i, top] with top = the float below i + 1 (rounding of i + u could give i + 1).
  static float inside(double v, int i, float top) { return std::clamp(static_cast<float>(v), static_cast<float>(i), top); }

  const Tracer& tracer_;
  const AdaptiveSampler& a_;
  int W_, H_, threads_;
  Progress progress_;
  long long N_, B_, spent_ = 0;
  uint64_t round_ = 0;
  struct Round {
    std::vector<size_t> start;     ///< N + 1 prefix sums: pixel p's samples are [start[p], start[p + 1])
    SampleBuffer::Storage samples;  ///< written in the round's parallel loop before any read
  };
  std::vector<Round> rounds_;
  SampleBuffer final_;  ///< written by the `last` round; empty before
  bool finished_ = false;
  std::vector<int> count_;  ///< samples per pixel over all rounds
  std::vector<float> earlierWeight_;  ///< per pixel, set by setEarlierWeights (empty: weights kept)
  std::vector<uint64_t> hash_;
  mutable std::map<int, bool> quality_;  ///< count -> the base sampler has no warning() at it

  bool fullQuality(int n) const;
};

/// The largest value over each pixel's 3 x 3 neighbourhood (and 0) of a W x H image of values >= 0: a row pass
/// then a column pass (max is exact and its order free, so the same values as the 9-neighbour loop).
std::vector<double> dilate(const std::vector<double>& v, int W, int H);

/// The largest value over each pixel's 8 neighbours (and 0), the pixel itself left out.
std::vector<double> neighbourMax(const std::vector<double>& v, int W, int H);

/// Whitted's subdivision with fresh leaf samples (adaptive_subdiv.cpp); traces the whole budget.
void runSubdivision(Work& w, const AdaptiveSampler& a);

}  // namespace aliaslab::adaptiveimpl
