// The picture kit (core/picture_kit.h): the colour maps' values at their ends and middle, the colour bar's layout
// (picture at the top left, the bar showing map(t) from t = 0 at the left to 1 at the right), text drawing.
#include <gtest/gtest.h>

#include <cmath>

#include "core/picture_kit.h"

namespace aliaslab {
namespace {

bool same(const Color& a, const Color& b) { return (a == b).all(); }

TEST(PictureKit, DivergingMapIsWhiteAtZeroRedPositiveBlueNegative) {
  EXPECT_TRUE(same(divergingColor(0.f), Color(1, 1, 1)));
  EXPECT_TRUE(same(divergingColor(1.f), Color(1, 0, 0)));
  EXPECT_TRUE(same(divergingColor(-1.f), Color(0, 0, 1)));
  EXPECT_TRUE(same(divergingColor(0.25f), Color(1, 0.75f, 0.75f)));
  EXPECT_TRUE(same(divergingColor(7.f), Color(1, 0, 0)));  // clamped
  EXPECT_TRUE(same(divergingColor(NAN), Color(1, 1, 1)));
}

TEST(PictureKit, HeatMapRunsBlackRedYellowWhite) {
  EXPECT_TRUE(same(heatColorOf(0.f), Color(0, 0, 0)));
  EXPECT_TRUE(same(heatColorOf(1.f / 3), Color(1, 0, 0)));
  EXPECT_NEAR(heatColorOf(2.f / 3)[1], 1.f, 1e-6f);
  EXPECT_NEAR(heatColorOf(2.f / 3)[2], 0.f, 1e-6f);
  EXPECT_TRUE(same(heatColorOf(1.f), Color(1, 1, 1)));
  EXPECT_TRUE(same(heatColorOf(NAN), Color(1, 1, 1)));
  EXPECT_TRUE(same(heatColorOf(-3.f), Color(0, 0, 0)));  // clamped
}

TEST(PictureKit, ImageMapsUseTheChannelMeanAndKeepSignAndOrder) {
  Image e(3, 1);
  e.set(0, 0, Color::Constant(-1)), e.set(1, 0, Color::Zero()), e.set(2, 0, Color(1.5f, 0.f, 0.f));
  const Image fc = falseColor(e, 1.f);
  EXPECT_TRUE(same(fc.get(0, 0), Color(0, 0, 1)));
  EXPECT_TRUE(same(fc.get(1, 0), Color(1, 1, 1)));
  EXPECT_TRUE(same(fc.get(2, 0), Color(1, 0.5f, 0.5f)));  // mean 0.5
  const Image hc = heatColor(e, 1.5f);
  EXPECT_TRUE(same(hc.get(0, 0), Color(0, 0, 0)));
  EXPECT_TRUE(same(hc.get(2, 0), heatColorOf(0.5f / 1.5f)));
  EXPECT_LT(hc.get(1, 0).sum(), hc.get(2, 0).sum());
}

TEST(PictureKit, ColourBarSitsBelowThePictureAndRunsFromMapZeroToMapOne) {
  Image picture(12, 5, Color(0.3f, 0.6f, 0.9f));
  picture.set(0, 0, Color(1, 0, 1));  // bottom-left pixel
  const auto grey = [](float t) { return Color(Color::Constant(t)); };
  const Image out = withColorBar(picture, grey, "", "", "");
  ASSERT_EQ(out.width(), kColorBarMinWidth);
  ASSERT_EQ(out.height(), 5 + kColorBarHeight);
  // The picture keeps its rows above the band (rows count from the bottom).
  EXPECT_TRUE(same(out.get(0, kColorBarHeight), Color(1, 0, 1)));
  EXPECT_TRUE(same(out.get(11, kColorBarHeight + 4), Color(0.3f, 0.6f, 0.9f)));
  EXPECT_TRUE(same(out.get(12, kColorBarHeight + 4), Color::Constant(0.12f)));  // background beside it
  // The bar: 12 rows starting 3 rows below the picture, from x = 4 (map(0)) to x = width - 5 (map(1)).
  const int barRow = out.height() - 1 - (picture.height() + 3);
  EXPECT_TRUE(same(out.get(4, barRow), Color::Zero()));
  EXPECT_TRUE(same(out.get(out.width() - 5, barRow), Color::Ones()));
  EXPECT_NEAR(out.get(4 + (out.width() - 9) / 2, barRow)[0], 0.5f, 0.01f);
  EXPECT_TRUE(same(out.get(4, barRow - 11), Color::Zero()));
  // A wide picture widens the bar.
  EXPECT_EQ(withColorBar(Image(300, 2), grey, "", "", "").width(), 300);
}

TEST(PictureKit, DrawTextMarksPixelsWhenAFontIsFoundAndNothingOtherwise) {
  Image img(60, 20, Color::Zero());
  const bool drawn = drawText(img, 2, 2, "Hi", 12);
  double sum = 0;
  for (int y = 0; y < img.height(); ++y)
    for (int x = 0; x < img.width(); ++x) sum += img.get(x, y).sum();
  if (drawn) EXPECT_GT(sum, 0.0) << "the text left no mark";
  else EXPECT_EQ(sum, 0.0) << "no font, yet the picture changed";
  for (int y = 0; y < img.height(); ++y)  // white text on black: grey levels only
    for (int x = 0; x < img.width(); ++x) EXPECT_EQ(img.get(x, y)[0], img.get(x, y)[2]);
}

}  // namespace
}  // namespace aliaslab
