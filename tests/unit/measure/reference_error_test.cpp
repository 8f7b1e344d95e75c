// The references' own error (docs/science.md, "The references' own error"): constructed references with a
// known variance, made of two independent halves Ga = truth + eps_a, Gb = truth + eps_b, the noise eps
// spatially correlated (a 3 x 3 box average of independent values: neighbours within 2 px share it, as pixels
// within a filter's footprints share samples; the filter radius 1.5 says so), so Var G = Var(eps) / 2 is
// known. Images I_k = truth + bias + independent noise. Over many repetitions the corrected estimators must be
// unbiased, the uncorrected ones off by Var G, and (estimate - expectation) / se must behave like a z-score
// (mean 0, sd 1): a standard error without the reference part, or one that drops the neighbours' covariance
// (the window of measure/standard_errors.h too small for the filter's radius), fails this.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <vector>

#include "core/hash.h"
#include "measure/metrics.h"
#include "support/pixel_fields.h"

using namespace aliaslab;

namespace {
constexpr int W = 64, H = 64, K = 8, kReps = 300;
constexpr double kN = W * H * 3.0;
constexpr int kBox = 1;  // the reference noise is a (2 kBox + 1)^2 box average: correlated up to lag 2
constexpr double kRadius = 1.5;  // the filter radius whose footprints overlap up to lag ceil(2 r) - 1 = 2

double truth(int x, int y, int c) { return 0.5 + 0.2 * std::sin(0.3 * x + c) * std::cos(0.17 * y); }
double biasPattern(int x, int y, int c) { return 0.03 * std::cos(0.45 * x - 0.8 * c) * std::sin(0.21 * y + 1); }
double blurPattern(int x, int y, int c) { return 0.05 * std::sin(0.13 * x + 0.4 * c + 0.5) * std::cos(0.29 * y); }

double gaussian(HashRng& rng) {
  const double u1 = 1.0 - rng.nextDouble(), u2 = rng.nextDouble();
  return std::sqrt(-2.0 * std::log(u1)) * std::cos(2.0 * M_PI * u2);
}

// Independent unit Gaussians per value, averaged over a (2 kBox + 1)^2 box (wrapping), scaled to sd `sd`.
std::vector<double> correlatedNoise(uint64_t key, double sd) {
  HashRng rng(key);
  std::vector<double> white(static_cast<size_t>(kN)), out(static_cast<size_t>(kN), 0.0);
  for (double& v : white) v = gaussian(rng);
  const double norm = sd / (2 * kBox + 1);  // the sum of (2 kBox + 1)^2 unit values has sd 2 kBox + 1
  for (int y = 0; y < H; ++y)
    for (int x = 0; x < W; ++x)
      for (int c = 0; c < 3; ++c) {
        double s = 0;
        for (int dy = -kBox; dy <= kBox; ++dy)
          for (int dx = -kBox; dx <= kBox; ++dx) s += white[3 * (((y + dy + H) % H) * W + (x + dx + W) % W) + c];
        out[3 * (y * W + x) + c] = norm * s;
      }
  return out;
}

template <class F>
Image imageOf(F f) {
  Image im(W, H);
  for (int y = 0; y < H; ++y)
    for (int x = 0; x < W; ++x) im.set(x, y, Color(float(f(x, y, 0)), float(f(x, y, 1)), float(f(x, y, 2))));
  return im;
}

template <class F>
double meanOver(F f) {
  return aliaslab::testing::meanOverPixels(W, H, f);
}

/// A reference from two halves: exact + eps_a and exact + eps_b.
struct Halves {
  Image mean, half;
};
Halves halves(const std::vector<double>& exact, const std::vector<double>& a, const std::vector<double>& b) {
  Image ga(W, H), gb(W, H);
  for (size_t i = 0; i < exact.size(); ++i)
    ga.data()[i] = float(exact[i] + a[i]), gb.data()[i] = float(exact[i] + b[i]);
  return {averageImages(ga, gb), halfDifference(ga, gb)};
}

std::vector<double> values(double (*f)(int, int, int), double (*g)(int, int, int) = nullptr) {
  std::vector<double> v(static_cast<size_t>(kN));
  for (int y = 0; y < H; ++y)
    for (int x = 0; x < W; ++x)
      for (int c = 0; c < 3; ++c) v[3 * (y * W + x) + c] = f(x, y, c) + (g ? g(x, y, c) : 0.0);
  return v;
}

/// One repetition: G around the truth with halves (sd of eps: refSd), a target T = truth + blur whose halves
/// share part of G's noise (same samples), K images truth + biasScale * bias + noise (sd sigma).
struct Repetition {
  Halves g, t;
  std::vector<Image> images;
};
Repetition repetition(int r, double biasScale, double refSd, double sigma) {
  const uint64_t key = hashWords(0x5EF, r);
  const auto ea = correlatedNoise(hashWords(key, 1), refSd), eb = correlatedNoise(hashWords(key, 2), refSd);
  const auto fa = correlatedNoise(hashWords(key, 3), refSd), fb = correlatedNoise(hashWords(key, 4), refSd);
  std::vector<double> ta(ea.size()), tb(eb.size());
  for (size_t i = 0; i < ea.size(); ++i) ta[i] = 0.8 * ea[i] + 0.6 * fa[i], tb[i] = 0.8 * eb[i] + 0.6 * fb[i];
  Repetition rep{halves(values(truth), ea, eb), halves(values(truth, blurPattern), ta, tb), {}};
  for (int k = 0; k < K; ++k) {
    HashRng rng(hashWords(key, 100 + k));
    rep.images.push_back(imageOf([&](int x, int y, int c) {
      return truth(x, y, c) + biasScale * biasPattern(x, y, c) + sigma * gaussian(rng);
    }));
  }
  return rep;
}

struct Moments {
  double mean = 0, sd = 0;
};
Moments moments(const std::vector<double>& v) {
  Moments m;
  for (double x : v) m.mean += x / v.size();
  for (double x : v) m.sd += (x - m.mean) * (x - m.mean) / (v.size() - 1);
  m.sd = std::sqrt(m.sd);
  return m;
}

/// z-scores of aliasing, mse_target and blur against their expectations, and the raw (uncorrected) aliasing.
struct Study {
  std::vector<double> zAliasing, zTarget, zBlur, rawAliasing, aliasing;
  double varG = 0;
};
Study study(double biasScale, double refSd, double sigma, double radius = kRadius) {
  Study s;
  const double b2 =
      biasScale * biasScale * meanOver([](int x, int y, int c) { return biasPattern(x, y, c) * biasPattern(x, y, c); });
  const double target = meanOver([&](int x, int y, int c) {
    const double e = biasScale * biasPattern(x, y, c) - blurPattern(x, y, c);
    return e * e;
  }) + sigma * sigma;
  const double blur = meanOver([](int x, int y, int c) { return blurPattern(x, y, c) * blurPattern(x, y, c); });
  s.varG = refSd * refSd / 2;
  for (int r = 0; r < kReps; ++r) {
    const Repetition rep = repetition(r, biasScale, refSd, sigma);
    const Metrics m =
        computeMetrics(rep.images, {&rep.g.mean, &rep.g.half, radius}, {{&rep.t.mean, &rep.t.half, radius}});
    const TargetMetrics& t = m.targets[0];
    s.zAliasing.push_back((m.aliasing - b2) / m.aliasingSe);
    s.zTarget.push_back((t.mseTarget - target) / t.mseTargetSe);
    s.zBlur.push_back((t.blur - blur) / t.blurSe);
    s.rawAliasing.push_back(m.aliasing + m.refVar);
    s.aliasing.push_back(m.aliasing);
  }
  return s;
}

// z-scores: mean within 4 / sqrt(R) of 0 (0.23), sd in [0.85, 1.2] (its own sd is about 0.04; the pair
// statistics' floor may overstate the seed part a little).
void expectZ(const std::vector<double>& z, const char* what) {
  SCOPED_TRACE(what);
  const Moments m = moments(z);
  EXPECT_NEAR(m.mean, 0.0, 4.0 / std::sqrt(double(kReps))) << "sd " << m.sd;
  EXPECT_GT(m.sd, 0.85) << "mean " << m.mean;
  EXPECT_LT(m.sd, 1.2) << "mean " << m.mean;
}
}  // namespace

TEST(ReferenceError, UnbiasedEstimatorHasZeroAliasingWithinItsError) {
  // The reference's variance (8e-4) is larger than the images' noise / K (5e-5): uncorrected, it is aliasing.
  const Study s = study(0.0, 0.04, 0.02);
  expectZ(s.zAliasing, "aliasing");
  expectZ(s.zTarget, "mse_target");
  expectZ(s.zBlur, "blur");
  const Moments raw = moments(s.rawAliasing), corrected = moments(s.aliasing);
  EXPECT_NEAR(raw.mean / s.varG, 1.0, 0.1);  // the uncorrected value is biased by Var G
  EXPECT_NEAR(corrected.mean / s.varG, 0.0, 0.05);
}

TEST(ReferenceError, KnownBiasIsRecoveredWithinItsError) {
  // A structured error of mean square 2.2e-4 beside a reference variance of 3.2e-4: the linear term
  // -2 mean (m - G) delta dominates the reference part.
  const Study s = study(1.0, 0.025, 0.02);
  expectZ(s.zAliasing, "aliasing");
  expectZ(s.zTarget, "mse_target");
  expectZ(s.zBlur, "blur");
  const double b2 = meanOver([](int x, int y, int c) { return biasPattern(x, y, c) * biasPattern(x, y, c); });
  EXPECT_NEAR(moments(s.rawAliasing).mean - b2, s.varG, 0.1 * s.varG);
}

TEST(ReferenceError, WithoutTheReferencePartTheErrorsAreTooSmall) {
  // The same repetitions, se from the seeds alone (exact references claimed): z spreads far beyond 1.
  std::vector<double> z;
  const double b2 = meanOver([](int x, int y, int c) { return biasPattern(x, y, c) * biasPattern(x, y, c); });
  for (int r = 0; r < 100; ++r) {
    const Repetition rep = repetition(r, 1.0, 0.025, 0.02);
    const Metrics exact = computeMetrics(rep.images, {&rep.g.mean}, {});
    const Metrics m = computeMetrics(rep.images, {&rep.g.mean, &rep.g.half, kRadius}, {});
    z.push_back((m.aliasing - b2) / exact.aliasingSe);
  }
  EXPECT_GT(moments(z).sd, 2.0);
}

TEST(ReferenceError, ErrorsThatIgnoreTheNeighboursCovarianceAreTooSmall) {
  // The same construction read as if the references' filter had radius 0.5 (no pixel shares a sample): the
  // reference part keeps only each pixel's own variance and misses the 3 x 3 covariance.
  const Study s = study(1.0, 0.025, 0.02, 0.5);
  EXPECT_GT(moments(s.zAliasing).sd, 1.5);
}

TEST(ReferenceError, CorrectedTermsAddUpAndPerSeedValuesAverageToMseTarget) {
  const Repetition rep = repetition(7, 1.0, 0.03, 0.02);
  const RefEstimate gEst{&rep.g.mean, &rep.g.half, kRadius}, tEst{&rep.t.mean, &rep.t.half, kRadius};
  const Metrics m = computeMetrics(rep.images, gEst, {tEst});
  const TargetMetrics& t = m.targets[0];
  EXPECT_NEAR(m.noise + m.aliasing + t.blur + t.cross, t.mseTarget, 1e-12 * t.mseTarget);
  EXPECT_NEAR(m.aliasing + m.noise, m.mse, 1e-12 * m.mse);
  // the subtracted variances: mean D^2 = mean (Ga - Gb)^2 / 4
  double varG = 0, varT = 0;
  for (size_t i = 0; i < size_t(kN); ++i)
    varG += double(rep.g.half.data()[i]) * rep.g.half.data()[i] / kN,
        varT += double(rep.t.half.data()[i]) * rep.t.half.data()[i] / kN;
  EXPECT_NEAR(m.refVar, varG, 1e-12 * varG);
  EXPECT_NEAR(t.refVar, varT, 1e-12 * varT);
  // per seed: mean (I_k - T)^2 - mean Var T, averaging to mse_target
  ASSERT_EQ(t.perSeed.size(), size_t(K));
  double mean = 0;
  for (int k = 0; k < K; ++k) {
    EXPECT_NEAR(t.perSeed[k], meanSquaredDifference(rep.images[k], rep.t.mean) - varT, 1e-12);
    mean += t.perSeed[k] / K;
  }
  EXPECT_NEAR(mean, t.mseTarget, 1e-12 * t.mseTarget);
  // the corrections relative to the exact-reference values
  const Metrics raw = computeMetrics(rep.images, {&rep.g.mean}, {{&rep.t.mean}});
  EXPECT_NEAR(raw.aliasing - m.aliasing, varG, 1e-12);
  EXPECT_NEAR(raw.mse - m.mse, varG, 1e-12);
  EXPECT_NEAR(raw.targets[0].mseTarget - t.mseTarget, varT, 1e-12);
  double cov = 0, varDelta = 0;
  for (size_t i = 0; i < size_t(kN); ++i) {
    const double a = rep.g.half.data()[i], b = rep.t.half.data()[i];
    cov += a * (a - b) / kN, varDelta += (a - b) * (a - b) / kN;
  }
  EXPECT_NEAR(raw.targets[0].blur - t.blur, varDelta, 1e-12);
  EXPECT_NEAR(t.cross - raw.targets[0].cross, 2 * cov, 1e-12);
  EXPECT_GT(m.mseSe, raw.mseSe);  // the reference part adds to the seeds'
  EXPECT_GT(t.mseTargetSe, raw.targets[0].mseTargetSe);
  EXPECT_EQ(raw.targets[0].blurSe, 0.0);  // exact references: blur has no error
  EXPECT_GT(t.blurSe, 0.0);
}

TEST(ReferenceError, DeterministicWhenAllImagesAreIdentical) {
  const Repetition rep = repetition(3, 1.0, 0.02, 0.02);
  std::vector<Image> same(5, rep.images[0]);
  const Metrics m = computeMetrics(same, {&rep.g.mean, &rep.g.half, kRadius}, {{&rep.t.mean, &rep.t.half, kRadius}});
  EXPECT_TRUE(m.deterministic);
  EXPECT_EQ(m.noise, 0.0);
  EXPECT_GT(m.mseSe, 0.0);  // no seed part, but the references still err
  same[3].data()[17] = std::nextafter(same[3].data()[17], 2.0f);  // one bit
  EXPECT_FALSE(computeMetrics(same, {&rep.g.mean}, {}).deterministic);
  EXPECT_FALSE(computeMetrics(rep.images, {&rep.g.mean}, {}).deterministic);
}

TEST(ReferenceError, PsnrIsInfiniteWhenTheCorrectedMseIsNotPositive) {
  // Images equal to G's mean: the raw mse is 0, the corrected one -Var G.
  const Repetition rep = repetition(5, 0.0, 0.02, 0.0);
  const std::vector<Image> images(4, rep.g.mean);
  const Metrics m = computeMetrics(images, {&rep.g.mean, &rep.g.half, kRadius}, {});
  EXPECT_LT(m.mse, 0.0);
  EXPECT_TRUE(std::isinf(m.psnr) && m.psnr > 0);
}

TEST(ReferenceError, PairStatisticErrorsNeedFourSeeds) {
  const Repetition rep = repetition(9, 1.0, 0.02, 0.02);
  const std::vector<Image> three(rep.images.begin(), rep.images.begin() + 3);
  const Metrics m = computeMetrics(three, {&rep.g.mean, &rep.g.half, kRadius}, {{&rep.t.mean, &rep.t.half, kRadius}});
  EXPECT_TRUE(std::isnan(m.aliasingSe));
  EXPECT_TRUE(std::isnan(m.noiseSe));
  EXPECT_GT(m.mseSe, 0.0);
  EXPECT_GT(m.targets[0].mseTargetSe, 0.0);
}
