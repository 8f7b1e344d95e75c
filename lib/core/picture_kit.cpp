// The picture kit: colour maps, colour bar, text.
#include "core/picture_kit.h"

#include <OpenImageIO/imagebuf.h>
#include <OpenImageIO/imagebufalgo.h>

#include <algorithm>
#include <cmath>

namespace aliaslab {

Color divergingColor(float t) {
  t = std::clamp(std::isfinite(t) ? t : 0.f, -1.f, 1.f);
  const float a = 1.f - std::abs(t);
  return t >= 0 ? Color(1.f, a, a) : Color(a, a, 1.f);
}

Color heatColorOf(float t) {
  t = std::clamp(std::isfinite(t) ? t : 1.f, 0.f, 1.f);
  return Color(std::min(1.f, 3 * t), std::clamp(3 * t - 1, 0.f, 1.f), std::clamp(3 * t - 2, 0.f, 1.f));
}

namespace {
// OIIO's text box, or an undefined ROI when there is nothing to draw (no font, or empty text: text_size then
// returns a box with begin > end, whose width() would overflow).
OIIO::ROI textBox(const std::string& text, int size) {
  if (text.empty()) return OIIO::ROI();
  const OIIO::ROI box = OIIO::ImageBufAlgo::text_size(text, size, "DejaVuSans");
  return box.defined() && box.xend > box.xbegin && box.yend > box.ybegin ? box : OIIO::ROI();
}
}  // namespace

bool drawText(Image& img, int x, int yTop, const std::string& text, int size) {
  namespace IBA = OIIO::ImageBufAlgo;
  const OIIO::ROI box = textBox(text, size);
  if (!box.defined()) return false;
  // render white on black into a buffer the size of the text's box, then use it as coverage
  OIIO::ImageBuf buf(OIIO::ImageSpec(box.width(), box.height(), 1, OIIO::TypeDesc::FLOAT));
  IBA::zero(buf);
  const float white[1] = {1.f};
  if (!IBA::render_text(buf, -box.xbegin, -box.ybegin, text, size, "DejaVuSans", white)) return false;
  for (int r = 0; r < box.height(); ++r)
    for (int c = 0; c < box.width(); ++c) {
      const int X = x + c, Y = img.height() - 1 - (yTop + r);  // Image rows count from the bottom
      if (X < 0 || Y < 0 || X >= img.width() || Y >= img.height()) continue;
      float a = 0.f;
      buf.getpixel(c, r, &a, 1);
      a = std::clamp(a, 0.f, 1.f);
      img.set(X, Y, img.get(X, Y) * (1 - a) + Color::Constant(a));
    }
  return true;
}

Image withColorBar(const Image& picture, Color (*map)(float), const std::string& low, const std::string& mid,
                   const std::string& high) {
  const int w = std::max(picture.width(), kColorBarMinWidth), h = picture.height() + kColorBarHeight;
  Image out(w, h, Color::Constant(0.12f));
  for (int y = 0; y < picture.height(); ++y)
    for (int x = 0; x < picture.width(); ++x) out.set(x, kColorBarHeight + y, picture.get(x, y));
  // the bar: rows 3..14 of the band from its top, inset 4 pixels left and right
  const int x0 = 4, x1 = w - 5, top = picture.height() + 3;  // top: rows counted from the top of `out`
  for (int r = 0; r < 12; ++r)
    for (int x = x0; x <= x1; ++x) out.set(x, h - 1 - (top + r), map(float(x - x0) / float(x1 - x0)));
  const int textTop = top + 14;
  const int size = 10;
  auto width = [&](const std::string& t) {
    const OIIO::ROI b = textBox(t, size);
    return b.defined() ? b.width() : 0;
  };
  drawText(out, x0, textTop, low, size);
  drawText(out, (x0 + x1) / 2 - width(mid) / 2, textTop, mid, size);
  drawText(out, x1 - width(high), textTop, high, size);
  return out;
}

Image falseColor(const Image& signedError, float scale) {
  Image img(signedError.width(), signedError.height());
  for (int y = 0; y < img.height(); ++y)
    for (int x = 0; x < img.width(); ++x) img.set(x, y, divergingColor(channelMean(signedError.get(x, y)) / scale));
  return img;
}

Image heatColor(const Image& value, float maxValue) {
  Image img(value.width(), value.height());
  for (int y = 0; y < img.height(); ++y)
    for (int x = 0; x < img.width(); ++x) {
      img.set(x, y, heatColorOf(channelMean(value.get(x, y)) / maxValue));
    }
  return img;
}

}  // namespace aliaslab
