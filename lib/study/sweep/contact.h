// The sweep's pictures.
//
// Per configuration (seed 0), in <out>/images/<scene>/:
//   <base>.png        the reconstruction (8-bit, classic truncation)
//   <base>-error.png  signed error I_0 - G in a diverging map: blue negative,
//                     red positive, white 0, saturated at +-kErrorScale
//   <base>-noise.png  per-pixel noise as the standard deviation s over the
//                     K seeds (sqrt of the noise map), black 0 .. white at kNoiseScale
//   <base>-density.png  adaptive samplers only (when `density` is given): the
//                     reconstruction, its signed error and the samples per
//                     pixel (heat map, black 0 .. white at the largest count)
//                     side by side, enlarged to at least 128 pixels high, with
//                     the density's colour bar labelled in samples per pixel
// (colour maps: film/visualize.h falseColor and heatColor, each above a
// colour bar labelled with its scale: film/visualize.h withColorBar), with
// <base> = <sampler>-spp<spp>-<filter>-r<radius>-<reconstruction>.
//
// Per scene, contact-<scene>.png in <out>/images/: the methods side by side
// (rows: samplers; columns: the pixel-area reference, then each filter at its
// best radius by mse_area; weighted mode at the largest spp of the CSV), each
// tile above a nearest-neighbour zoom of the hardest region: the square
// window with the largest summed squared error against the reference over
// all tiles (outlined on every tile). Tiles are labelled when a font is
// available; contact-<scene>.txt always lists the tiles row by row.
#pragma once
#include <string>

#include "core/image.h"
#include "study/records/csv.h"

namespace aliaslab {

inline constexpr float kErrorScale = 0.25f;  ///< |signed error| shown fully saturated
inline constexpr float kNoiseScale = 0.25f;  ///< standard deviation shown white

/// "<sampler>-spp<spp>-<filter>-r<radius>-<reconstruction>".
std::string configurationImageBase(const CsvRow& row);

/// Writes the per-configuration images. `noise` is the per-pixel
/// variance s^2 (MetricAccumulator::noiseMap); `density` (samples per pixel
/// of seed 0, render/adaptive.h sampleDensity) adds <base>-density.png when
/// not empty. Throws FileError.
void writeConfigurationImages(const std::string& dir, const std::string& base, const Image& seed0,
                              const Image& reference, const Image& noise, const Image& density = Image());

/// The reconstruction | signed error | density panel with its colour bar (see above).
Image densityPanel(const Image& seed0, const Image& reference, const Image& density);

/// One contact sheet per scene of the CSV, from the PNGs under imagesDir.
/// Scenes whose images are missing are skipped.
void writeContactSheets(const std::string& csvPath, const std::string& imagesDir);

}  // namespace aliaslab
