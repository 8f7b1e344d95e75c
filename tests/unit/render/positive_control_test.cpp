// The positive controls for correlated samplers (scenes/controls/same_pixel.txt, diagonal stripes, and
// same_pixel_x.txt, vertical ones): every pixel integrates the same square wave and its true value is 0.5
// exactly, so a sampler whose neighbouring pixels' errors are negatively correlated must show it there. At the
// full sample count, zsobol (diagonal) and bluenoise-dither:sobol (vertical: its two per-coordinate masks make
// its error blue only for an integrand of one coordinate, results/positive_control.md) put less of their error
// below a quarter of Nyquist (lowfreq_error, measure/spectrum.h) than white noise (random) on the same scene,
// by more than three standard errors of the difference; random itself sits at the white share, pi / 64.
#include <gtest/gtest.h>

#include <cmath>

#include "accel/aggregate.h"
#include "aliaslab_paths.h"
#include "measure/spectrum.h"
#include "render/render.h"
#include "scene/scene.h"

namespace aliaslab {
namespace {

struct Control {
  explicit Control(const std::string& file = "same_pixel.txt")
      : scene(parseScene(std::string(ALIASLAB_SOURCE_DIR) + "/scenes/controls/" + file)) {}
  Scene scene;
  std::unique_ptr<Aggregate> aggregate = makeBruteForce(*scene.root);
  Tracer tracer{scene, *aggregate, TraceOptions{}};
};

/// lowfreq_error and its standard error of `sampler` at spp over `seeds` seeds, against the exact 0.5, from each
/// pixel's first `prefix` samples (all by default): the plain mean of those.
SpectrumTargetMetrics lowfreq(const Tracer& t, const std::string& sampler, int size, int spp, int seeds,
                              int prefix = 0) {
  const Image exact(size, size, Color::Constant(0.5f));
  SpectrumAccumulator acc({&exact, nullptr}, {{&exact, nullptr}});
  const int n = prefix > 0 ? prefix : spp;
  for (int k = 0; k < seeds; ++k) {
    const SampleBuffer b = traceSamples(t, *makeSampler(sampler, spp, 7 + k), size, size, 2);
    Image img(size, size);
    for (int j = 0; j < size; ++j)
      for (int i = 0; i < size; ++i) {
        Color sum = Color::Zero();
        for (int q = 0; q < n; ++q) sum += b.pixel(i, j)[q].L;
        img.set(i, j, sum / static_cast<float>(n));
      }
    acc.add(img);
  }
  return acc.result().targets[0];
}

TEST(PositiveControl, PixelsAreIdenticalAndWorthOneHalf) {
  Control c;
  // the same point in every pixel gives the same value (32 x 32 and 64 x 64), and a fine grid gives 0.5
  for (int size : {32, 64})
    for (int q = 0; q < 50; ++q) {
      const float x = (q % 7 + 0.31f) / 7.f, y = (q / 7 + 0.77f) / 8.f;
      const Color first = c.tracer.radianceAt(x, y, size, size);
      for (int p : {1, 5, 17, size - 1})
        ASSERT_EQ(c.tracer.radianceAt(p + x, (p * 3) % size + y, size, size)[0], first[0]) << size << " " << q;
    }
  // (a grid offset by irrational fractions: a midpoint grid would sit on the stripes' boundaries)
  double sum = 0;
  for (int b = 0; b < 128; ++b)
    for (int a = 0; a < 128; ++a)
      sum += c.tracer.radianceAt(9 + (a + 0.4142f) / 128, 4 + (b + 0.7320f) / 128, 64, 64)[0];
  EXPECT_NEAR(sum / (128 * 128), 0.5, 1.5 / 128);
}

TEST(PositiveControl, CorrelatedSamplersPutLessErrorAtLowFrequencies) {
  const int size = 32, spp = 16, seeds = 12;
  for (const auto& [file, name] : {std::pair{"same_pixel.txt", "zsobol"}, {"same_pixel_x.txt", "bluenoise-dither:sobol"}}) {
    Control c(file);
    const SpectrumTargetMetrics white = lowfreq(c.tracer, "random", size, spp, seeds);
    const SpectrumTargetMetrics m = lowfreq(c.tracer, name, size, spp, seeds);
    std::printf("%s: random lowfreq_error %.4f +- %.4f, %s %.4f +- %.4f\n", file, white.lowfreqError,
                white.lowfreqErrorSe, name, m.lowfreqError, m.lowfreqErrorSe);
    EXPECT_NEAR(white.lowfreqError, std::acos(-1.0) / 64, 3 * white.lowfreqErrorSe + 0.002) << file;
    EXPECT_LT(m.lowfreqError + 3 * std::hypot(m.lowfreqErrorSe, white.lowfreqErrorSe), white.lowfreqError) << name;
  }
}

// A prefix of zsobol's points (the first 4 of each pixel's 16) is not an aligned block of the image's sequence,
// so the pixels' errors no longer complement each other: the share below a quarter of Nyquist returns to about
// white, clearly above the full set's.
TEST(PositiveControl, ZsobolPrefixReturnsToWhite) {
  Control c;
  const int size = 32, spp = 16, seeds = 12;
  const SpectrumTargetMetrics full = lowfreq(c.tracer, "zsobol", size, spp, seeds);
  const SpectrumTargetMetrics prefix = lowfreq(c.tracer, "zsobol", size, spp, seeds, 4);
  std::printf("zsobol 16: lowfreq_error %.4f +- %.4f; its first 4: %.4f +- %.4f\n", full.lowfreqError,
              full.lowfreqErrorSe, prefix.lowfreqError, prefix.lowfreqErrorSe);
  EXPECT_GT(prefix.lowfreqError - 3 * std::hypot(full.lowfreqErrorSe, prefix.lowfreqErrorSe), full.lowfreqError);
}

}  // namespace
}  // namespace aliaslab
