// Pictures of samples, filters and error maps (linear RGB Images, y up;
// write them with writeImage).
#pragma once
#include "core/image.h"
#include "film/film.h"
#include "filter/filter.h"
#include "sampling/sampler.h"

namespace aliaslab {

/// The classic -render_samples picture: (w*zoom) x (h*zoom), each pixel's
/// zoom x zoom block grey 0.2 when i + j is even else black, each sample one
/// image pixel at (floor(x*zoom), floor(y*zoom)) in its radiance (samples
/// outside the film are left out). zoom >= 1. With zoom >= 4 each pixel's
/// block also shows, as amber ghost dots (0.75, 0.55, 0.15) drawn before
/// the samples, the sub-pixel offsets of the other pixels of its aligned 2x2
/// block (pixels (i^1, j), (i, j^1), (i^1, j^1)): samplers correlated across
/// pixels (zsobol) fill each other's gaps, independent ones clump.
Image renderSamples(const SampleBuffer& samples, int zoom);

/// The classic -render_filter picture for a width x height film:
/// (width*zoom+1) x (height*zoom+1) dark blue (0,0,0.5); every cell within
/// classicSupport(filter) of the centre pixel (width/2, height/2) is painted
/// grey with the raw weight evalClassic at each image pixel's corner
/// (X/zoom, Y/zoom) offset from that pixel's centre (0 gives black); then
/// pure blue (0,0,1) on every row and column index that is a multiple of zoom.
Image renderFilter(const Filter& filter, int width, int height, int zoom);

/// A sampler's points over blocksX x blocksY pixels: white dots on a dark
/// background with grey pixel grid lines; (blocksX*zoom+1) x (blocksY*zoom+1).
Image plotSamplerPoints(const Sampler& sampler, int blocksX, int blocksY, int zoom);

/// The 2-D kernel over [-r, r]^2 as a diverging false colour (positive red,
/// negative blue, scaled by max |f|) in a size x size square, above a
/// size x size/2 panel with the 1-D profile f(dx, 0) as a white curve over a
/// grey zero line. Image size: size x (size + size/2).
Image plotFilter(const Filter& filter, int size);

/// Diverging map of a signed error image (channel mean / scale, clamped to
/// [-1, 1]): white at 0, red for positive, blue for negative.
Image falseColor(const Image& signedError, float scale);

/// Sequential "hot" map (black, red, yellow, white) of channel mean / maxValue clamped to [0, 1].
Image heatColor(const Image& value, float maxValue);

}  // namespace aliaslab
