// The splat's runs path (filmimpl::SplatPath::Runs, the default) against the direct one (samples added in memory
// order, the definition): the same contributions summed in another order within each batch, so the weighted
// averages may differ only by double rounding. The stated tolerance (docs/science.md, "Reconstruction"): per
// pixel and channel |runs - direct| <= 1e-6 * max(|direct|, 1e-3 * mean |direct|) of the resolved image; the
// weight sums within 1e-12 of sum |w| per pixel. Checked on renders of five scenes (16 spp, sobol) for every
// registered filter at radii from 0.5 to 3.
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "aliaslab_paths.h"
#include "film/film.h"
#include "film/film_impl.h"
#include "render/render.h"
#include "sampling/sampler.h"
#include "study/study_scene.h"

namespace aliaslab {
namespace {

using filmimpl::SplatPath;

Image resolveImage(const SampleBuffer& b, const Filter& f, SplatPath path, std::vector<double>& sums) {
  const size_t n = 4 * static_cast<size_t>(b.width()) * b.height();
  sums.assign(n, 0.0);
  std::vector<double> plain(n, 0.0);
  const size_t skipped = filmimpl::addPlainSums(b, plain.data());
  filmimpl::splatWeighted(b, f, sums.data(), 1, true, path);
  return filmimpl::resolveSums(b.width(), b.height(), sums.data(), plain.data(), filmimpl::weightTolerance(f), skipped)
      .image;
}

/// The largest |runs - direct| / max(|direct|, floor) over pixels and channels.
double worstRelative(const Image& runs, const Image& direct) {
  double mean = 0;
  for (int j = 0; j < direct.height(); ++j)
    for (int i = 0; i < direct.width(); ++i) mean += direct.get(i, j).abs().sum();
  const double floor = std::max(1e-3 * mean / (3.0 * direct.width() * direct.height()), 1e-30);
  double worst = 0;
  for (int j = 0; j < direct.height(); ++j)
    for (int i = 0; i < direct.width(); ++i)
      for (int c = 0; c < 3; ++c) {
        const double d = direct.get(i, j)[c], r = runs.get(i, j)[c];
        worst = std::max(worst, std::abs(r - d) / std::max(std::abs(d), floor));
      }
  return worst;
}

TEST(SplatRuns, WithinToleranceOfDirectOnScenesForEveryFilter) {
  const std::string dir = std::string(ALIASLAB_SOURCE_DIR) + "/scenes/";
  int differing = 0, compared = 0;
  for (const char* name : {"zoneplate", "siemens", "fence", "checker_horizon", "sinc"}) {
    const auto scene = loadStudyScene(dir + name + ".txt", 0, 0, 0, 40);
    const SampleBuffer b = traceSamples(*scene->tracer, *makeSampler("sobol", 16, 11), scene->width, scene->height, 2);
    for (const std::string& filter : allFilterNames())
      for (float r : {0.5f, 1.f, 1.5f, 2.f, 2.3f, 3.f}) {
        const auto f = makeFilter(filter, r);
        std::vector<double> runsSums, directSums;
        const Image runs = resolveImage(b, *f, SplatPath::Runs, runsSums);
        const Image direct = resolveImage(b, *f, SplatPath::Direct, directSums);
        EXPECT_LE(worstRelative(runs, direct), 1e-6) << name << " " << f->describe();
        // the weight sums: the same terms in another order (|w| <= max |f| per term, so 1e-12 of the count bound)
        double worstWeight = 0;
        for (size_t p = 3; p < runsSums.size(); p += 4)
          worstWeight = std::max(worstWeight, std::abs(runsSums[p] - directSums[p]));
        EXPECT_LE(worstWeight, 1e-12 * 16 * (2 * r + 1) * (2 * r + 1) * std::max(1.f, std::abs(f->eval(0, 0))))
            << name << " " << f->describe();
        differing += runsSums != directSums, ++compared;
      }
  }
  // the runs path is taken (it sums in another order somewhere), else this test compares a path with itself
  EXPECT_GT(differing, 0) << "of " << compared;
}

TEST(SplatRuns, RunsAddTheSameContributionsAsDirect) {
  // Integer radiance and the box (weights 1): every sum is exact in any order, so the paths agree bit for bit;
  // a run kernel that dropped or repeated a sample would not.
  const int w = 37, h = 35, spp = 16;
  SampleBuffer b(w, h, spp);
  const auto sampler = makeSampler("sobol", spp, 5);
  std::vector<Vec2> u(spp);
  for (int j = 0; j < h; ++j)
    for (int i = 0; i < w; ++i) {
      sampler->generate(i, j, u.data());
      for (int k = 0; k < spp; ++k) {
        FilmSample& s = b.pixel(i, j)[k];
        s.x = i + u[k].x(), s.y = j + u[k].y(), s.L = Color(float(k), float(i % 7), float(j % 5));
      }
    }
  for (float r : {0.5f, 1.f, 1.5f, 2.f, 2.5f, 3.f, 4.f}) {
    const auto f = makeFilter("box", r);
    std::vector<double> runs(4 * w * h, 0.0), direct(runs);
    filmimpl::splatWeighted(b, *f, runs.data(), 1, true, SplatPath::Runs);
    filmimpl::splatWeighted(b, *f, direct.data(), 1, true, SplatPath::Direct);
    EXPECT_TRUE(runs == direct) << f->describe();
    double total = 0;
    for (size_t p = 3; p < runs.size(); p += 4) total += runs[p];
    EXPECT_GT(total, 0.0);
  }
}

}  // namespace
}  // namespace aliaslab
