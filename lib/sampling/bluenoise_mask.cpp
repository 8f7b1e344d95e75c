// Void-and-cluster masks (see bluenoise_mask.h for the algorithm).
#include "sampling/bluenoise_mask.h"

#include <cmath>
#include <map>
#include <mutex>
#include <utility>

#include "core/hash.h"

namespace aliaslab::sampling {
namespace {

constexpr int kN = kMaskSize * kMaskSize;
constexpr double kSigma = 1.5;
constexpr size_t kCacheLimit = 256;  ///< masks kept; the cache is emptied when it would grow past this

/// kernel[dy * kMaskSize + dx]: the Gaussian of the toroidal distance of offset (dx, dy).
const std::vector<double>& kernel() {
  static const std::vector<double> k = [] {
    std::vector<double> v(kN);
    for (int dy = 0; dy < kMaskSize; ++dy)
      for (int dx = 0; dx < kMaskSize; ++dx) {
        const int wx = std::min(dx, kMaskSize - dx), wy = std::min(dy, kMaskSize - dy);
        v[dy * kMaskSize + dx] = std::exp(-(wx * wx + wy * wy) / (2 * kSigma * kSigma));
      }
    return v;
  }();
  return k;
}

struct Pattern {
  std::vector<char> set = std::vector<char>(kN, 0);
  std::vector<double> energy = std::vector<double>(kN, 0.0);

  void toggle(int p, double sign) {
    set[p] = sign > 0;
    const std::vector<double>& k = kernel();
    const int px = p % kMaskSize, py = p / kMaskSize;
    for (int y = 0; y < kMaskSize; ++y) {
      const int dy = (y - py) & (kMaskSize - 1);
      double* row = &energy[y * kMaskSize];
      const double* krow = &k[dy * kMaskSize];
      for (int x = 0; x < kMaskSize; ++x) row[x] += sign * krow[(x - px) & (kMaskSize - 1)];
    }
  }
  int tightestCluster() const {
    int best = -1;
    for (int p = 0; p < kN; ++p)
      if (set[p] && (best < 0 || energy[p] > energy[best])) best = p;
    return best;
  }
  int largestVoid() const {
    int best = -1;
    for (int p = 0; p < kN; ++p)
      if (!set[p] && (best < 0 || energy[p] < energy[best])) best = p;
    return best;
  }
};

}  // namespace

std::vector<uint16_t> makeVoidAndClusterMask(uint64_t key) {
  Pattern proto;
  HashRng rng(key);
  int ones = 0;
  while (ones < kN / 10) {
    const int p = static_cast<int>(rng.nextBelow(kN));
    if (!proto.set[p]) proto.toggle(p, +1), ++ones;
  }
  // 1. Relax the prototype: move the tightest cluster into the largest void until that undoes itself.
  for (int guard = 0; guard < 100 * kN; ++guard) {
    const int cluster = proto.tightestCluster();
    proto.toggle(cluster, -1);
    const int hole = proto.largestVoid();
    proto.toggle(hole, +1);
    if (hole == cluster) break;
  }
  std::vector<uint16_t> rank(kN);
  // 2. Ranks below the prototype's count: strip clusters.
  Pattern p = proto;
  for (int left = ones; left > 0; --left) {
    const int c = p.tightestCluster();
    p.toggle(c, -1);
    rank[c] = static_cast<uint16_t>(left - 1);
  }
  // 3. Ranks from the prototype's count up: fill voids.
  p = std::move(proto);
  for (int r = ones; r < kN; ++r) {
    const int v = p.largestVoid();
    p.toggle(v, +1);
    rank[v] = static_cast<uint16_t>(r);
  }
  return rank;
}

std::shared_ptr<const std::vector<uint16_t>> blueNoiseMask(uint64_t seed, int channel) {
  static std::mutex mutex;
  static std::map<std::pair<uint64_t, int>, std::shared_ptr<const std::vector<uint16_t>>> cache;
  const std::pair<uint64_t, int> id{seed, channel};
  {
    std::lock_guard<std::mutex> lock(mutex);
    if (auto it = cache.find(id); it != cache.end()) return it->second;
  }
  // Built outside the lock (two threads may build the same mask; both get equal values).
  auto mask = std::make_shared<const std::vector<uint16_t>>(
      makeVoidAndClusterMask(hashWords(seed, 0x766f6964ULL, static_cast<uint64_t>(channel))));
  std::lock_guard<std::mutex> lock(mutex);
  if (cache.size() >= kCacheLimit) cache.clear();
  return cache.emplace(id, std::move(mask)).first->second;
}

}  // namespace aliaslab::sampling
