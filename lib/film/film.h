// The film: samples in, pixels out.
//
// A SampleBuffer holds one traced sample set: for each pixel (i, j), spp
// samples stored contiguously at [(j * width + i) * spp, ... + spp), or, for
// adaptive sampling (render/adaptive/adaptive.h), count(i, j) samples per pixel
// stored pixel after pixel in the same order (every reconstruction except
// Supersample takes either kind). Each
// sample is a film position (continuous pixel coordinates, pixel (i, j)
// covers [i, i+1) x [j, j+1), y up), its radiance (linear, unclamped) and a
// weight (1, except for filter importance sampling, where it is
// sign(f) * integral |f|).
//
// Reconstruction turns a buffer into an Image and counts what went wrong
// (ReconStats). The modes are defined in docs/science.md ("Reconstruction").
// The weighted average's readable definition, sum f(x_k - p) L_k / sum f(x_k - p)
// over every sample in double (pbrt-v4's film.h and Nori's ImageBlock::put are
// the models), is reconstructDefinition (film/film_definition.h): the
// reference every fast path below (reconstruct's splat, the Accumulator) is
// tested against.
//
// Degenerate outcomes (every mode; no NaN ever reaches an Image):
// - a sample with a non-finite position or radiance is skipped and counted
//   in nonFiniteSamples;
// - a pixel whose |sum of weights| is below the tolerance is undefined: it
//   takes the plain mean of its own finite samples (0 if it has none) and is
//   counted in undefinedPixels. Tolerance: 1e-8 * |f(0, 0)| (the filter's
//   peak) for WeightedAverage and Accumulator, 1e-8 * |f(0, 0)| of the
//   course variant for Classic, 1e-8 * the integral of |f|
//   (FilterSampler::absIntegral) for ImportanceSampled. Supersample
//   has no weights: a pixel with no finite sample is undefined (value 0);
// - a result that is not finite in float (overflow, inf / inf) takes the same
//   fallback and is counted in nanPixels;
// - a pixel with a negative channel keeps it (it is what the filter made;
//   the 8-bit writer clamps) and is counted in negativePixels.
// FilmSample::weight is used by ImportanceSampled, and by WeightedAverage,
// Classic and the Accumulator when the buffer is areaWeighted(): adaptive
// sampling marks each sample with the area it stands for (its pixel's or
// sub-cell's area over the samples there), so a filter sums f w L / sum f w
// and dense regions do not count more than their area.
#pragma once
#include <cstddef>
#include <algorithm>
#include <string>
#include <type_traits>
#include <vector>

#include "core/image.h"
#include "core/huge_pages.h"
#include "filter/filter.h"

namespace aliaslab {

/// Storage of large per-pixel buffers: huge pages where offered (core/huge_pages.h).
template <class T>
using LargeVector = std::vector<T, HugePageAllocator<T>>;

struct FilmSample {
  float x = 0, y = 0;          ///< film position
  Color L = Color::Zero();     ///< radiance
  float weight = 1.f;          ///< importance weight (1 unless filter importance sampling)
};

class SampleBuffer {
 public:
  using Storage = std::vector<FilmSample, UninitializedAllocator<FilmSample>>;
  /// Marks a buffer whose every field of every sample the caller writes before reading (traceSamples does):
  /// nothing is initialised, so the first touch of its pages happens in the caller's parallel loop.
  struct Unwritten {};

  SampleBuffer() = default;
  /// Fixed count: spp samples in every pixel, each FilmSample{}.
  SampleBuffer(int width, int height, int spp) : SampleBuffer(width, height, spp, Unwritten{}) {
    std::fill(samples_.begin(), samples_.end(), FilmSample{});
  }
  SampleBuffer(int width, int height, int spp, Unwritten)
      : width_(width), height_(height), spp_(spp), samples_(static_cast<size_t>(width) * height * spp) {}
  /// Variable count (adaptive sampling): counts[j * width + i] samples in pixel (i, j), stored pixel after
  /// pixel in the same row-major order, so each row's samples are still contiguous; each FilmSample{}.
  /// Throws std::invalid_argument unless counts has width x height entries, none negative.
  SampleBuffer(int width, int height, const std::vector<int>& counts)
      : SampleBuffer(width, height, counts, Unwritten{}) {
    std::fill(samples_.begin(), samples_.end(), FilmSample{});
  }
  /// The same layout, nothing initialised (the caller writes every sample before reading: adaptive gather).
  SampleBuffer(int width, int height, const std::vector<int>& counts, Unwritten);
  int width() const { return width_; }
  int height() const { return height_; }
  /// The fixed count; 0 for a variable-count buffer (use count()).
  int spp() const { return spp_; }
  bool variable() const { return !offsets_.empty(); }
  /// Whether WeightedAverage and Classic multiply each sample by FilmSample::weight (see the top of the file).
  bool areaWeighted() const { return areaWeighted_; }
  void setAreaWeighted(bool on) { areaWeighted_ = on; }
  /// Samples in pixel (i, j).
  int count(int i, int j) const {
    const size_t p = static_cast<size_t>(j) * width_ + i;
    return variable() ? static_cast<int>(offsets_[p + 1] - offsets_[p]) : spp_;
  }
  /// Samples of row j (pixels (0, j) .. (width-1, j)), contiguous from pixel(0, j).
  size_t rowCount(int j) const {
    return variable() ? offsets_[static_cast<size_t>(j + 1) * width_] - offsets_[static_cast<size_t>(j) * width_]
                      : static_cast<size_t>(width_) * spp_;
  }
  FilmSample* pixel(int i, int j) { return samples_.data() + start(i, j); }
  const FilmSample* pixel(int i, int j) const { return samples_.data() + start(i, j); }
  Storage& samples() { return samples_; }
  const Storage& samples() const { return samples_; }

 private:
  size_t start(int i, int j) const {
    const size_t p = static_cast<size_t>(j) * width_ + i;
    return variable() ? offsets_[p] : p * spp_;
  }
  int width_ = 0, height_ = 0, spp_ = 0;
  Storage samples_;
  bool areaWeighted_ = false;
  std::vector<size_t> offsets_;  ///< variable count only: pixel p's samples at [offsets_[p], offsets_[p + 1])
};

/// What happened to the pixels of one reconstruction.
struct ReconStats {
  size_t undefinedPixels = 0;   ///< |sum of weights| below tolerance (documented fallback used)
  size_t negativePixels = 0;    ///< some channel < 0 (kept as computed; see reconstruct())
  size_t nanPixels = 0;         ///< a non-finite value was produced (documented fallback used)
  size_t nonFiniteSamples = 0;  ///< samples with NaN/inf radiance (skipped)
  ReconStats& operator+=(const ReconStats& o);
};

struct Reconstruction {
  Image image;
  ReconStats stats;
};

enum class ReconMode {
  WeightedAverage,     ///< sum f L / sum f over every sample within the radius, clipped by the film edge
  Classic,             ///< the course's gather: samples of pixels i-R..i+R with R = classicSupport(filter)
  ImportanceSampled,   ///< sum w L / sum w over the pixel's own samples (weights from FilterSampler::sample)
  Supersample,         ///< spp = k^2 sub-pixel centres, 3x3 binomial blur, k x k box average
};
std::string toString(ReconMode mode);
/// Parses "weighted", "classic", "importance", "supersample"; throws OptionError("reconstruction").
ReconMode parseReconMode(const std::string& name);

/// The classic integer support: ceil(r - 0.5) of the filter's course variant (makeCourseVariant: the Gaussian's
/// is course-gaussian, whose radius is ceil(2 sigma - 0.5) + 0.5), or of the filter itself.
int classicSupport(const Filter& filter);

/// Reconstructs with `mode`; `filter` is ignored by Supersample, which throws
/// OptionError("spp", ...) unless spp = k * k. Supersample puts each sample
/// in the sub-pixel cell of the k-times finer grid that contains its
/// position (a cell with several samples takes their mean, an empty cell
/// the mean of its pixel's finite samples), blurs with [1 2 1]/4 x [1 2 1]/4
/// (renormalised over the taps inside the image) and averages k x k blocks.
/// Classic uses the eval() of the filter's course variant (makeCourseVariant, else the filter itself) over the
/// samples of pixels i-R..i+R, j-R..j+R, R = classicSupport(filter). `threads`: 0 = all cores.
/// Deterministic for any thread count.
Reconstruction reconstruct(const SampleBuffer& samples, const Filter& filter, ReconMode mode, int threads = 0);

/// Streaming accumulation of the weighted average into several filters at
/// once, in double precision, without storing samples: memory is
/// width x height x filters x 4 doubles. add() may be called with any number
/// of batches (each a SampleBuffer of the full image); the result equals
/// reconstructing the union of all batches, and one add() then resolve(k)
/// equals reconstruct(batch, filter k, WeightedAverage) bit for bit. The
/// work that does not depend on the filter (finiteness, the fallback sums,
/// each sample's footprint for a radius) is done once per batch or radius,
/// so one more filter costs only its weights and accumulation. The sweep
/// reconstructs every weighted-average row of a sample set this way.
/// Deterministic for any thread count.
class Accumulator {
 public:
  Accumulator(int width, int height, std::vector<const Filter*> filters);
  void add(const SampleBuffer& batch, int threads = 0);
  /// From now on each add() also measures how its wall time divides among the filters (a little extra work per
  /// batch of samples, so off unless asked): filterSeconds()[k] = filter k's own weights and accumulation (CPU
  /// time over the threads used) plus an equal share of the rest; sharedSeconds() = that rest, the work no
  /// filter owns (finiteness, the fallback sums, each radius's footprints and band set-up, adding the bands
  /// into the sums). Both describe the last add(); empty and 0 until a measured add().
  void measureShares() { measureShares_ = true; }
  const std::vector<double>& filterSeconds() const { return filterSeconds_; }
  double sharedSeconds() const { return sharedSeconds_; }
  /// Resolves filter k's image (same outcomes and counts as reconstruct()).
  Reconstruction resolve(size_t k) const;
  size_t samplesAdded() const { return samplesAdded_; }
  size_t bytes() const;  ///< memory held by the accumulators

 private:
  int width_, height_;
  std::vector<const Filter*> filters_;
  /// per filter: r, g, b, weight per pixel; not initialised until the first add() sets them (overwrite)
  std::vector<std::vector<double, UninitializedAllocator<double>>> sums_;
  bool fresh_ = true;  ///< no add() yet: sums_ hold no values
  std::vector<double> plain_;              ///< r, g, b, count of each pixel's own finite samples (fallback)
  size_t samplesAdded_ = 0;
  size_t nonFinite_ = 0;
  bool measureShares_ = false;
  std::vector<double> filterSeconds_;  ///< the last measured add()'s shares (measureShares)
  double sharedSeconds_ = 0;
};

}  // namespace aliaslab
