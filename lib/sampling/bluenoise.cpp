// bluenoise: best-candidate blue noise (Mitchell 1991) on the torus.
//
// | property   | value                                                      |
// |------------|------------------------------------------------------------|
// | points     | a best-candidate set: point i is, among 1 + min(10 i, 256)  |
// |            | uniform candidates, the one farthest (toroidal distance)   |
// |            | from points 0 .. i-1; no two points are close, no grid     |
// |            | structure, energy low at low frequencies                   |
// | per pixel  | a pool of 16 sets per seed built by the constructor (a     |
// |            | toroidal grid makes each nearest search O(1)); pixel p     |
// |            | uses set hash(p) mod 16 shifted toroidally by a uniform    |
// |            | offset from hash(seed, p) (32-bit fixed-point add with     |
// |            | wrap-around, so the shift keeps the toroidal distances)    |
// | counts     | any 1 <= spp <= 4096, no warning; more is refused          |
// |            | (OptionError): the 16 sets cost about 0.7 ms per point to  |
// |            | build. The candidate count is capped at 257, so large sets |
// |            | are slightly less even than the pure Mitchell rule         |
// | use it     | when the look of the noise matters (blue noise hides in    |
// |            | high frequencies); no stratification guarantee.            |
#include <cmath>
#include <vector>

#include "core/error.h"
#include "core/hash.h"
#include "sampling/sample_math.h"
#include "sampling/sampler_registry.h"

namespace aliaslab::sampling {
namespace {

constexpr int kPoolSize = 16;
constexpr int kCandidatesPerPoint = 10;
constexpr int kMaxCandidates = 256;
constexpr int kMaxSpp = 4096;

struct Point32 {
  uint32_t x, y;
};

/// Squared toroidal distance in units of the unit square (wrapped differences).
inline double torusDist2(Point32 a, Point32 b) {
  const double dx = static_cast<int32_t>(a.x - b.x) * 0x1p-32, dy = static_cast<int32_t>(a.y - b.y) * 0x1p-32;
  return dx * dx + dy * dy;
}

/// Mitchell's best-candidate set of `count` points, nearest searches on a g x g toroidal grid.
std::vector<Point32> bestCandidateSet(int count, uint64_t key) {
  HashRng rng(key);
  const int g = std::max(1, static_cast<int>(std::sqrt(count / 2.0)));
  std::vector<std::vector<int>> grid(static_cast<size_t>(g) * g);
  std::vector<Point32> points;
  points.reserve(count);
  const auto cellOf = [g](uint32_t v) { return static_cast<int>((static_cast<uint64_t>(v) * g) >> 32); };
  // Distance to the nearest placed point: rings of cells until no closer point can exist.
  const auto nearest2 = [&](Point32 c) {
    double best = 4.0;
    // Few points: the grid is mostly empty, a plain scan is cheaper.
    if (points.size() * points.size() <= static_cast<size_t>(count)) {
      for (const Point32& p : points) best = std::min(best, torusDist2(c, p));
      return best;
    }
    const int cx = cellOf(c.x), cy = cellOf(c.y);
    const auto wrap = [g](int v) { return v < 0 ? v + g : (v >= g ? v - g : v); };
    for (int r = 0; r <= g / 2 + 1; ++r) {
      for (int dy = -r; dy <= r; ++dy) {
        const int gy = wrap(cy + dy);
        const int step = (r == 0 || dy == -r || dy == r) ? 1 : 2 * r;  // inner rows: the two ends only
        for (int dx = -r; dx <= r; dx += step)
          for (int k : grid[static_cast<size_t>(gy) * g + wrap(cx + dx)]) best = std::min(best, torusDist2(c, points[k]));
      }
      const double reach = static_cast<double>(r) / g;  // every unvisited point is at least this far
      if (best <= reach * reach) break;
    }
    return best;
  };
  for (int i = 0; i < count; ++i) {
    Point32 chosen{rng.nextU32(), rng.nextU32()};
    if (i > 0) {
      double bestDist = nearest2(chosen);
      const int candidates = 1 + std::min(kCandidatesPerPoint * i, kMaxCandidates);
      for (int c = 1; c < candidates; ++c) {
        const Point32 cand{rng.nextU32(), rng.nextU32()};
        const double d = nearest2(cand);
        if (d > bestDist) bestDist = d, chosen = cand;
      }
    }
    grid[static_cast<size_t>(cellOf(chosen.y)) * g + cellOf(chosen.x)].push_back(i);
    points.push_back(chosen);
  }
  return points;
}

class BlueNoiseSampler final : public Sampler {
 public:
  BlueNoiseSampler(int spp, uint64_t seed) : Sampler(spp, seed) {
    for (int s = 0; s < kPoolSize; ++s) pool_.push_back(bestCandidateSet(spp, hashWords(seed, 0x626c7565ULL, s)));
  }

  void generate(int px, int py, Vec2* out) const override {
    const uint64_t key = pixelSeed(seed(), px, py);
    const uint64_t h = hashWords(key, 0x7368696674ULL);
    const std::vector<Point32>& set = pool_[hashWords(key, 0x706f6f6cULL) % kPoolSize];
    const uint32_t sx = key32(h), sy = static_cast<uint32_t>(h);
    for (int i = 0; i < spp(); ++i) out[i] = Vec2(fixedToUnit(set[i].x + sx), fixedToUnit(set[i].y + sy));
  }
  std::string name() const override { return "bluenoise"; }
  std::string describe() const override {
    return "bluenoise best-candidate " + std::to_string(spp()) + " points, pool of 16 toroidally shifted per pixel";
  }

 private:
  std::vector<std::vector<Point32>> pool_;
};

}  // namespace

std::unique_ptr<Sampler> makeBlueNoiseSampler(int spp, uint64_t seed) {
  if (spp > kMaxSpp)
    throw OptionError("spp", "bluenoise supports at most " + std::to_string(kMaxSpp) +
                                   " samples per pixel (its best-candidate sets grow slowly), got " +
                                   std::to_string(spp) + "; use sobol or pmj02 for more");
  return std::make_unique<BlueNoiseSampler>(spp, seed);
}

}  // namespace aliaslab::sampling
