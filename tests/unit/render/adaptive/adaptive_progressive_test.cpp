// Adaptive sampling keeps its base's stratification (render/adaptive/adaptive.h, docs/adaptive.md "Bias"): with a
// progressive base the fresh samples continue each pixel's own sequence, so a pixel that gets exactly its share is
// the base's own spp-point set. Checked sample for sample (sobol, pmj02, halton, random), in distribution for
// jittered (progressive jittered at 4^k points: jittered's noise within 3 se), and on the Siemens star at 16 spp,
// where every pixel holds an edge and the earlier design (pilot and fresh samples two independent sets) had 1.95x
// jittered's error: now no worse than jittered beyond 2 se. Progressive jittered itself: every prefix of 4^k points
// has one point in each cell of the 2^k grid.
#include "aliaslab_paths.h"
#include <gtest/gtest.h>

#include <cmath>
#include <set>

#include "accel/aggregate.h"
#include "filter/filter.h"
#include "measure/metrics.h"
#include "render/adaptive/adaptive.h"
#include "render/render.h"
#include "sampling/progressive.h"
#include "study/config.h"
#include "study/records/csv.h"
#include "study/study_scene.h"
#include "study/sweep/sweep.h"
#include "support/scratch_dir.h"

namespace aliaslab {
namespace {

const std::string kSrc = ALIASLAB_SOURCE_DIR;
// The negative control for 4 spp: a grating of 2 cycles per pixel, full contrast in every pixel, so contrast
// marks every pixel and the budget goes evenly.
const std::string kGrating = kSrc + "/scenes/controls/negative_spp4.txt";

/// One colour, nothing else: the error method's pilots have no spread anywhere.
struct FlatScene {
  Scene scene;
  std::unique_ptr<Aggregate> aggregate;
  std::unique_ptr<Tracer> tracer;
  FlatScene() {
    scene.background = Color(0.3f, 0.6f, 0.9f);
    scene.camera = makeOrthographicCamera(Vec3(0, 0, 10), -Vec3::UnitZ(), Vec3::UnitY(), 2.f);
    scene.root = std::make_unique<Group>(ObjectList{});
    aggregate = makeBruteForce(*scene.root);
    tracer = std::make_unique<Tracer>(scene, *aggregate, TraceOptions{});
  }
};

// docs/adaptive.md "What all three guarantee": with first=1 (nothing left to decide) adaptive-contrast:B is B sample
// for sample when B's pixel sequence is progressive (random, halton, sobol, pmj02) or B gives no warning at that
// spp (bluenoise; the grid at square counts); at other counts the grid is drawn as parts it handles fully (7 =
// 4 + 2 + 1), and jittered is progressive jittered: never its points, only their distribution at 4^k.
TEST(AdaptiveFirstPass, IsTheBaseSampleForSampleExactlyWhereTheDocsSay) {
  FlatScene s;
  auto same = [&](const std::string& base, int spp) {
    const SampleBuffer a =
        traceAdaptive(*s.tracer, *makeAdaptiveSampler("adaptive-contrast:" + base + "+first=1", spp, 4), 8, 8, 2);
    const SampleBuffer b = traceSamples(*s.tracer, *makeSampler(base, spp, 4), 8, 8, 2);
    if (a.samples().size() != b.samples().size()) return false;
    for (size_t k = 0; k < a.samples().size(); ++k)
      if (a.samples()[k].x != b.samples()[k].x || a.samples()[k].y != b.samples()[k].y) return false;
    return true;
  };
  for (int spp : {7, 16, 64}) {
    for (const char* base : {"random", "halton", "sobol", "pmj02", "bluenoise"}) EXPECT_TRUE(same(base, spp)) << base << " " << spp;
    EXPECT_FALSE(same("jittered", spp)) << spp;
    EXPECT_EQ(same("uniform", spp), spp != 7) << spp;  // 7 is not a square: 4 + 2 + 1
  }
}

TEST(ProgressiveJittered, EveryPowerOfFourPrefixIsJittered) {
  for (uint64_t seed : {1u, 2u})
    for (int px = 0; px < 3; ++px) {
      const auto s = makeProgressiveSampler("jittered", 256, seed);
      std::vector<Vec2> p(256);
      s->generate(px, 7, p.data());
      for (int n : {1, 4, 16, 64, 256}) {
        const int k = static_cast<int>(std::lround(std::sqrt(n)));
        std::set<int> cells;
        for (int i = 0; i < n; ++i) {
          ASSERT_TRUE(p[i].x() >= 0 && p[i].x() < 1 && p[i].y() >= 0 && p[i].y() < 1);
          cells.insert(int(std::floor(p[i].y() * k)) * k + int(std::floor(p[i].x() * k)));
        }
        EXPECT_EQ(cells.size(), size_t(n)) << "prefix " << n;
      }
      std::vector<Vec2> q(16);
      makeProgressiveSampler("jittered", 16, seed)->generate(px, 7, q.data());  // the same points at any count
      for (int i = 0; i < 16; ++i) EXPECT_TRUE(q[i] == p[i]);
    }
  EXPECT_EQ(makeProgressiveSampler("cmj", 16, 1), nullptr);
  EXPECT_EQ(makeProgressiveSampler("zsobol", 16, 1), nullptr);  // correlated across pixels on purpose
}

// Every pixel gets exactly spp samples (contrast on the grating: all marked alike; error on a flat image: all at
// the floor plus the even rest), and they are the base sampler's own points, in order, each weighing 1/spp.
TEST(AdaptiveProgressive, AnEvenShareIsTheBaseSampleForSample) {
  const auto grating = loadStudyScene(kGrating);
  FlatScene flat;
  for (const std::string base : {"sobol", "pmj02", "halton", "random"})
    for (const std::string method : {"contrast", "error"}) {
      const std::string name = "adaptive-" + method + ":" + base;
      SCOPED_TRACE(name);
      const int spp = 16, w = method == "contrast" ? 64 : 16, h = w;
      const Tracer& t = method == "contrast" ? *grating->tracer : *flat.tracer;
      const auto a = makeAdaptiveSampler(name, spp, 5);
      ASSERT_TRUE(a->progressive());
      const SampleBuffer b = traceAdaptive(t, *a, w, h, 2);
      const auto s = makeSampler(base, spp, 5);
      std::vector<Vec2> u(spp);
      for (int j = 0; j < h; ++j)
        for (int i = 0; i < w; ++i) {
          ASSERT_EQ(b.count(i, j), spp) << i << "," << j;
          s->generate(i, j, u.data());
          for (int k = 0; k < spp; ++k) {
            const FilmSample& f = b.pixel(i, j)[k];
            // (the film position i + u rounded to float, kept inside the pixel as every sample is)
            const auto at = [](int i, float u) { return std::min(i + u, std::nextafter(float(i + 1), 0.f)); };
            ASSERT_EQ(f.x, at(i, u[k].x())) << i << "," << j << " sample " << k;
            ASSERT_EQ(f.y, at(j, u[k].y())) << i << "," << j << " sample " << k;
            ASSERT_EQ(f.weight, 1.f / spp);
          }
        }
    }
}

/// noise and its se of K seeds of an image source on the grating, box r = 0.5.
template <class Trace>
Metrics noiseOf(const Tracer& t, int w, int h, Trace trace) {
  const Image zero(w, h, Color::Zero());
  MetricAccumulator acc(RefEstimate{&zero, nullptr, 0.5}, {});
  const auto box = makeFilter("box", 0.5f);
  for (uint64_t k = 0; k < 8; ++k) acc.add(reconstruct(trace(k), *box, ReconMode::WeightedAverage, 2).image);
  return acc.result();
}

// jittered through progressive jittered: at an even share of 16 = 4^2 points a pixel's set is distributed as
// jittered's, so its noise is jittered's within 3 se (the earlier design: pilot and fresh samples two independent
// jittered sets, about twice the variance on a smooth integrand; here 2 cycles per pixel, smooth at 4 x 4 strata).
TEST(AdaptiveProgressive, JitteredAtAnEvenShareHasJitteredsNoise) {
  const auto scene = loadStudyScene(kGrating);
  const int w = scene->width, h = scene->height;
  const Metrics base = noiseOf(*scene->tracer, w, h, [&](uint64_t k) {
    return traceSamples(*scene->tracer, *makeSampler("jittered", 16, k), w, h, 2);
  });
  for (const std::string name : {"adaptive-contrast:jittered"}) {
    const Metrics m = noiseOf(*scene->tracer, w, h, [&](uint64_t k) {
      const SampleBuffer b = traceAdaptive(*scene->tracer, *makeAdaptiveSampler(name, 16, k), w, h, 2);
      EXPECT_EQ(spentSamples(b).max, 16);  // an even share everywhere
      return b;
    });
    const double se = std::hypot(m.noiseSe, base.noiseSe);
    std::printf("%s: noise %.4g +- %.2g, jittered %.4g +- %.2g (ratio %.3f)\n", name.c_str(), m.noise, m.noiseSe,
                base.noise, base.noiseSe, m.noise / base.noise);
    EXPECT_LT(std::abs(m.noise - base.noise), 3 * se);
  }
}

// The Siemens star at 48 px (the quick study's size), 16 spp, box r = 0.5 against the pixel area: every pixel holds
// an edge, nothing moves, and the progressive methods are no worse than jittered beyond 2 standard errors.
TEST(AdaptiveProgressive, SiemensAt16SppNoLongerLosesToItsBase) {
  StudyConfig c;
  c.scenes = {kSrc + "/scenes/siemens.txt"};
  c.maxSize = 48;
  c.samplers = {"jittered", "adaptive-contrast:jittered", "adaptive-error:jittered"};
  c.spp = {16};
  c.filters = {"box"};
  c.radii = {0.5};
  c.seeds = 8;
  c.refSpp = 1024;
  c.targets = {"area"};
  const auto& dir = testing::scratchDir("aliaslab_adaptive_progressive_test");
  c.out = (dir / "study").string(), c.cache = (dir / "cache").string();
  c.threads = 2, c.images = false, c.progress = false;
  runSweep(c);
  std::map<std::string, std::pair<double, double>> err;  // sampler -> (mse_target, se)
  for (const std::string& line : readCsvLines(csvPath(c))) {
    const auto f = splitCsvLine(line);
    if (f[csvColumn("filter")] == "box" && f[csvColumn("reconstruction")] == "weighted")
      err[f[csvColumn("sampler")]] = {std::stod(f[csvColumn("mse_target")]), std::stod(f[csvColumn("mse_target_se")])};
  }
  const auto [b, bse] = err.at("jittered");
  for (const std::string name : {"adaptive-contrast:jittered", "adaptive-error:jittered"}) {
    const auto [a, ase] = err.at(name);
    if (name == "adaptive-error:jittered") {  // it moves samples here (by each pixel's spread): reported, not held
      std::printf("siemens 48 px 16 spp: %s %.4g +- %.2g, %.3fx jittered\n", name.c_str(), a, ase, a / b);
      continue;
    }
    const double z = (a - b) / std::hypot(ase, bse);
    std::printf("siemens 48 px 16 spp: %s %.4g +- %.2g against jittered %.4g +- %.2g: %.3fx (z = %.1f)\n",
                name.c_str(), a, ase, b, bse, a / b, z);
    EXPECT_LT(z, 2) << name;
  }
}

}  // namespace
}  // namespace aliaslab
