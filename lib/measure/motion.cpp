// Shimmer and flicker of K seeds x F frames in the content's frame (measure/motion.h). Every sum in double.
#include "measure/motion.h"

#include <cmath>
#include <stdexcept>

#include "measure/registration.h"
#include "measure/standard_errors.h"

namespace aliaslab {
namespace {

// The interior pixels compared: [m, w - m) x [m, h - m); throws when it is empty.
struct Interior {
  int m, w, h;
  Interior(int width, int height, double dx, double dy) : m(registrationMargin(dx, dy)), w(width), h(height) {
    if (w <= 2 * m || h <= 2 * m)
      throw std::invalid_argument("motion metrics: a " + std::to_string(w) + " x " + std::to_string(h) +
                                  " image has no pixel " + std::to_string(m) +
                                  " pixels from its border (the motion plus the registration's margin)");
  }
  double values(int pairs) const { return double(w - 2 * m) * (h - 2 * m) * 3 * pairs; }
  template <class Fn>
  void each(Fn&& fn) const {
    for (int y = m; y < h - m; ++y)
      for (int x = m; x < w - m; ++x)
        for (int c = 0; c < 3; ++c) fn(3 * (size_t(y) * w + x) + c);
  }
};

void checkInput(const std::vector<std::vector<Image>>& images) {
  const size_t K = images.size();
  if (K < 2) throw std::invalid_argument("motion metrics: need at least 2 seeds");
  const size_t F = images[0].size();
  if (F < 2) throw std::invalid_argument("motion metrics: need at least 2 frames");
  const Image& first = images[0][0];
  for (const auto& seq : images) {
    if (seq.size() != F) throw std::invalid_argument("motion metrics: every seed needs one image per frame");
    for (const Image& i : seq)
      if (i.width() != first.width() || i.height() != first.height())
        throw std::invalid_argument("motion metrics: the images differ in size");
  }
}

// Mean and standard error of per-sequence values.
void meanAndSe(const std::vector<double>& v, double& mean, double& se) {
  double s = 0;
  for (double x : v) s += x;
  mean = s / v.size();
  double ss = 0;
  for (double x : v) ss += (x - mean) * (x - mean);
  se = std::sqrt(ss / (v.size() - 1) / v.size());
}

}  // namespace

MotionMetrics computeMotionMetrics(const std::vector<std::vector<Image>>& images, double dx, double dy) {
  checkInput(images);
  const int K = static_cast<int>(images.size()), F = static_cast<int>(images[0].size());
  const Interior in(images[0][0].width(), images[0][0].height(), dx, dy);
  const double values = in.values(F - 1);

  std::vector<std::vector<double>> gram(K);  // gram[k][l], l <= k: sum over pairs and values of a_k a_l
  for (int k = 0; k < K; ++k) gram[k].assign(k + 1, 0.0);
  std::vector<double> newSeed(K, 0.0), a(K);
  std::vector<std::vector<double>> moved(K);  // moved[k]: R I_{k,t+1} of the current pair
  for (int t = 0; t + 1 < F; ++t) {
    for (int k = 0; k < K; ++k) moved[k] = shiftImage(images[k][t + 1], dx, dy);
    in.each([&](size_t i) {
      for (int k = 0; k < K; ++k) a[k] = moved[k][i] - images[k][t].data()[i];
      for (int k = 0; k < K; ++k)
        for (int l = 0; l <= k; ++l) gram[k][l] += a[k] * a[l];
      // sequence j: seed (j + t) mod K in frame t, (j + t + 1) mod K in frame t + 1
      for (int j = 0; j < K; ++j) {
        const double c = moved[(j + t + 1) % K][i] - images[(j + t) % K][t].data()[i];
        newSeed[j] += c * c;
      }
    });
  }
  MotionMetrics m;
  m.frames = F, m.seeds = K;
  // shimmer: the mean over seed pairs of the cross products (the U-statistic form of mean^2 - s^2 / K)
  std::vector<std::vector<double>> h(K);
  double cross = 0;
  for (int k = 0; k < K; ++k) {
    h[k].resize(k);
    for (int l = 0; l < k; ++l) h[k][l] = gram[k][l] / values, cross += h[k][l];
  }
  m.shimmer = cross / (0.5 * K * (K - 1));
  m.shimmerSe = pairStatisticSe(h);
  std::vector<double> same(K);
  for (int k = 0; k < K; ++k) same[k] = gram[k][k] / values;
  for (double& v : newSeed) v /= values;
  meanAndSe(same, m.flickerSameSeed, m.flickerSameSeedSe);
  meanAndSe(newSeed, m.flickerNewSeed, m.flickerNewSeedSe);
  return m;
}

double targetShimmer(const std::vector<RefEstimate>& targets, double dx, double dy) {
  const int F = static_cast<int>(targets.size());
  if (F < 2) throw std::invalid_argument("motion metrics: need at least 2 frames");
  const Image& first = *targets[0].mean;
  for (const RefEstimate& t : targets)
    if (!t.mean || t.mean->width() != first.width() || t.mean->height() != first.height() ||
        (t.halfDiff && (t.halfDiff->width() != first.width() || t.halfDiff->height() != first.height())))
      throw std::invalid_argument("motion metrics: every target (and half-difference) must be of the same size");
  const Interior in(first.width(), first.height(), dx, dy);
  double sum = 0, noise = 0;
  for (int t = 0; t + 1 < F; ++t) {
    const std::vector<double> moved = shiftImage(*targets[t + 1].mean, dx, dy);
    const float* T0 = targets[t].mean->data();
    in.each([&](size_t i) { sum += (moved[i] - T0[i]) * (moved[i] - T0[i]); });
    if (targets[t].halfDiff && targets[t + 1].halfDiff) {
      const std::vector<double> d = shiftImage(*targets[t + 1].halfDiff, dx, dy);
      const float* D0 = targets[t].halfDiff->data();
      in.each([&](size_t i) { noise += (d[i] - D0[i]) * (d[i] - D0[i]); });
    }
  }
  return (sum - noise) / in.values(F - 1);
}

}  // namespace aliaslab
