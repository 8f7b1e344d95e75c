// Shimmer and flicker of K seeds x F frames (measure/motion.h). Every sum in double precision.
#include "measure/motion.h"

#include <cmath>
#include <stdexcept>

#include "measure/standard_errors.h"

namespace aliaslab {
namespace {

void checkInput(const std::vector<std::vector<Image>>& images, const std::vector<RefEstimate>& targets) {
  const size_t K = images.size(), F = targets.size();
  if (K < 2) throw std::invalid_argument("motion metrics: need at least 2 seeds");
  if (F < 2) throw std::invalid_argument("motion metrics: need at least 2 frames");
  const Image& first = *targets[0].mean;
  for (const RefEstimate& t : targets) {
    if (!t.mean || t.mean->width() != first.width() || t.mean->height() != first.height())
      throw std::invalid_argument("motion metrics: every target must be given and of the same size");
    if (t.halfDiff && (t.halfDiff->width() != first.width() || t.halfDiff->height() != first.height()))
      throw std::invalid_argument("motion metrics: a target's half-difference differs in size");
  }
  for (const auto& seq : images) {
    if (seq.size() != F) throw std::invalid_argument("motion metrics: every seed needs one image per frame");
    for (const Image& i : seq)
      if (i.width() != first.width() || i.height() != first.height())
        throw std::invalid_argument("motion metrics: an image differs in size from the targets");
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

MotionMetrics computeMotionMetrics(const std::vector<std::vector<Image>>& images,
                                   const std::vector<RefEstimate>& targets) {
  checkInput(images, targets);
  const int K = static_cast<int>(images.size()), F = static_cast<int>(targets.size());
  const size_t n = size_t(targets[0].mean->width()) * targets[0].mean->height() * 3;
  const double values = double(n) * (F - 1);

  std::vector<std::vector<double>> gram(K);  // gram[k][l], l <= k: sum over pairs and values of a_k a_l
  for (int k = 0; k < K; ++k) gram[k].assign(k + 1, 0.0);
  std::vector<double> newSeed(K, 0.0), a(K);
  double targetVar = 0;
  for (int t = 0; t + 1 < F; ++t) {
    const float* T0 = targets[t].mean->data();
    const float* T1 = targets[t + 1].mean->data();
    const float* D0 = targets[t].halfDiff ? targets[t].halfDiff->data() : nullptr;
    const float* D1 = targets[t + 1].halfDiff ? targets[t + 1].halfDiff->data() : nullptr;
    for (size_t i = 0; i < n; ++i) {
      const double dT = double(T1[i]) - T0[i];
      const double dD = (D1 ? double(D1[i]) : 0.0) - (D0 ? double(D0[i]) : 0.0);
      targetVar += dD * dD;
      for (int k = 0; k < K; ++k) a[k] = double(images[k][t + 1].data()[i]) - images[k][t].data()[i] - dT;
      for (int k = 0; k < K; ++k)
        for (int l = 0; l <= k; ++l) gram[k][l] += a[k] * a[l];
      // sequence j: seed (j + t) mod K in frame t, (j + t + 1) mod K in frame t + 1
      for (int j = 0; j < K; ++j) {
        const int k0 = (j + t) % K, k1 = (j + t + 1) % K;
        const double c = double(images[k1][t + 1].data()[i]) - images[k0][t].data()[i] - dT;
        newSeed[j] += c * c;
      }
    }
  }
  MotionMetrics m;
  m.frames = F, m.seeds = K;
  m.targetChangeVar = targetVar / values;
  // shimmer: the mean over seed pairs of the cross products (the U-statistic form of mean^2 - s^2 / K)
  std::vector<std::vector<double>> h(K);
  double cross = 0;
  for (int k = 0; k < K; ++k) {
    h[k].resize(k);
    for (int l = 0; l < k; ++l) h[k][l] = gram[k][l] / values, cross += h[k][l];
  }
  m.shimmer = cross / (0.5 * K * (K - 1)) - m.targetChangeVar;
  m.shimmerSe = pairStatisticSe(h);
  std::vector<double> same(K);
  for (int k = 0; k < K; ++k) same[k] = gram[k][k] / values - m.targetChangeVar;
  for (double& v : newSeed) v = v / values - m.targetChangeVar;
  meanAndSe(same, m.flickerSameSeed, m.flickerSameSeedSe);
  meanAndSe(newSeed, m.flickerNewSeed, m.flickerNewSeedSe);
  return m;
}

}  // namespace aliaslab
