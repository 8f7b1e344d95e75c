// Pictures of the film: its samples and its filters (linear RGB Images, y up; write them with writeImage). The
// colour maps, colour bar and text they use are the picture kit, core/picture_kit.h.
#pragma once
#include <string>

#include "core/image.h"
#include "film/film.h"
#include "filter/filter.h"

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

/// The same picture made readable, for the general flags: when
/// strataColumns x strataRows > 0 each pixel's strata are outlined in dark
/// blue (0.1, 0.2, 0.45); each sample is its own image pixel in its colour
/// with, at zoom >= 4, a ring of the 8 surrounding image pixels in white
/// for a dark sample (channel mean < 0.5) or black for a bright one, so a
/// black sample on a black cell still shows.
Image renderSamplesMarked(const SampleBuffer& samples, int zoom, int strataColumns, int strataRows);

/// The classic -render_filter picture for a width x height film:
/// (width*zoom+1) x (height*zoom+1) dark blue (0,0,0.5); every cell within
/// classicSupport(filter) of the centre pixel (width/2, height/2) is painted
/// grey with the raw weight of the course variant (makeCourseVariant, else
/// the filter itself) at each image pixel's corner
/// (X/zoom, Y/zoom) offset from that pixel's centre (0 gives black); then
/// pure blue (0,0,1) on every row and column index that is a multiple of zoom.
Image renderFilter(const Filter& filter, int width, int height, int zoom);

/// The -render_filter picture of the filter the weighted (and importance)
/// reconstruction really uses: eval(), cut at the filter's radius, so a
/// Gaussian of radius R shows its disc of radius R whatever sigma is. The
/// top (width*zoom+1) x (height*zoom+1) block shows eval at each image
/// pixel's corner offset (X/zoom, Y/zoom) from the centre pixel's centre,
/// in the diverging map of falseColor (white 0, red positive, blue negative
/// lobes) of sign(f) sqrt(|f| / max|f|), so a lobe of 5% of the peak is a
/// clear tint, with grey pixel grid lines; below it withColorBar's legend,
/// linear in the weight from -max|f| to +max|f|.
Image renderFilterSigned(const Filter& filter, int width, int height, int zoom);

/// The 2-D kernel over [-r, r]^2 as a diverging false colour (positive red,
/// negative blue, scaled by max |f|) in a size x size square, above a
/// size x size/2 panel with the 1-D profile f(dx, 0) as a white curve over a
/// grey zero line. Image size: size x (size + size/2).
Image plotFilter(const Filter& filter, int size);

}  // namespace aliaslab
