// Numbers that cannot lie: a small sweep over every bundled scene with the
// default study's samplers and filters (16 px, 2 seeds), then
//  - every image it wrote (PNG images, EXR reference cache) is finite;
//  - every CSV row's counts are recounted independently: the sample sets are
//    traced again here (deterministic in the seed), reconstructed, and
//    negative pixels counted from the images themselves; undefined pixels
//    are recounted from the filter weights of the samples around each pixel
//    centre (|sum| below 1e-8 |f(0,0)|, film/film.h); the CSV must hold the
//    sums over the seeds exactly;
//  - the seed-0 PNG written for a row is that configuration's seed-0 image.
#include "aliaslab_paths.h"
#include <gtest/gtest.h>

#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>

#include "core/image.h"
#include "render/render.h"
#include "study/config.h"
#include "study/validate.h"
#include "study/sweep/contact.h"
#include "study/records/csv.h"
#include "study/study_scene.h"
#include "study/sweep/sweep.h"
#include "support/study_rows.h"

namespace fs = std::filesystem;
using namespace aliaslab;

namespace {

constexpr int kSeeds = 2, kMaxSize = 16, kSpp = 4;

const fs::path& sweepDir() {
  static const fs::path dir = [] {
    fs::path d = fs::temp_directory_path() / ("aliaslab_cannot_lie_" + std::to_string(::getpid()));
    fs::remove_all(d);
    StudyConfig c;
    c.scenes = {ALIASLAB_SOURCE_DIR "/scenes"};
    c.samplers = {"random", "uniform", "jittered", "sobol", "pmj02", "bluenoise"};
    c.spp = {kSpp};
    c.filters = {"box", "tent", "gaussian", "mitchell", "lanczos"};
    c.radii = {0.5, 2.0};
    c.seeds = kSeeds;
    c.refSpp = 64;
    c.targets = {"area"};
    c.maxSize = kMaxSize;
    c.out = (d / "out").string();
    c.cache = (d / "cache").string();
    c.images = true;
    c.progress = false;
    runSweep(c);
    return d;
  }();
  return dir;
}

std::vector<std::vector<std::string>> csvRows(const fs::path& csv) { return aliaslab::testing::readStudyRows(csv.string()); }

size_t column(const std::string& name) {
  const auto& cols = csvColumns();
  return static_cast<size_t>(std::find(cols.begin(), cols.end(), name) - cols.begin());
}

/// Every PNG and EXR under the sweep's folders is finite.
void checkWrittenImagesAreFinite() {
  size_t images = 0, exr = 0;
  for (const auto& e : fs::recursive_directory_iterator(sweepDir())) {
    const std::string ext = e.path().extension().string();
    if (ext != ".png" && ext != ".exr") continue;
    const Image im = readImage(e.path().string());
    size_t bad = 0;
    for (size_t i = 0; i < size_t(3) * im.width() * im.height(); ++i) bad += !std::isfinite(im.data()[i]);
    EXPECT_EQ(bad, 0u) << e.path();
    ++images, exr += ext == ".exr";
  }
  EXPECT_GT(images, 1000u);
  EXPECT_GT(exr, 10u) << "the reference cache holds EXR images";
}

/// Pixels whose |sum of filter weights| over the samples around their centre is below 1e-8 |f(0,0)|.
size_t undefinedByWeights(const SampleBuffer& s, const Filter& f) {
  const int R = static_cast<int>(std::ceil(f.radius())) + 1;
  const double tol = 1e-8 * std::abs(f.eval(0.f, 0.f));
  size_t undefined = 0;
  for (int j = 0; j < s.height(); ++j)
    for (int i = 0; i < s.width(); ++i) {
      double sum = 0;
      for (int b = std::max(0, j - R); b <= std::min(s.height() - 1, j + R); ++b)
        for (int a = std::max(0, i - R); a <= std::min(s.width() - 1, i + R); ++a)
          for (int k = 0; k < s.spp(); ++k) {
            const FilmSample& x = s.pixel(a, b)[k];
            sum += f.eval(x.x - (i + 0.5f), x.y - (j + 0.5f));
          }
      undefined += std::abs(sum) < tol;
    }
  return undefined;
}

/// Every row's counts equal the recount; every row's PNG is its seed-0 image.
void checkCsvAgainstRecount() {
  const fs::path out = sweepDir() / "out";
  const auto rows = csvRows(out / "study.csv");
  ASSERT_GT(rows.size(), 500u);
  const size_t cScene = column("scene"), cW = column("width"), cH = column("height"), cSampler = column("sampler"),
               cSpp = column("spp"), cFilter = column("filter"), cRadius = column("radius"),
               cRecon = column("reconstruction"), cNan = column("nan_pixels"), cNeg = column("negative_pixels"),
               cUndef = column("undefined_pixels");

  std::map<std::string, std::unique_ptr<StudyScene>> scenes;
  std::map<std::string, std::vector<SampleBuffer>> traced;  // (scene, sampler) -> one buffer per seed
  size_t negativeSeen = 0;
  for (const auto& f : rows) {
    // Every measure finite, every count within K x pixels.
    for (const char* m : {"mse", "aliasing", "noise", "mse_area", "ref_error"})
      EXPECT_TRUE(std::isfinite(std::stod(f[column(m)]))) << m << " of " << f[cScene] << " " << f[cFilter];
    const long long pixels = std::stoll(f[cW]) * std::stoll(f[cH]);
    for (size_t c : {cNan, cNeg, cUndef}) {
      EXPECT_GE(std::stoll(f[c]), 0);
      EXPECT_LE(std::stoll(f[c]), kSeeds * pixels);
    }

    // Trace the sample sets again.
    auto& scene = scenes[f[cScene]];
    if (!scene) scene = loadStudyScene(ALIASLAB_SOURCE_DIR "/scenes/" + f[cScene] + ".txt", 0, 0, kMaxSize);
    ASSERT_EQ(scene->width, std::stoi(f[cW]));
    ASSERT_EQ(scene->height, std::stoi(f[cH]));
    auto& buffers = traced[f[cScene] + "/" + f[cSampler]];
    for (int k = static_cast<int>(buffers.size()); k < kSeeds; ++k)
      buffers.push_back(traceSamples(*scene->tracer, *makeSampler(f[cSampler], std::stoi(f[cSpp]), k),
                                     scene->width, scene->height, 1));

    // Reconstruct and recount.
    ASSERT_EQ(f[cRecon], "weighted");
    const auto filter = makeFilter(f[cFilter], static_cast<float>(std::stod(f[cRadius])));
    long long negative = 0, undefined = 0, nan = 0;
    Image seed0;
    for (int k = 0; k < kSeeds; ++k) {
      Reconstruction r = reconstruct(buffers[k], *filter, ReconMode::WeightedAverage, 1);
      for (int y = 0; y < r.image.height(); ++y)
        for (int x = 0; x < r.image.width(); ++x) {
          const Color c = r.image.get(x, y);
          ASSERT_TRUE(c.isFinite().all()) << "a NaN or infinity reached an image";
          negative += (c < 0.f).any();
        }
      undefined += static_cast<long long>(undefinedByWeights(buffers[k], *filter));
      nan += static_cast<long long>(r.stats.nanPixels);
      if (k == 0) seed0 = std::move(r.image);
    }
    const std::string what = f[cScene] + " " + f[cSampler] + " " + f[cFilter] + " r=" + f[cRadius];
    EXPECT_EQ(std::stoll(f[cNeg]), negative) << what;
    EXPECT_EQ(std::stoll(f[cUndef]), undefined) << what;
    EXPECT_EQ(std::stoll(f[cNan]), nan) << what;
    negativeSeen += negative > 0;

    // The written PNG is the seed-0 image, quantised like writeImage (within one code).
    CsvRow key;
    key.sampler = f[cSampler], key.spp = std::stoi(f[cSpp]), key.filter = f[cFilter];
    key.radius = std::stod(f[cRadius]), key.reconstruction = f[cRecon];
    const fs::path png = out / "images" / f[cScene] / (configurationImageBase(key) + ".png");
    ASSERT_TRUE(fs::exists(png)) << png;
    const Image written = readImage(png.string());
    ASSERT_EQ(written.width(), seed0.width());
    ASSERT_EQ(written.height(), seed0.height());
    float worst = 0;
    for (int y = 0; y < seed0.height(); ++y)
      for (int x = 0; x < seed0.width(); ++x) {
        const Color q = (seed0.get(x, y).max(0.f).min(1.f) * 255.f).floor() / 255.f;
        worst = std::max(worst, (q - written.get(x, y)).abs().maxCoeff());
      }
    EXPECT_LE(worst, 1.f / 255.f + 1e-6f) << png;
  }
  EXPECT_GT(negativeSeen, 0u) << "Mitchell and Lanczos ring below zero somewhere in the scenes";
}

// One test, so that ctest runs the sweep once.
TEST(CannotLie, ImagesAreFiniteAndCsvCountsEqualAnIndependentRecount) {
  {
    SCOPED_TRACE("images");
    checkWrittenImagesAreFinite();
  }
  {
    SCOPED_TRACE("csv");
    checkCsvAgainstRecount();
  }
  if (!HasFailure()) fs::remove_all(sweepDir());
}

}  // namespace
