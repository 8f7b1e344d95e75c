// imgdiff: how two images differ. A is the test image, B the reference (any
// format OpenImageIO reads; the first three channels). Prints, one
// "name value" per line:
//   mse            mean over pixels and channels of (A - B)^2
//   relmse         mean of (A - B)^2 / (B^2 + 0.01) (relative, for HDR data)
//   psnr_db        10 log10(1 / mse) (peak 1; inf for identical images)
//   bias, spread   the difference D = A - B split as mse = bias^2 + spread^2:
//                  bias = mean D, spread = its standard deviation (population)
//   flip           mean LDR-FLIP (lib/measure/flip/flip.h), 67 pixels per degree
//   max_abs        largest |D|
// With --output, a false-colour picture of the channel-mean difference
// (red A brighter, blue darker, saturated at --scale, default max |D|)
// with a colour bar; with --flip-output the FLIP map (black 0 .. white 1).
#include <cmath>
#include <cstdio>
#include <iostream>

#include "common/cli.h"
#include "common/front_end.h"
#include "core/error.h"
#include "core/files.h"
#include "core/format.h"
#include "core/image.h"
#include "core/memory_limit.h"
#include "core/picture_kit.h"
#include "measure/flip/flip.h"
#include "measure/image_diff.h"

using namespace aliaslab;

namespace {
const FrontEnd kImgdiff{"imgdiff", {}, 2, 1, 1, ""};  // bad options exit 2, anything else 1
}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"imgdiff: MSE, relative MSE, PSNR, bias and spread, and LDR-FLIP of image A against reference B "
               "(aliaslab)"};
  setupCommandLine(app, "imgdiff");
  std::string a, b, output, flipOutput;
  double scale = 0, ppd = kFlipDefaultPixelsPerDegree;
  app.add_option("A", a, "test image")->required();
  app.add_option("B", b, "reference image")->required();
  app.add_option("--output", output, "false-colour difference picture file (.png, .exr) with a colour bar");
  app.add_option("--flip-output", flipOutput, "FLIP map picture file (.png, .exr)");
  app.add_option("--scale", scale, "difference shown fully saturated in --output (default: max |A - B|)");
  app.add_option("--ppd", ppd, "FLIP viewing condition, pixels per degree")->check(CLI::Range(1.0, 1000.0));
  if (const int rc = parseCommandLine(app, argc, argv, "imgdiff"); rc >= 0) return rc;
  return runFrontEnd(kImgdiff, [&] {
    if (!(std::isfinite(scale) && scale >= 0)) throw OptionError("--scale", "must be a finite number >= 0");
    for (const auto& [opt, path] : {std::pair<std::string, std::string>{"--output", output}, {"--flip-output", flipOutput}})
      if (!path.empty() && !isSupportedImageExtension(path))
        throw OptionError(opt, "'" + path + "': unsupported image extension (use .png, .tga or .exr)");
    // No output may be an input (nor the other output): writing it would destroy what is compared.
    refuseOutputsOverInputs({{"--output", output}, {"--flip-output", flipOutput}}, {a, b});
    // Fails before reading when the images cannot fit: per pixel, each image's decoded channels and its Image,
    // the difference images of --output, the FLIP map and FLIP's working planes (about 48 floats a pixel for
    // both images together, measure/flip/flip.h): an upper estimate, not a measurement.
    for (const auto& [key, path] : {std::pair<std::string, std::string>{"A", a}, {"B", b}}) {
      const ImageHeader h = readImageHeader(path);
      const double perPixel = 2.0 * (h.channels * sizeof(float) + sizeof(Color)) + 3.0 * sizeof(Color) +
                              49.0 * sizeof(float);
      requireMemory(double(h.width) * h.height * perPixel, key,
                    "comparing two " + std::to_string(h.width) + " x " + std::to_string(h.height) + " images");
    }
    const Image A = readImage(a), B = readImage(b);
    // NaN or infinite pixels have no difference: refused rather than reported as a number (or as identical).
    for (const auto& [path, image] : {std::pair<const std::string&, const Image&>{a, A}, {b, B}})
      if (const size_t n = countNonFinitePixels(image))
        throw FileError(path, std::to_string(n) + " of " + std::to_string(size_t(image.width()) * image.height()) +
                                  " pixels are NaN or infinite: the difference is undefined");
    if (A.width() != B.width() || A.height() != B.height())
      throw FileError(b, "size " + std::to_string(B.width()) + " x " + std::to_string(B.height()) + " differs from " +
                             a + ": " + std::to_string(A.width()) + " x " + std::to_string(A.height()));
    const ImageDifference d = imageDifference(A, B);
    const std::vector<float> flip = flipMap(A, B, ppd);
    double flipMean = 0;
    for (float v : flip) flipMean += v;
    flipMean /= flip.size();
    std::printf("size %d %d\nmse %.9g\nrelmse %.9g\npsnr_db %.6g\nbias %.9g\nspread %.9g\nflip %.6g\nmax_abs %.9g\n",
                A.width(), A.height(), d.mse, d.relmse, d.psnr, d.bias, d.spread, flipMean, d.maxAbs);
    if (!output.empty()) {
      const float s = static_cast<float>(scale > 0 ? scale : (d.maxAbs > 0 ? d.maxAbs : 1.0));
      writeImage(output, withColorBar(falseColor(differenceImage(A, B), s),
                                      [](float t) { return divergingColor(2 * t - 1); }, "-" + formatNumber(s),
                                      "0 (A - B)", "+" + formatNumber(s)));
    }
    if (!flipOutput.empty()) {
      Image f(A.width(), A.height());
      for (int y = 0; y < A.height(); ++y)
        for (int x = 0; x < A.width(); ++x) f.set(x, y, Color::Constant(flip[f.index(x, y)]));
      writeImage(flipOutput, withColorBar(f, [](float t) { return Color(Color::Constant(t)); }, "0", "FLIP", "1"));
    }
    return 0;
  });
}
