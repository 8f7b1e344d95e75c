// The film's pictures (film/visualize.h): the filter plots and the sample plots (the colour maps: picture_kit_test).
#include <gtest/gtest.h>

#include <cmath>

#include "core/picture_kit.h"
#include "film/visualize.h"
#include "support/film_samples.h"

namespace aliaslab {
namespace {

using testing::makeSamples;
using testing::noisy;

TEST(Visualize, RenderFilterReproducesClassicTentPicture) {
  auto f = makeFilter("tent", 1.7f);
  const Image img = renderFilter(*f, 9, 9, 20);
  ASSERT_EQ(img.width(), 181);
  ASSERT_EQ(img.height(), 181);
  // corner (5.05, 5.05) of image pixel (101, 101), offset (0.55, 0.55) from (4.5, 4.5)
  EXPECT_NEAR(img.get(101, 101)[0], 1 - std::hypot(0.55, 0.55) / 1.7, 1e-6);
  EXPECT_NEAR(img.get(90, 95)[1], 1 - std::hypot(0.0, 0.25) / 1.7, 1e-6);
  EXPECT_EQ(img.get(90, 95)[0], img.get(90, 95)[2]);  // grey
  EXPECT_TRUE((img.get(41, 101) == Color(0, 0, 0)).all());   // in the support square, weight 0
  EXPECT_TRUE((img.get(21, 21) == Color(0, 0, 0.5f)).all()); // outside the support cells
  EXPECT_TRUE((img.get(100, 57) == Color(0, 0, 1)).all());   // grid column
  EXPECT_TRUE((img.get(57, 180) == Color(0, 0, 1)).all());   // last grid row
}

TEST(Visualize, RenderFilterSignedDrawsEvalCutAtTheRadiusAboveAColourBar) {
  auto f = makeFilter("gaussian", 1.f, {{"sigma", 1.0}});
  const Image img = renderFilterSigned(*f, 9, 9, 20);
  ASSERT_EQ(img.width(), std::max(181, kColorBarMinWidth));
  ASSERT_EQ(img.height(), 181 + kColorBarHeight);
  const int b = kColorBarHeight;
  // offset (0.55, 0.55) from (4.5, 4.5): d = 0.78 inside, weight exp(-d^2 / 2), shown as sqrt of it
  const float w = std::exp(-0.5f * (0.55f * 0.55f * 2));
  EXPECT_NEAR(img.get(101, b + 101)[1], 1 - std::sqrt(w), 1e-5);
  EXPECT_NEAR(img.get(101, b + 101)[0], 1, 1e-6);
  EXPECT_TRUE((img.get(112, b + 101) == Color(1, 1, 1)).all());  // offset (1.1, 0.55): beyond r = 1, white
  EXPECT_TRUE((img.get(100, b + 57) == Color::Constant(0.55f)).all());  // grid column
  // the bar runs blue (left) through white to red (right)
  const int barRow = kColorBarHeight - 1 - 8;
  EXPECT_TRUE((img.get(4, barRow) == Color(0, 0, 1)).all());
  EXPECT_TRUE((img.get(img.width() - 5, barRow) == Color(1, 0, 0)).all());
}

TEST(Visualize, RenderSamplesPutsEachSampleInItsPixel) {
  const SampleBuffer b = makeSamples(3, 2, 2, 4, noisy);
  const Image img = renderSamples(b, 10);
  ASSERT_EQ(img.width(), 30);
  ASSERT_EQ(img.height(), 20);
  for (int j = 0; j < 2; ++j)
    for (int i = 0; i < 3; ++i) {
      const FilmSample& s = b.pixel(i, j)[1];
      const int x = int(std::floor(s.x * 10)), y = int(std::floor(s.y * 10));
      EXPECT_EQ(x / 10, i);
      EXPECT_EQ(y / 10, j);
      EXPECT_TRUE((img.get(x, y) == s.L).all());
    }
  EXPECT_FLOAT_EQ(renderSamples(SampleBuffer(2, 2, 0), 4).get(1, 1)[0], 0.2f);  // (0,0) even: grey
  EXPECT_FLOAT_EQ(renderSamples(SampleBuffer(2, 2, 0), 4).get(5, 1)[0], 0.f);   // (1,0) odd: black
}

TEST(Visualize, RenderSamplesShowsTheBlockNeighboursOffsets) {
  // 2x2 film, 1 spp: pixel (i, j)'s sample at offset (0.1 + 0.4 i, 0.1 + 0.4 j). At zoom 10 every cell
  // shows its own sample in its colour and the three others' offsets as ghosts; a ghost never covers
  // a sample, and zoom < 4 draws the classic picture only.
  SampleBuffer b(2, 2, 1);
  for (int j = 0; j < 2; ++j)
    for (int i = 0; i < 2; ++i) {
      FilmSample& s = b.pixel(i, j)[0];
      s.x = i + 0.15f + 0.4f * i, s.y = j + 0.15f + 0.4f * j;
      s.L = Color(1.f, 0.5f * i, 0.5f * j);
    }
  const Image img = renderSamples(b, 10);
  for (int j = 0; j < 2; ++j)
    for (int i = 0; i < 2; ++i)
      for (int nj = 0; nj < 2; ++nj)
        for (int ni = 0; ni < 2; ++ni) {
          const int x = 10 * i + 1 + 4 * ni, y = 10 * j + 1 + 4 * nj;  // floor((i + 0.15 + 0.4 ni) * 10)
          const Color expect = (ni == i && nj == j) ? b.pixel(i, j)[0].L : Color(0.75f, 0.55f, 0.15f);
          EXPECT_TRUE((img.get(x, y) == expect).all()) << "cell " << i << "," << j << " offset of " << ni << "," << nj;
        }
  const Image small = renderSamples(b, 3);
  for (int y = 0; y < 6; ++y)
    for (int x = 0; x < 6; ++x) {
      const Color c = small.get(x, y);
      EXPECT_FALSE(c[0] == 0.75f && c[1] == 0.55f) << x << "," << y;
    }
}

TEST(Visualize, RenderSamplesMarkedOutlinesStrataAndRingsDarkSamples) {
  SampleBuffer b = makeSamples(2, 2, 1, 1, noisy);
  const Image plain = renderSamplesMarked(SampleBuffer(2, 2, 0), 20, 2, 2);  // 2 x 2 strata per 20-pixel cell
  const Color line(0.1f, 0.2f, 0.45f);
  EXPECT_TRUE((plain.get(9, 3) == line).all());   // x = 9..10 crosses the stratum boundary at 10
  EXPECT_TRUE((plain.get(3, 19) == line).all());  // the pixel boundary at 20 as well
  // a black sample far from the lines gets a white ring
  b.samples()[0].L = Color::Zero(), b.samples()[0].x = 0.26f, b.samples()[0].y = 0.26f;
  const Image marked = renderSamplesMarked(b, 20, 0, 0);
  EXPECT_TRUE((marked.get(5, 5) == Color::Zero()).all());
  EXPECT_TRUE((marked.get(6, 5) == Color::Ones()).all());
  EXPECT_TRUE((marked.get(4, 4) == Color::Ones()).all());
}

TEST(Visualize, PlotFilterPutsTheProfilePanelBelowTheKernel) {
  EXPECT_EQ(plotFilter(*makeFilter("lanczos", 2.f), 64).height(), 96);
  EXPECT_EQ(plotFilter(*makeFilter("lanczos", 2.f), 64).width(), 64);
}

}  // namespace
}  // namespace aliaslab
