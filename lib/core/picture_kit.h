// The picture kit: colour maps, a labelled colour bar and text on linear RGB Images (y up), for every picture a
// program writes (the film's filter plots, the study's error and noise maps, imgdiff's difference images).
#pragma once
#include <string>

#include "core/image.h"

namespace aliaslab {

/// The mean of a colour's three channels.
inline float channelMean(const Color& c) { return (c[0] + c[1] + c[2]) / 3.f; }

/// Diverging colour of t in [-1, 1] (clamped; NaN gives 0): white at 0, red
/// towards +1, blue towards -1 (the map of falseColor).
Color divergingColor(float t);
/// Sequential "hot" colour of t in [0, 1] (clamped; NaN gives 1): black,
/// red, yellow, white (the map of heatColor).
Color heatColorOf(float t);

/// `picture` above a legend band of kColorBarHeight rows: a horizontal bar
/// of map(t) for t from 0 (left) to 1 (right), and under it the labels
/// `low` at the left end, `mid` at the centre and `high` at the right end
/// (drawn with OpenImageIO's text rendering when a font is found; the bar
/// alone otherwise). The result is at least kColorBarMinWidth wide; the
/// picture sits at its top left over a dark grey background.
Image withColorBar(const Image& picture, Color (*map)(float t), const std::string& low, const std::string& mid,
                   const std::string& high);
inline constexpr int kColorBarHeight = 34, kColorBarMinWidth = 200;

/// Draws `text` in white on `img` with the top of its box at row yTop
/// (counted from the top of the picture) and its left at column x, at
/// `size` pixels. False when no font is found.
bool drawText(Image& img, int x, int yTop, const std::string& text, int size = 11);

/// Diverging map of a signed error image (channel mean / scale, clamped to
/// [-1, 1]): white at 0, red for positive, blue for negative.
Image falseColor(const Image& signedError, float scale);

/// Sequential "hot" map (black, red, yellow, white) of channel mean / maxValue clamped to [0, 1].
Image heatColor(const Image& value, float maxValue);

}  // namespace aliaslab
