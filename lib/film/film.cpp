// reconstruct(): mode dispatch, the classic gather, filter importance
// sampling, and the shared resolution of weighted sums.
#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "core/error.h"
#include "core/parallel.h"
#include "film/film_impl.h"
#include "filter/filter_sampler.h"

namespace aliaslab {

ReconStats& ReconStats::operator+=(const ReconStats& o) {
  undefinedPixels += o.undefinedPixels;
  negativePixels += o.negativePixels;
  nanPixels += o.nanPixels;
  nonFiniteSamples += o.nonFiniteSamples;
  return *this;
}

std::string toString(ReconMode mode) {
  switch (mode) {
    case ReconMode::WeightedAverage: return "weighted";
    case ReconMode::Classic: return "classic";
    case ReconMode::ImportanceSampled: return "importance";
    case ReconMode::Supersample: return "supersample";
  }
  return "?";
}

ReconMode parseReconMode(const std::string& name) {
  for (ReconMode m : {ReconMode::WeightedAverage, ReconMode::Classic, ReconMode::ImportanceSampled,
                      ReconMode::Supersample})
    if (toString(m) == name) return m;
  throw OptionError("reconstruction",
                    "unknown mode '" + name + "' (valid: weighted, classic, importance, supersample)");
}

int classicSupport(const Filter& filter) {
  const std::unique_ptr<Filter> course = makeCourseVariant(filter);
  return std::max(0, static_cast<int>(std::ceil(double((course ? *course : filter).radius()) - 0.5)));
}

SampleBuffer::SampleBuffer(int width, int height, const std::vector<int>& counts, Unwritten)
    : width_(width), height_(height), offsets_(static_cast<size_t>(width) * height + 1, 0) {
  if (counts.size() != static_cast<size_t>(width) * height)
    throw std::invalid_argument("SampleBuffer: " + std::to_string(counts.size()) + " counts for " +
                                std::to_string(width) + "x" + std::to_string(height) + " pixels");
  for (size_t p = 0; p < counts.size(); ++p) {
    if (counts[p] < 0) throw std::invalid_argument("SampleBuffer: negative sample count");
    offsets_[p + 1] = offsets_[p] + static_cast<size_t>(counts[p]);
  }
  samples_.resize(offsets_.back());
}

namespace filmimpl {

double weightTolerance(const Filter& filter) { return std::max(1e-8 * std::abs(filter.eval(0, 0)), 1e-30); }

Reconstruction resolveSums(int width, int height, const double* sums, const double* plain, double tolerance,
                           size_t nonFiniteSamples) {
  Reconstruction out{Image(width, height), {}};
  out.stats.nonFiniteSamples = nonFiniteSamples;
  for (int j = 0; j < height; ++j)
    for (int i = 0; i < width; ++i) {
      const size_t p = 4 * (static_cast<size_t>(j) * width + i);
      const double* s = sums + p;
      Color c;
      bool fallback = false;
      if (std::abs(s[3]) < tolerance) {
        ++out.stats.undefinedPixels, fallback = true;
      } else {
        c = Color(float(s[0] / s[3]), float(s[1] / s[3]), float(s[2] / s[3]));
        if (!c.allFinite()) ++out.stats.nanPixels, fallback = true;
      }
      if (fallback) {
        const double* q = plain + p;
        c = q[3] > 0 ? Color(float(q[0] / q[3]), float(q[1] / q[3]), float(q[2] / q[3])) : Color::Zero();
        if (!c.allFinite()) c = Color::Zero();  // the mean itself overflowed float
      }
      if ((c < 0).any()) ++out.stats.negativePixels;
      out.image.set(i, j, c);
    }
  return out;
}

}  // namespace filmimpl

namespace {

using namespace filmimpl;

/// Classic gather (the course variant's eval over pixels i-R..i+R) or ImportanceSampled (own samples,
/// FilmSample::weight).
Reconstruction gather(const SampleBuffer& samples, const Filter& given, bool classic, int threads) {
  const std::unique_ptr<Filter> course = classic ? makeCourseVariant(given) : nullptr;
  const Filter& filter = course ? *course : given;
  const int W = samples.width(), H = samples.height();
  const int R = classic ? classicSupport(filter) : 0;
  std::vector<double> sums(4 * size_t(W) * H, 0.0), plain(4 * size_t(W) * H, 0.0);
  const size_t nonFinite = addPlainSums(samples, plain.data());
  parallelFor(H, threads, [&](int j) {
    for (int i = 0; i < W; ++i) {
      double* out = &sums[4 * (size_t(j) * W + i)];
      const float cx = i + 0.5f, cy = j + 0.5f;
      for (int sj = std::max(0, j - R); sj <= std::min(H - 1, j + R); ++sj)
        for (int si = std::max(0, i - R); si <= std::min(W - 1, i + R); ++si) {
          const FilmSample* s = samples.pixel(si, sj);
          for (int k = 0, n = samples.count(si, sj); k < n; ++k) {
            if (!finiteSample(s[k])) continue;
            const double w = classic ? filter.eval(s[k].x - cx, s[k].y - cy) *
                                           (samples.areaWeighted() ? double(s[k].weight) : 1.0)
                                     : s[k].weight;
            out[0] += w * s[k].L[0], out[1] += w * s[k].L[1], out[2] += w * s[k].L[2], out[3] += w;
          }
        }
    }
  });
  const double tol = classic ? weightTolerance(filter) : std::max(1e-8 * FilterSampler(filter).absIntegral(), 1e-30);
  return resolveSums(W, H, sums.data(), plain.data(), tol, nonFinite);
}

}  // namespace

Reconstruction reconstruct(const SampleBuffer& samples, const Filter& filter, ReconMode mode, int threads) {
  switch (mode) {
    case ReconMode::WeightedAverage: {
      const size_t n = 4 * size_t(samples.width()) * samples.height();
      std::vector<double> sums(n, 0.0), plain(n, 0.0);
      const size_t nonFinite = addPlainSums(samples, plain.data());
      splatWeighted(samples, filter, sums.data(), threads);
      return resolveSums(samples.width(), samples.height(), sums.data(), plain.data(), weightTolerance(filter),
                         nonFinite);
    }
    case ReconMode::Classic: return gather(samples, filter, true, threads);
    case ReconMode::ImportanceSampled: return gather(samples, filter, false, threads);
    case ReconMode::Supersample: return reconstructSupersample(samples, threads);
  }
  return {};
}

}  // namespace aliaslab
