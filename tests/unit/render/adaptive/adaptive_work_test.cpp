// The adaptive methods' shared state (render/adaptive/adaptive_work.h, private to render/): the rounds' layout and the
// 3 x 3 dilation the methods use, each against a plain computation of the same thing.
#include <gtest/gtest.h>

#include <cstring>
#include <random>

#include "accel/aggregate.h"
#include "aliaslab_paths.h"
#include "render/adaptive/adaptive_work.h"
#include "scene/scene.h"

namespace aliaslab::adaptiveimpl {
namespace {

// The separable dilation equals the 9-neighbour maximum (with 0) on every shape, borders included.
TEST(AdaptiveWork, DilateIsTheNeighbourhoodMaximum) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> value(0.0, 1.0);
  for (const auto& [W, H] : std::vector<std::pair<int, int>>{{1, 1}, {1, 6}, {6, 1}, {2, 2}, {7, 5}, {16, 9}}) {
    SCOPED_TRACE(std::to_string(W) + " x " + std::to_string(H));
    std::vector<double> v(size_t(W) * H);
    for (double& x : v) x = value(rng) < 0.3 ? 0.0 : value(rng);
    const std::vector<double> d = dilate(v, W, H);
    ASSERT_EQ(d.size(), v.size());
    for (int j = 0; j < H; ++j)
      for (int i = 0; i < W; ++i) {
        double m = 0;
        for (int y = j - 1; y <= j + 1; ++y)
          for (int x = i - 1; x <= i + 1; ++x)
            if (x >= 0 && x < W && y >= 0 && y < H) m = std::max(m, v[size_t(y) * W + x]);
        EXPECT_EQ(d[size_t(j) * W + i], m) << "pixel " << i << "," << j;
      }
  }
}

// A round's samples land by pixel whatever the order of its requests across pixels (each pixel's own order
// kept): requests in pixel order and the same requests with the pixels reversed give the same buffer, bit for bit.
TEST(AdaptiveWork, RequestsInAnyPixelOrderGiveTheSameSamples) {
  const Scene scene = parseScene(std::string(ALIASLAB_SOURCE_DIR) + "/scenes/controls/edge.txt");
  const auto aggregate = makeDefaultAggregate(*scene.root);
  const Tracer tracer(scene, *aggregate, TraceOptions{});
  const auto sampler = makeAdaptiveSampler("adaptive-subdiv:jittered", 8, 3);
  const int W = 9, H = 7;
  std::vector<std::pair<long long, Request>> ordered;
  for (long long p = 0; p < W * H; ++p) {
    ordered.push_back({p, {0, 0, 0, 3, 0.25f}});
    if (p % 3 == 0) {
      ordered.push_back({p, {1, static_cast<int>(p % 2), 1, 4, 0.125f}});
      ordered.push_back({p, {2, 3, 0, 1, 0.125f}});
    }
  }
  std::vector<std::pair<long long, Request>> reversed;
  for (long long p = W * H - 1; p >= 0; --p)
    for (const auto& r : ordered)
      if (r.first == p) reversed.push_back(r);
  const auto run = [&](const std::vector<std::pair<long long, Request>>& requests) {
    Work w(tracer, *sampler, W, H, 2, {});
    w.trace(requests);
    std::vector<std::pair<long long, Request>> rest;
    for (long long p = 0; p < W * H; ++p) rest.push_back({p, {0, 0, 0, 1, 0.5f}});
    w.trace(rest, true);
    return w.gather();
  };
  const SampleBuffer a = run(ordered), b = run(reversed);
  ASSERT_EQ(a.samples().size(), b.samples().size());
  ASSERT_EQ(a.samples().size(), size_t(W * H * 4 + (W * H + 2) / 3 * 5));
  for (size_t k = 0; k < a.samples().size(); ++k) {
    const FilmSample &x = a.samples()[k], &y = b.samples()[k];
    EXPECT_TRUE(x.x == y.x && x.y == y.y && x.weight == y.weight && (x.L == y.L).all()) << "sample " << k;
  }
  for (int j = 0; j < H; ++j)
    for (int i = 0; i < W; ++i) ASSERT_EQ(a.count(i, j), b.count(i, j));
}

}  // namespace
}  // namespace aliaslab::adaptiveimpl
