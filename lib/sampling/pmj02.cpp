// pmj02: progressive multi-jittered (0,2) sequence (Christensen, Kensler and
// Kilpatrick 2018), built with Pharr's (2019) search for free strata.
//
// | property   | value                                                      |
// |------------|------------------------------------------------------------|
// | points     | the first spp points of a pmj02 sequence: every prefix of  |
// |            | 2^j points is a (0,j,2)-net in base 2 (each elementary     |
// |            | interval of area 2^-j holds exactly one point)             |
// | method     | construction (per sequence, 32-bit fixed point): the point |
// |            | 0 is uniform; for n = 1, 4, 16, ...: points n..2n-1 go in  |
// |            | the sub-quadrant diagonally opposite point i - n, points   |
// |            | 2n..3n-1 in the sub-quadrant beside point i - 2n (x or y   |
// |            | neighbour at random), points 3n..4n-1 diagonally opposite  |
// |            | those; inside its sub-quadrant each point takes a random   |
// |            | x and y stratum of width 1/(current count) among those     |
// |            | whose every elementary interval is still empty (Pharr's    |
// |            | recursive search), then uniform within it                  |
// | per pixel  | a pool of 16 sequences per seed, built once by the         |
// |            | constructor; pixel p uses sequence hash(p) mod 16 with x   |
// |            | and y XORed by two 32-bit masks from hash(seed, p). XOR of |
// |            | the binary digits maps every elementary interval onto one  |
// |            | of the same shape, so the (0,2) property of every prefix   |
// |            | is kept while each point becomes uniform on [0,1)^2        |
// | counts     | any 1 <= spp <= 65536: the first spp points; warning()     |
// |            | says the net property holds only at powers of two; larger |
// |            | spp is refused (OptionError): the strata tables grow as    |
// |            | spp log spp per sequence                                   |
// | progressive| yes: the pool's sequences are built point by point, so the |
// |            | first n points are the same at every count >= n            |
// | use it     | like sobol, with less structure across the pixel grid      |
// |            | between pool members; construction costs about a second at |
// |            | the largest spp.                                          |
#include <stdexcept>
#include <vector>

#include "core/error.h"
#include "core/hash.h"
#include "sampling/sample_math.h"
#include "sampling/sampler_registry.h"

namespace aliaslab::sampling {
namespace {

constexpr int kPoolSize = 16;
constexpr int kMaxSpp = 1 << 16;

struct Point32 {
  uint32_t x, y;
};

/// The top `bits` bits of v (0 when bits == 0).
constexpr uint32_t top(uint32_t v, int bits) { return bits == 0 ? 0 : v >> (32 - bits); }

/// Builds one pmj02 sequence of `count` points; returns false in the (not
/// observed) case that a sub-quadrant has no free stratum.
class Pmj02Builder {
 public:
  Pmj02Builder(int count, uint64_t key) : count_(count), rng_(key) { points_.reserve(count); }

  bool build() {
    points_.push_back({rng_.nextU32(), rng_.nextU32()});
    for (int n = 1; n < count_; n *= 4) {
      // Odd level: 2n points, cells of a 2^a x 2^a grid with a = (level + 1) / 2.
      subdivide();
      int a = (level_ + 1) / 2;
      for (int i = 0; i < n && n + i < count_; ++i)
        if (!add(top(points_[i].x, a) ^ 1, top(points_[i].y, a) ^ 1, a)) return false;
      if (2 * n >= count_) break;
      // Even level: 4n points, sub-quadrants of a 2^a x 2^a grid with a = level / 2.
      subdivide();
      a = level_ / 2;
      std::vector<Point32> cells(n);
      for (int i = 0; i < n && 2 * n + i < count_; ++i) {
        const uint32_t cx = top(points_[i].x, a), cy = top(points_[i].y, a);
        const bool flipX = rng_.nextU32() & 1;
        cells[i] = flipX ? Point32{cx ^ 1, cy} : Point32{cx, cy ^ 1};
        if (!add(cells[i].x, cells[i].y, a)) {
          cells[i] = flipX ? Point32{cx, cy ^ 1} : Point32{cx ^ 1, cy};
          if (!add(cells[i].x, cells[i].y, a)) return false;
        }
      }
      for (int i = 0; i < n && 3 * n + i < count_; ++i)
        if (!add(cells[i].x ^ 1, cells[i].y ^ 1, a)) return false;
    }
    return true;
  }
  const std::vector<Point32>& points() const { return points_; }

 private:
  // Strata of shape j: 2^(level - j) columns x 2^j rows.
  bool occupied(int j, uint32_t xi, uint32_t yi) const { return strata_[j][(yi << (level_ - j)) + xi]; }
  void mark(const Point32& p) {
    for (int j = 0; j <= level_; ++j) strata_[j][(top(p.y, j) << (level_ - j)) + top(p.x, level_ - j)] = 1;
  }
  void subdivide() {
    ++level_;
    strata_.assign(level_ + 1, std::vector<uint8_t>(size_t{1} << level_, 0));
    for (const Point32& p : points_) mark(p);
  }
  // Free x strata (width 2^-level) below stratum (xi, yi) of shape j, descending to finer x.
  void freeX(int j, uint32_t xi, uint32_t yi, std::vector<uint32_t>& out) const {
    if (occupied(j, xi, yi)) return;
    if (j == 0) return out.push_back(xi);
    freeX(j - 1, 2 * xi, yi >> 1, out);
    freeX(j - 1, 2 * xi + 1, yi >> 1, out);
  }
  void freeY(int j, uint32_t xi, uint32_t yi, std::vector<uint32_t>& out) const {
    if (occupied(j, xi, yi)) return;
    if (j == level_) return out.push_back(yi);
    freeY(j + 1, xi >> 1, 2 * yi, out);
    freeY(j + 1, xi >> 1, 2 * yi + 1, out);
  }
  // Adds a point in cell (cx, cy) of the 2^a x 2^a grid (2a >= level).
  bool add(uint32_t cx, uint32_t cy, int a) {
    const int b = level_ - a;  // rows of the shape with a columns
    xs_.clear(), ys_.clear();
    freeX(b, cx, cy >> (a - b), xs_);
    freeY(a, cx >> (a - b), cy, ys_);
    if (xs_.empty() || ys_.empty()) return false;
    const uint32_t sx = xs_[rng_.nextBelow(static_cast<uint32_t>(xs_.size()))];
    const uint32_t sy = ys_[rng_.nextBelow(static_cast<uint32_t>(ys_.size()))];
    const uint32_t lowMask = level_ == 32 ? 0 : 0xffffffffu >> level_;
    const Point32 p{(level_ == 0 ? 0 : sx << (32 - level_)) | (rng_.nextU32() & lowMask),
                    (level_ == 0 ? 0 : sy << (32 - level_)) | (rng_.nextU32() & lowMask)};
    points_.push_back(p);
    mark(p);
    return true;
  }

  int count_;
  HashRng rng_;
  int level_ = 0;  ///< strata have 2^level cells
  std::vector<Point32> points_;
  std::vector<std::vector<uint8_t>> strata_;
  std::vector<uint32_t> xs_, ys_;
};

class Pmj02Sampler final : public Sampler {
 public:
  Pmj02Sampler(int spp, uint64_t seed) : Sampler(spp, seed) {
    pool_.reserve(kPoolSize);
    for (int s = 0; s < kPoolSize; ++s) {
      for (int attempt = 0;; ++attempt) {
        Pmj02Builder builder(spp, hashWords(seed, 0x706d6a3032ULL, s, attempt));
        if (builder.build()) {
          pool_.push_back(builder.points());
          break;
        }
        if (attempt == 8) throw std::logic_error("pmj02: no free stratum after 8 attempts");
      }
    }
  }

  void generate(int px, int py, Vec2* out) const override { generatePrefix(px, py, spp(), out); }
  void generatePrefix(int px, int py, int count, Vec2* out) const override {
    const uint64_t key = pixelSeed(seed(), px, py);
    const uint64_t h = hashWords(key, 0x786f72ULL);
    const std::vector<Point32>& seq = pool_[hashWords(key, 0x706f6f6cULL) % kPoolSize];
    const uint32_t maskX = key32(h), maskY = static_cast<uint32_t>(h);
    for (int i = 0; i < count; ++i) out[i] = Vec2(fixedToUnit(seq[i].x ^ maskX), fixedToUnit(seq[i].y ^ maskY));
  }
  std::string name() const override { return "pmj02"; }
  bool progressive() const override { return true; }
  std::string describe() const override {
    return "pmj02 first " + std::to_string(spp()) + " points, pool of 16 XOR-scrambled per pixel" +
           ((spp() & (spp() - 1)) ? " (not a power of two)" : "");
  }
  std::string warning() const override {
    if ((spp() & (spp() - 1)) == 0) return {};
    return "pmj02: spp " + std::to_string(spp()) +
           " is not a power of two; using the first spp points, the (0,2)-net property holds only at powers of two";
  }

 private:
  std::vector<std::vector<Point32>> pool_;
};

}  // namespace

std::unique_ptr<Sampler> makePmj02Sampler(int spp, uint64_t seed) {
  if (spp > kMaxSpp)
    throw OptionError("spp", "pmj02 supports at most " + std::to_string(kMaxSpp) + " samples per pixel, got " +
                                   std::to_string(spp));
  return std::make_unique<Pmj02Sampler>(spp, seed);
}

}  // namespace aliaslab::sampling
