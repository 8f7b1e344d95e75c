// The error spectrum measure (measure/spectrum.h) against mathematics: white
// noise is flat, a sinusoid puts its power at its frequency, Parseval, and
// the accumulator's totals equal the independently computed mse and noise.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "core/hash.h"
#include "measure/metrics.h"
#include "measure/spectrum.h"
#include "study/records/spectrum_files.h"

using namespace aliaslab;

namespace {

constexpr double kTau = 6.283185307179586;

Image whiteNoise(int w, int h, uint64_t seed, double amplitude = 1.0) {
  Image im(w, h);
  HashRng rng(seed);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x)
      im.set(x, y, Color(static_cast<float>(amplitude * (rng.nextDouble() - 0.5)),
                         static_cast<float>(amplitude * (rng.nextDouble() - 0.5)),
                         static_cast<float>(amplitude * (rng.nextDouble() - 0.5))));
  return im;
}

/// a cos(2 pi (fu x + fv y) + phase) in every channel, plus `offset`.
Image sinusoid(int w, int h, double fu, double fv, double a, double phase = 0, const Image* offset = nullptr) {
  Image im(w, h);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      const float v = static_cast<float>(a * std::cos(kTau * (fu * x + fv * y) + phase));
      im.set(x, y, (offset ? offset->get(x, y) : Color::Zero()) + Color(v, v, v));
    }
  return im;
}

double meanSquare(const Image& im) {
  double s = 0;
  const size_t n = 3 * static_cast<size_t>(im.width()) * im.height();
  for (size_t i = 0; i < n; ++i) s += static_cast<double>(im.data()[i]) * im.data()[i];
  return s / n;
}

TEST(Spectrum, ParsevalSumEqualsMeanSquare) {
  for (const auto& [w, h] : std::vector<std::pair<int, int>>{{45, 37}, {64, 64}, {96, 40}}) {
    const Image im = whiteNoise(w, h, 3, 2.0);
    const auto p = powerSpectrum(im);
    double sum = 0;
    for (double v : p) sum += v;
    EXPECT_NEAR(sum, meanSquare(im), 1e-12 * meanSquare(im)) << w << "x" << h;
    EXPECT_NEAR(radialSpectrum(im).total(), meanSquare(im), 1e-12 * meanSquare(im)) << w << "x" << h;
  }
}

TEST(Spectrum, WhiteNoiseIsFlat) {
  // Uniform noise of variance s^2 = 1/12 per channel: every non-DC frequency has expected power s^2 / N.
  // A bin's average over 3 * count exponential-like terms has relative sd 1/sqrt(3 count): allow 5 sd.
  const int w = 128, h = 128;
  const Image im = whiteNoise(w, h, 5);
  const RadialSpectrum r = radialSpectrum(im);
  const double expected = (1.0 / 12) / (w * h);
  for (int b = 1; b < 32; ++b) {  // bins fully inside the Nyquist disc
    ASSERT_GT(r.count[b], 0);
    const double tol = 5.0 / std::sqrt(3.0 * r.count[b]);
    EXPECT_NEAR(r.power(b) / expected, 1.0, tol) << "bin " << b;
  }
  // and the low-frequency share is the disc's share of the frequency square, pi / 64
  const Image zero(w, h);
  SpectrumAccumulator acc(RefEstimate{&zero}, {});
  acc.add(im);
  acc.add(whiteNoise(w, h, 6));
  EXPECT_NEAR(acc.result().lowfreqError, kTau / 2 * 0.125 * 0.125, 0.006);
}

TEST(Spectrum, SinusoidPeaksAtItsFrequency) {
  // cos at (12/96, 8/64) = (0.125, 0.125) cycles per pixel: radius 0.1768, bin 11; (10/128, 0): bin 5.
  struct Case { int w, h, a, b, bin; };
  for (const Case c : {Case{96, 64, 12, 8, 11}, Case{128, 32, 10, 0, 5}, Case{50, 50, 0, 20, 25}}) {
    const Image im = sinusoid(c.w, c.h, static_cast<double>(c.a) / c.w, static_cast<double>(c.b) / c.h, 0.3, 0.7);
    const RadialSpectrum r = radialSpectrum(im);
    int peak = 0;
    for (int b = 0; b < kSpectrumBins; ++b)
      if (r.energy[b] > r.energy[peak]) peak = b;
    EXPECT_EQ(peak, c.bin) << c.w << "x" << c.h;
    EXPECT_NEAR(r.energy[peak], 0.3 * 0.3 / 2, 1e-6);  // all of a cosine's mean square a^2 / 2
  }
}

TEST(Spectrum, AccumulatorTotalsAreMseAndNoise) {
  // Error = a fixed pattern plus per-seed noise: the error spectrum sums to mse, the noise spectrum to
  // the unbiased variance, both computed independently by MetricAccumulator.
  const int w = 40, h = 30, k = 5;
  const Image g = whiteNoise(w, h, 10, 0.5);
  const Image bias = sinusoid(w, h, 3.0 / w, 2.0 / h, 0.05);
  std::vector<Image> images;
  for (int i = 0; i < k; ++i) {
    Image im = whiteNoise(w, h, 100 + i, 0.2);
    for (int y = 0; y < h; ++y)
      for (int x = 0; x < w; ++x) im.set(x, y, im.get(x, y) + g.get(x, y) + bias.get(x, y));
    images.push_back(std::move(im));
  }
  SpectrumAccumulator acc(RefEstimate{&g}, {});
  for (const Image& im : images) acc.add(im);
  const SpectrumMetrics s = acc.result();
  const Metrics m = computeMetrics(images, RefEstimate{&g}, {});
  EXPECT_NEAR(s.error.total(), m.mse, 1e-9 * m.mse);
  EXPECT_NEAR(s.noise.total(), m.noise, 1e-9 * m.noise);
  EXPECT_EQ(s.images, k);
  EXPECT_LT(s.blurredMse, m.mse);
  EXPECT_GT(s.lowfreqError, 0.0);
  EXPECT_LT(s.lowfreqError, 1.0);
  EXPECT_GT(s.lowfreqErrorSe, 0.0);
}

TEST(Spectrum, LowFrequencyShareAndBlurOfSinusoids) {
  // A sinusoid error below the cutoff: lowfreq_error 1 (with zero spread over seeds); above it: 0.
  // Blurred mse of a cosine of frequency rho: mse * exp(-4 pi^2 sigma^2 rho^2); of a constant: mse.
  const int w = 64, h = 64;
  const Image g(w, h, Color(0.5f, 0.5f, 0.5f));
  for (const auto& [f, low] : std::vector<std::pair<double, double>>{{4.0 / 64, 1.0}, {20.0 / 64, 0.0}}) {
    SpectrumAccumulator acc(RefEstimate{&g}, {});
    for (int i = 0; i < 3; ++i) acc.add(sinusoid(w, h, f, 0, 0.1 * (i + 1), i, &g));
    const SpectrumMetrics s = acc.result();
    EXPECT_NEAR(s.lowfreqError, low, 1e-12);  // float images: leakage ~1e-14
    EXPECT_NEAR(s.lowfreqErrorSe, 0.0, 1e-12);
    const double mse = (0.01 + 0.04 + 0.09) / 3 / 2;
    EXPECT_NEAR(s.blurredMse, mse * std::exp(-2 * kTau * kTau / 2 * kBlurSigma * kBlurSigma * f * f), 1e-6 * mse);
  }
  SpectrumAccumulator dc(RefEstimate{&g}, {});
  dc.add(Image(w, h, Color(0.6f, 0.6f, 0.6f)));
  dc.add(Image(w, h, Color(0.3f, 0.3f, 0.3f)));
  const SpectrumMetrics s = dc.result();
  EXPECT_NEAR(s.blurredMse, (0.01 + 0.04) / 2, 1e-7);
  EXPECT_NEAR(s.lowfreqError, 1.0, 1e-12);
  // half the energy below the cutoff, half above: 0.5
  SpectrumAccumulator mix(RefEstimate{&g}, {});
  for (int i = 0; i < 2; ++i) {
    const Image lowPart = sinusoid(w, h, 0, 3.0 / 64, 0.1, i, &g);
    mix.add(sinusoid(w, h, 25.0 / 64, 0, 0.1, 0.3 * i, &lowPart));
  }
  EXPECT_NEAR(mix.result().lowfreqError, 0.5, 1e-9);
}

// The measures against a target T (by linearity, from the spectra of I_k - G) against a direct power spectrum of
// I_k - T here, with the target's half-difference D_T subtracted: blurred_mse = mean_k B[I_k - T] - B[D_T],
// lowfreq share f_k = (L[I_k - T] - L[D_T]) / (E[I_k - T] - E[D_T]) (L below the cutoff, E in total, B blurred).
struct Energy {
  double low = 0, total = 0, blurred = 0;
};
Energy directEnergy(const Image& im) {
  const auto p = powerSpectrum(im);
  Energy e;
  for (int v = 0; v < im.height(); ++v)
    for (int u = 0; u < im.width(); ++u) {
      const double rho = frequencyRadius(u, v, im.width(), im.height()), q = p[size_t(v) * im.width() + u];
      e.total += q, e.low += rho < kLowFrequencyCutoff ? q : 0.0;
      e.blurred += q * std::exp(-kTau * kTau * kBlurSigma * kBlurSigma * rho * rho);
    }
  return e;
}

Image difference(const Image& a, const Image& b) {
  Image d(a.width(), a.height());
  for (size_t i = 0; i < 3 * size_t(a.width()) * a.height(); ++i)
    d.data()[i] = static_cast<float>(double(a.data()[i]) - b.data()[i]);
  return d;
}

TEST(Spectrum, TargetMeasuresEqualADirectSpectrumOfTheErrorAgainstTheTarget) {
  const int w = 40, h = 36, k = 4;
  const Image g = whiteNoise(w, h, 20, 0.5);
  const Image t = sinusoid(w, h, 2.0 / w, 3.0 / h, 0.05, 0.2, &g);  // T = G + a low-frequency difference
  const Image gHalf = whiteNoise(w, h, 21, 0.03), tHalf = whiteNoise(w, h, 22, 0.03);
  std::vector<Image> images;
  for (int i = 0; i < k; ++i) {
    Image im = whiteNoise(w, h, 200 + i, 0.2);
    for (int y = 0; y < h; ++y)
      for (int x = 0; x < w; ++x) im.set(x, y, im.get(x, y) + g.get(x, y));
    images.push_back(std::move(im));
  }
  SpectrumAccumulator acc(RefEstimate{&g, &gHalf}, {RefEstimate{&t, &tHalf}, RefEstimate{&t}});
  for (const Image& im : images) acc.add(im);
  const SpectrumMetrics s = acc.result();
  ASSERT_EQ(s.targets.size(), 2u);
  const Energy dt = directEnergy(tHalf), dg = directEnergy(gHalf);
  auto check = [&](const SpectrumTargetMetrics& m, const Image& ref, const Energy& half, const char* what) {
    SCOPED_TRACE(what);
    std::vector<double> f;
    double blurred = 0, mean = 0, var = 0;
    for (const Image& im : images) {
      const Energy e = directEnergy(difference(im, ref));
      f.push_back(std::clamp((e.low - half.low) / (e.total - half.total), 0.0, 1.0));
      blurred += e.blurred / k;
    }
    for (double v : f) mean += v / k;
    for (double v : f) var += (v - mean) * (v - mean) / (k - 1);
    EXPECT_NEAR(m.blurredMse, blurred - half.blurred, 1e-6 * blurred);
    EXPECT_NEAR(m.lowfreqError, mean, 1e-6 * mean);
    EXPECT_NEAR(m.lowfreqErrorSe, std::sqrt(var / k), 1e-5 * std::sqrt(var / k));
  };
  check(s.targets[0], t, dt, "target with halves");
  check(s.targets[1], t, Energy{}, "exact target");
  check({s.lowfreqError, s.lowfreqErrorSe, s.blurredMse}, g, dg, "own reference with halves");
  EXPECT_GT(dt.blurred, 1e-3 * s.targets[0].blurredMse);  // the subtraction is not negligible here
  EXPECT_NEAR(s.reference.total(), dg.total, 1e-12 * dg.total);
}

// A spectrum CSV's data lines after canonicaliseSpectrumCsv, its header checked.
std::vector<std::string> canonicalLines(const std::string& path) {
  canonicaliseSpectrumCsv(path);
  std::ifstream in(path);
  std::string line;
  std::getline(in, line);
  EXPECT_EQ(line, spectrumCsvHeader());
  std::vector<std::string> lines;
  while (std::getline(in, line)) lines.push_back(line);
  return lines;
}

TEST(Spectrum, CsvAppendsAndCanonicalises) {
  const std::string path = (std::filesystem::temp_directory_path() / "aliaslab_spectrum_test.csv").string();
  std::filesystem::remove(path);
  const Image zero(16, 16);
  SpectrumAccumulator acc(RefEstimate{&zero}, {});
  acc.add(whiteNoise(16, 16, 1));
  acc.add(whiteNoise(16, 16, 2));
  const SpectrumMetrics m = acc.result();
  appendSpectrumCsv(path, "s,zsobol,16,box,0.5,weighted,none", m);
  appendSpectrumCsv(path, "s,random,4,box,0.5,weighted,none", m);
  { std::ofstream torn(path, std::ios::app); torn << "s,random,4,box,0.5,weighted,none,error,3,0.0"; }
  appendSpectrumCsv(path, "s,zsobol,16,box,0.5,weighted,none", m);  // re-measured after an interruption
  const std::vector<std::string> lines = canonicalLines(path);
  // bins with frequencies: 16x16 reaches rho = 0.707 -> bins 0 .. 45, all non-empty? count them
  int bins = 0;
  for (int b = 0; b < kSpectrumBins; ++b) bins += m.error.count[b] > 0;
  ASSERT_EQ(lines.size(), 2u * 2u * bins);  // two configurations, error and noise, no duplicates
  EXPECT_EQ(lines.front().rfind("s,random,4,box,0.5,weighted,none,error,", 0), 0u) << lines.front();
  EXPECT_EQ(lines.back().rfind("s,zsobol,16,box,0.5,weighted,none,noise,", 0), 0u) << lines.back();
  std::filesystem::remove(path);
}

// Canonical order by hand: numbers compare as numbers (spp 4 < 16, radius 1.5 < 10, bin 2 < 10, where text
// order says the opposite), text as text, and of a key written twice the last copy is kept.
TEST(Spectrum, CanonicalOrderIsNumericAndKeepsTheLastCopy) {
  const std::string path = (std::filesystem::temp_directory_path() / "aliaslab_spectrum_order_test.csv").string();
  {
    std::ofstream out(path);
    out << spectrumCsvHeader() << '\n'
        << "s,a,16,box,1.5,weighted,none,error,2,0.1,5,50\n"
        << "s,a,4,box,10,weighted,none,error,2,0.1,6,60\n"
        << "s,a,4,box,1.5,weighted,none,noise,10,0.5,1,10\n"
        << "s,a,4,box,1.5,weighted,none,error,10,0.5,7,70\n"
        << "s,a,4,box,1.5,weighted,none,error,2,0.1,8,80\n"
        << "r,b,64,tent,2,weighted,none,error,0,0,3,30\n"
        << "s,a,16,box,1.5,weighted,none,error,2,0.1,9,90\n";  // re-measured: replaces the first line
  }
  const std::vector<std::string> lines = canonicalLines(path);
  const std::vector<std::string> expected = {
      "r,b,64,tent,2,weighted,none,error,0,0,3,30",      "s,a,4,box,1.5,weighted,none,error,2,0.1,8,80",
      "s,a,4,box,1.5,weighted,none,error,10,0.5,7,70",   "s,a,4,box,1.5,weighted,none,noise,10,0.5,1,10",
      "s,a,4,box,10,weighted,none,error,2,0.1,6,60",     "s,a,16,box,1.5,weighted,none,error,2,0.1,9,90"};
  EXPECT_EQ(lines, expected);
  std::filesystem::remove(path);
}

}  // namespace
