// inspect: what an image file holds. Prints its size, channel names and
// per channel min / max / mean over the finite values and the NaN and
// infinity counts; for a cached reference (<cache>/<key>.exr beside
// <key>.json, lib/study/reference/reference.h) also the manifest's summary: scene,
// size, spp, sampler, seed, filter, radius, reference error, git revision.
#include <OpenImageIO/imageio.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <limits>
#include <regex>
#include <sstream>
#include <vector>

#include "common/cli.h"
#include "common/front_end.h"
#include "study/reference/manifest_summary.h"
#include "core/error.h"
#include "core/files.h"
#include "core/memory_limit.h"
#include "core/format.h"

using namespace aliaslab;
namespace fs = std::filesystem;

namespace {

void printManifest(const fs::path& json, const std::string& key) {
  std::ifstream in(json);
  std::stringstream s;
  s << in.rdbuf();
  std::printf("manifest: %s\n", json.string().c_str());
  for (const auto& [k, v] : manifestSummary(s.str(), key, json.string())) std::printf("  %s: %s\n", k.c_str(), v.c_str());
}

}  // namespace

namespace {
const FrontEnd kInspect{"inspect", {}, 1, 1, 1, ""};  // every error exits 1
}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"inspect: size, channels, min/max/mean, NaN/Inf counts of an image; a cached reference's manifest "
               "(aliaslab)"};
  setupCommandLine(app, "inspect");
  std::string file;
  app.add_option("FILE", file, "image file (EXR, PNG, ...)")->required();
  if (const int rc = parseCommandLine(app, argc, argv, "inspect"); rc >= 0) return rc;
  return runFrontEnd(kInspect, [&] {
    requireRegularFile(file, "an image is read from a regular file");  // a FIFO would block the reader
    auto input = OIIO::ImageInput::open(file);
    if (!input) throw FileError(file, "cannot read the image: " + OIIO::geterror());
    const OIIO::ImageSpec spec = input->spec();
    const int w = spec.width, h = spec.height, nc = spec.nchannels;
    // The header's size decides before anything is allocated (a damaged or hostile header can claim any size).
    const double bytes = double(w) * h * nc * sizeof(float);
    if (const MemoryLimit limit = memoryLimit(); limit.bytes > 0 && bytes > limit.bytes)
      throw FileError(file, "its header claims " + std::to_string(w) + " x " + std::to_string(h) + " pixels of " +
                                std::to_string(nc) + " channels: reading them needs " +
                                formatNumber(bytes / 1e9, "%.3g") + " GB, more than the " +
                                formatNumber(limit.bytes / 1e9, "%.3g") + " GB this process may use (" + limit.source +
                                "); nothing read");
    std::vector<float> px(static_cast<size_t>(w) * h * nc);
    if (!input->read_image(0, 0, 0, nc, OIIO::TypeDesc::FLOAT, px.data()))
      throw FileError(file, "cannot read the pixels: " + input->geterror());
    std::printf("file: %s\nsize: %d x %d\nformat: %s, %d channels\n", file.c_str(), w, h,
                spec.format.c_str(), nc);
    for (int c = 0; c < nc; ++c) {
      double lo = std::numeric_limits<double>::infinity(), hi = -lo, sum = 0;
      size_t finite = 0, nans = 0, infs = 0;
      for (size_t i = c; i < px.size(); i += nc) {
        const float v = px[i];
        if (std::isnan(v)) ++nans;
        else if (std::isinf(v)) ++infs;
        else lo = std::min<double>(lo, v), hi = std::max<double>(hi, v), sum += v, ++finite;
      }
      std::printf("channel %s: min %.6g max %.6g mean %.6g nan %zu inf %zu\n",
                  c < int(spec.channelnames.size()) ? spec.channelnames[c].c_str() : "?", finite ? lo : NAN,
                  finite ? hi : NAN, finite ? sum / finite : NAN, nans, infs);
    }
    const fs::path json = fs::path(file).replace_extension(".json");
    std::error_code ec;
    if (fs::is_regular_file(json, ec)) printManifest(json, fs::path(file).stem().string());
    return 0;
  });
}
