// The half-plane spectra (measure/spectrum.h SpectrumAccumulator, a shared SpectrumReference) against the
// full-plane definition (measure/spectrum_definition.h) within the tolerance docs/spectrum.md states: every
// measure and every radial energy within 1e-9, relative to the error's mean square for energies and absolute for
// the shares and ratios; radial counts equal. On even, odd, non-square and one-pixel-wide images, with halves
// and without, and with one SpectrumReference shared by two accumulators.
#include <gtest/gtest.h>

#include <cmath>
#include <memory>

#include "core/hash.h"
#include "measure/spectrum.h"
#include "measure/spectrum_definition.h"

using namespace aliaslab;

namespace {

/// A smooth pattern plus white noise of amplitude `noise`, different per seed.
Image pattern(int w, int h, uint64_t seed, double noise) {
  Image im(w, h);
  HashRng rng(seed);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      const double s = 0.5 + 0.3 * std::sin(0.37 * x + 0.11 * y * y / (h + 1.0));
      auto v = [&](double k) { return static_cast<float>(k * s + noise * (rng.nextDouble() - 0.5)); };
      im.set(x, y, Color(v(1.0), v(0.8), v(0.6)));
    }
  return im;
}

void expectClose(const RadialSpectrum& a, const RadialSpectrum& b, double scale, const char* what) {
  for (int i = 0; i < kSpectrumBins; ++i) {
    EXPECT_NEAR(a.energy[i], b.energy[i], 1e-9 * scale) << what << " bin " << i;
    EXPECT_EQ(a.count[i], b.count[i]) << what << " bin " << i;
  }
}

void expectClose(const SpectrumMetrics& fast, const SpectrumMetrics& def, double scale) {
  EXPECT_NEAR(fast.lowfreqError, def.lowfreqError, 1e-9);
  EXPECT_NEAR(fast.lowfreqErrorSe, def.lowfreqErrorSe, 1e-9);
  EXPECT_NEAR(fast.blurredMse, def.blurredMse, 1e-9 * scale);
  ASSERT_EQ(fast.targets.size(), def.targets.size());
  for (size_t j = 0; j < def.targets.size(); ++j) {
    EXPECT_NEAR(fast.targets[j].lowfreqError, def.targets[j].lowfreqError, 1e-9) << j;
    EXPECT_NEAR(fast.targets[j].lowfreqErrorSe, def.targets[j].lowfreqErrorSe, 1e-9) << j;
    EXPECT_NEAR(fast.targets[j].blurredMse, def.targets[j].blurredMse, 1e-9 * scale) << j;
    for (size_t s = 0; s < kBlurCurve.size(); ++s) {
      EXPECT_NEAR(fast.targets[j].blurRatio[s], def.targets[j].blurRatio[s], 1e-9) << j << " " << s;
      EXPECT_NEAR(fast.targets[j].blurRatioSe[s], def.targets[j].blurRatioSe[s], 1e-9) << j << " " << s;
    }
  }
  expectClose(fast.error, def.error, scale, "error");
  expectClose(fast.noise, def.noise, scale, "noise");
  expectClose(fast.reference, def.reference, scale, "reference");
  EXPECT_EQ(fast.images, def.images);
}

}  // namespace

TEST(SpectrumHalfPlane, EqualsTheFullPlaneDefinitionWithinTolerance) {
  for (const auto& [w, h] : std::vector<std::pair<int, int>>{{64, 64}, {45, 37}, {96, 41}, {1, 17}, {17, 1}, {2, 2}}) {
    const Image g = pattern(w, h, 1, 0.01), gHalf = pattern(w, h, 2, 0.004);
    const Image t = pattern(w, h, 3, 0.05), tHalf = pattern(w, h, 4, 0.004);
    for (bool halves : {true, false}) {
      const RefEstimate own{&g, halves ? &gHalf : nullptr};
      const std::vector<RefEstimate> targets{{&t, halves ? &tHalf : nullptr}, {&g, nullptr}};
      SpectrumDefinition def(own, targets);
      const auto shared = std::make_shared<const SpectrumReference>(own, targets);
      SpectrumAccumulator fast(shared), second(shared);
      for (uint64_t k = 0; k < 5; ++k) {
        const Image image = pattern(w, h, 10 + k, 0.2);
        def.add(image), fast.add(image), second.add(image);
      }
      const SpectrumMetrics d = def.result();
      SCOPED_TRACE(std::to_string(w) + "x" + std::to_string(h) + (halves ? " halves" : " exact"));
      const double scale = d.error.total();
      ASSERT_GT(scale, 0);
      expectClose(fast.result(), d, scale);
      expectClose(second.result(), d, scale);  // the shared side is not changed by an accumulator
    }
  }
}

TEST(SpectrumHalfPlane, OwnReferenceAndSharedReferenceGiveTheSameBits) {
  const Image g = pattern(40, 30, 1, 0.01), gHalf = pattern(40, 30, 2, 0.004), t = pattern(40, 30, 3, 0.05);
  SpectrumAccumulator own({&g, &gHalf}, {{&t, nullptr}});
  SpectrumAccumulator shared(std::make_shared<const SpectrumReference>(RefEstimate{&g, &gHalf},
                                                                       std::vector<RefEstimate>{{&t, nullptr}}));
  for (uint64_t k = 0; k < 3; ++k) {
    const Image image = pattern(40, 30, 20 + k, 0.2);
    own.add(image), shared.add(image);
  }
  const SpectrumMetrics a = own.result(), b = shared.result();
  EXPECT_EQ(a.lowfreqError, b.lowfreqError);
  EXPECT_EQ(a.blurredMse, b.blurredMse);
  EXPECT_EQ(a.targets[0].blurRatio, b.targets[0].blurRatio);
  EXPECT_EQ(a.noise.energy, b.noise.energy);
}
