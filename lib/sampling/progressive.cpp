// makeProgressiveSampler and progressive jittered (sampling/progressive.h).
//
// | property   | value (pj, progressive jittered)                           |
// |------------|------------------------------------------------------------|
// | points     | point 0 uniform in [0,1)^2; for n = 1, 4, 16, ...: with    |
// |            | cells of side 1/s (s^2 = n) holding one point each and     |
// |            | sub-quadrants of side 1/(2s): point n + i in the sub-      |
// |            | quadrant of point i's cell diagonally opposite point i's,  |
// |            | point 2n + i in one of the two others (x or y neighbour,   |
// |            | at random), point 3n + i in the last one; each uniform in  |
// |            | its sub-quadrant                                           |
// | randomness | point t: (u, v) = the halves of hash(pixelSeed, t), the    |
// |            | neighbour's side from hash(pixelSeed, t, 1): point t never |
// |            | depends on the count, so every prefix is the same          |
// | structure  | at 4^k points one point per cell of the 2^k grid, uniform  |
// |            | in it and independent of the others: jittered's           |
// |            | distribution exactly                                      |
// | use it     | as the progressive form of jittered for the adaptive       |
// |            | methods; not a registered sampler                          |
#include "sampling/progressive.h"

#include <cmath>

#include "core/hash.h"
#include "sampling/sample_math.h"

namespace aliaslab {

namespace {

class ProgressiveJitteredSampler final : public Sampler {
 public:
  using Sampler::Sampler;
  void generate(int px, int py, Vec2* out) const override { generatePrefix(px, py, spp(), out); }
  void generatePrefix(int px, int py, int count, Vec2* out) const override {
    if (count <= 0) return;
    const uint64_t key = pixelSeed(seed(), px, py);
    out[0] = uniformIn(key, 0, 0, 0, 1);
    for (int n = 1, side = 1; n < count; n *= 4, side *= 2) {
      const int fine = 2 * side;  // sub-quadrants of the current cells
      for (int i = 0; i < n && n + i < count; ++i) {
        const auto [cx, cy] = cellOf(out[i], fine);
        out[n + i] = uniformIn(key, n + i, cx ^ 1, cy ^ 1, fine);  // diagonally opposite point i's
      }
      for (int i = 0; i < n && 2 * n + i < count; ++i) {
        const auto [cx, cy] = cellOf(out[i], fine);
        const bool flipX = hashWords(key, static_cast<uint64_t>(2 * n + i), 1) & 1;
        const int ax = flipX ? cx ^ 1 : cx, ay = flipX ? cy : cy ^ 1;
        out[2 * n + i] = uniformIn(key, 2 * n + i, ax, ay, fine);
        if (3 * n + i < count) out[3 * n + i] = uniformIn(key, 3 * n + i, ax ^ 1, ay ^ 1, fine);
      }
      // (points 3n + i need every point 2n + i first: with count inside [3n, 4n) the loop above places them in
      // the order i, which is the order of their indices within each block, as a longer count would)
    }
  }
  std::string name() const override { return "pj"; }
  std::string describe() const override { return "progressive jittered, " + std::to_string(spp()) + " points"; }
  bool progressive() const override { return true; }
  double varianceBound() const override {  // at 4^k: jittered's distribution
    int n = spp();
    while (n % 4 == 0) n /= 4;
    return n == 1 ? 1.0 : 0.0;
  }

 private:
  static std::pair<int, int> cellOf(const Vec2& p, int res) {
    return {static_cast<int>(std::floor(double(p.x()) * res)), static_cast<int>(std::floor(double(p.y()) * res))};
  }
  static Vec2 uniformIn(uint64_t key, int t, int cx, int cy, int res) {
    const uint64_t h = hashWords(key, static_cast<uint64_t>(t));
    return Vec2(sampling::stratumPoint(cx, sampling::fixedToUnit(static_cast<uint32_t>(h >> 32)), res),
                sampling::stratumPoint(cy, sampling::fixedToUnit(static_cast<uint32_t>(h)), res));
  }
};

}  // namespace

std::unique_ptr<Sampler> makeProgressiveSampler(const std::string& base, int count, uint64_t seed) {
  auto s = makeSampler(base, count, seed);  // checks the name and the count
  if (s->progressive()) return s;
  if (base == "jittered") return std::make_unique<ProgressiveJitteredSampler>(count, seed);
  return nullptr;
}

}  // namespace aliaslab
