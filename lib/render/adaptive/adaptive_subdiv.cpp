// Adaptive subdivision (Whitted 1980) with fresh leaf samples; see adaptive.h and docs/adaptive.md ("Bias").
//
// Every cell c of a pixel's quadtree is estimated as V_c = alpha_c mean(D_c) + (1 - alpha_c) X_c: D_c its 4
// decision samples, X_c the mean of its 4 children's V if it was split, else the mean of its fresh samples F_c
// (at least one in a pixel, four in a cell below it, drawn after every decision). alpha_c is fixed when the cell is made (4 / spp for the pixel,
// 1/2 below), so each sample's weight (its share of the pixel's V) is known before it is traced, and
// E[V_c] = the cell's mean whatever the decisions: the decision to split reads D_c (and the samples of its
// ancestors inside it), and only changes how X_c is formed, from samples not yet drawn.
#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>

#include "render/adaptive/adaptive_work.h"

namespace aliaslab::adaptiveimpl {

namespace {

/// One cell of a pixel's quadtree (24 bytes: the levels' lists are copied and walked often). Its decision
/// samples are 4, each of weight mass * alpha / 4; alpha follows from the level (alphaOf).
struct Cell {
  double mass;  ///< share of the pixel's estimate that V_c carries
  int p;        ///< pixel
  int level, cx, cy;
};

constexpr int kChildFresh = 4;  ///< fresh samples a cell below the pixel keeps if it stays a leaf

/// Fresh samples a leaf keeps at least: one for a pixel, kChildFresh below.
int keep(const Cell& c) { return c.level == 0 ? 1 : kChildFresh; }

/// The bounds of cell c, [x0, x1) x [y0, y1), compared against a sample's float position: in float when every
/// bound is a float (the comparison then gives the same answers as in double, float to double being exact), in
/// double otherwise (films wider than 2^(24 - level) pixels).
struct Bounds {
  double x0, x1, y0, y1;
  float fx0, fx1, fy0, fy1;
  bool exact;
  Bounds() = default;
  Bounds(const Work& w, const Cell& c) : Bounds(c.p % w.width(), c.p / w.width(), c) {}
  Bounds(int i, int j, const Cell& c) {  // (i, j): c's pixel
    const double side = cellSide(c.level);
    x0 = static_cast<double>(i) + c.cx * side, y0 = static_cast<double>(j) + c.cy * side;
    x1 = x0 + side, y1 = y0 + side;
    fx0 = static_cast<float>(x0), fx1 = static_cast<float>(x1);
    fy0 = static_cast<float>(y0), fy1 = static_cast<float>(y1);
    exact = fx0 == x0 && fx1 == x1 && fy0 == y0 && fy1 == y1;
  }
};

/// Max over channels of (max - min) of pixel p's finite samples for which inside(s) holds (0 with fewer than 2).
template <class Inside>
double spreadWhere(const Work& w, long long p, Inside inside) {
  Color lo = Color::Constant(INFINITY), hi = Color::Constant(-INFINITY);
  int in = 0;
  w.forSamples(p, [&](const FilmSample& s) {
    if (s.L.allFinite() && inside(s)) lo = lo.min(s.L), hi = hi.max(s.L), ++in;
  });
  return in >= 2 ? static_cast<double>((hi - lo).maxCoeff()) : 0.0;
}

/// The spread of the samples inside cell c.
double spreadIn(const Work& w, const Cell& c) {
  const Bounds b(w, c);
  if (b.exact) return spreadWhere(w, c.p, [&](const FilmSample& s) {
    return s.x >= b.fx0 && s.x < b.fx1 && s.y >= b.fy0 && s.y < b.fy1;
  });
  return spreadWhere(w, c.p, [&](const FilmSample& s) {
    return s.x >= b.x0 && s.x < b.x1 && s.y >= b.y0 && s.y < b.y1;
  });
}

/// The same for the 4 children q[0 .. 4) of one split cell, side by side (q[k] at 2 cx + (k & 1), 2 cy + (k >> 1)),
/// into diff[0 .. 4), in one pass over the pixel's samples: a sample inside the parent is placed by comparing it
/// with the midlines, which are the children's shared bounds (q[0]'s upper, q[3]'s lower), so each sample lands in
/// the child whose own bounds hold it, as testing the four would give.
void spreadInQuadrants(const Work& w, const Cell* q, double* diff) {
  const int i = q[0].p % w.width(), j = q[0].p / w.width();
  const Bounds a(i, j, q[0]), b(i, j, q[3]);  // a = [x0, xm) x [y0, ym), b = [xm, x1) x [ym, y1)
  Color lo[4], hi[4];
  int in[4] = {0, 0, 0, 0};
  for (int k = 0; k < 4; ++k) lo[k] = Color::Constant(INFINITY), hi[k] = Color::Constant(-INFINITY);
  const auto add = [&](int k, const Color& L) { lo[k] = lo[k].min(L), hi[k] = hi[k].max(L), ++in[k]; };
  if (a.exact && b.exact)  // every bound of the four children is one of these (see Bounds)
    w.forSamples(q[0].p, [&](const FilmSample& s) {
      if (s.L.allFinite() && s.x >= a.fx0 && s.x < b.fx1 && s.y >= a.fy0 && s.y < b.fy1)
        add((s.x >= b.fx0) + 2 * (s.y >= b.fy0), s.L);
    });
  else
    w.forSamples(q[0].p, [&](const FilmSample& s) {
      if (s.L.allFinite() && s.x >= a.x0 && s.x < b.x1 && s.y >= a.y0 && s.y < b.y1)
        add((s.x >= b.x0) + 2 * (s.y >= b.y0), s.L);
    });
  for (int k = 0; k < 4; ++k) diff[k] = in[k] >= 2 ? static_cast<double>((hi[k] - lo[k]).maxCoeff()) : 0.0;
}

/// A split candidate: the sort key and where the cell is in its level.
struct Key {
  uint64_t diff;  ///< the bits of a difference > threshold > 0: positive doubles order as their bits
  uint64_t hash;
  uint32_t k;
};

/// "x before y": largest difference first; equal ones in the pixel-hash order (no bias towards the first rows),
/// then in the level's order. A strict order, so any sort gives the order a stable sort by (difference, hash) would.
bool before(const Key& x, const Key& y) {
  if (x.diff != y.diff) return x.diff > y.diff;
  return x.hash != y.hash ? x.hash < y.hash : x.k < y.k;
}

/// Sorts keys (listed in k order) by before(). The differences often take a few values (flat colours: 1 or 2 on
/// fence and checker_horizon), the hashes are uniform: then by a counting sort into buckets of (difference, top
/// bits of the hash), stable, so k order holds within each, and an insertion sort of each bucket by hash (about
/// one key per bucket); else by std::sort. `count`: scratch.
void sortKeys(std::vector<Key>& keys, std::vector<Key>& scratch, std::vector<uint32_t>& count) {
  constexpr size_t kFewDiffs = 8;
  std::vector<uint64_t> diffs;
  for (size_t i = 0; i < keys.size() && diffs.size() <= kFewDiffs; ++i)
    if (std::find(diffs.begin(), diffs.end(), keys[i].diff) == diffs.end()) diffs.push_back(keys[i].diff);
  if (diffs.size() > kFewDiffs || keys.size() < 64) return std::sort(keys.begin(), keys.end(), before);
  std::sort(diffs.begin(), diffs.end(), std::greater<>());
  const int bits = std::bit_width(keys.size());  // about one key per bucket of each difference
  const auto bucket = [&](const Key& key) {
    const size_t d = static_cast<size_t>(std::find(diffs.begin(), diffs.end(), key.diff) - diffs.begin());
    return (d << bits) + static_cast<size_t>(key.hash >> (64 - bits));
  };
  count.assign((diffs.size() << bits) + 1, 0);
  for (const Key& key : keys) ++count[bucket(key) + 1];
  for (size_t b = 1; b < count.size(); ++b) count[b] += count[b - 1];
  scratch.resize(keys.size());
  for (const Key& key : keys) scratch[count[bucket(key)]++] = key;  // count[b] ends at bucket b + 1's start
  for (size_t b = 0, from = 0; b + 1 < count.size(); from = count[b++])
    for (size_t i = from + 1; i < count[b]; ++i)  // within the bucket: same difference, k ascending
      for (size_t j = i; j > from && scratch[j].hash < scratch[j - 1].hash; --j) std::swap(scratch[j], scratch[j - 1]);
  std::swap(keys, scratch);
}

/// The difference of each cell of `level` (level d of 0..depth; 0 at the last): the spread of its samples, each
/// pixel's at level 0, below it the 4 children of each split cell in one pass. byPixel, order: scratch.
void levelDifferences(const Work& w, const std::vector<Cell>& level, int d, int depth, std::vector<double>& diff,
                      std::vector<uint32_t>& byPixel, std::vector<uint32_t>& order) {
  diff.assign(level.size(), 0.0);
  if (d == 0 && d < depth) {
    // a pixel's cell holds every sample of the pixel (Work clamps each position inside its pixel, whose bounds
    // are floats on films narrower than 2^24 pixels): nothing to test there
    const bool whole = w.width() < (1 << 24) && w.pixels() / w.width() < (1 << 24);
    for (size_t k = 0; k < level.size(); ++k)
      diff[k] = whole ? spreadWhere(w, level[k].p, [](const FilmSample&) { return true; }) : spreadIn(w, level[k]);
  } else if (d < depth) {
    // below the pixel the level is made of the 4 children of each split cell, side by side, in the order of
    // the splits; visited in pixel order (counting sort), the 4 in one pass over the pixel's samples, so a
    // pixel's samples are read while in cache, not once per cell in the order of the splits
    const size_t groups = level.size() / 4;
    byPixel.assign(static_cast<size_t>(w.pixels()) + 1, 0);
    order.resize(groups);
    for (size_t g = 0; g < groups; ++g) ++byPixel[static_cast<size_t>(level[4 * g].p) + 1];
    for (long long p = 0; p < w.pixels(); ++p) byPixel[p + 1] += byPixel[p];
    for (size_t g = 0; g < groups; ++g) order[byPixel[level[4 * g].p]++] = static_cast<uint32_t>(g);
    for (uint32_t g : order) spreadInQuadrants(w, &level[4 * size_t(g)], &diff[4 * size_t(g)]);
  }
}

/// The fresh samples of each leaf: what every leaf keeps, and what is left of `free` in proportion to the share
/// each leaf's fresh mean carries (largest remainders; ties in the order of the leaves), never past the budget.
std::vector<int> freshCounts(const std::vector<Cell>& leaves, long long free, double alpha0, double alphaBelow) {
  const auto alphaOf = [&](const Cell& c) { return c.level == 0 ? alpha0 : alphaBelow; };
  double total = 0;
  for (const Cell& c : leaves) total += c.mass * (1 - alphaOf(c));
  std::vector<int> n(leaves.size());
  for (size_t k = 0; k < leaves.size(); ++k) n[k] = keep(leaves[k]);
  std::vector<double> rest(leaves.size());
  long long given = 0;
  for (size_t k = 0; k < leaves.size(); ++k) {
    const double share = static_cast<double>(free) * leaves[k].mass * (1 - alphaOf(leaves[k])) / total;
    const long long whole = static_cast<long long>(std::floor(share));
    n[k] += static_cast<int>(whole), given += whole;
    rest[k] = share - static_cast<double>(whole);
  }
  // one more to each of the (free - given) largest remainders, ties to the earlier leaf (a strict order, so the
  // set is unique): value by value, largest first, each value's leaves in leaf order. A cell's mass, so its share
  // and remainder, follows from its level: at most depth + 1 values, each a pass over the leaves.
  long long more = std::clamp<long long>(free - given, 0, static_cast<long long>(leaves.size()));
  std::vector<double> values;
  for (double r : rest)
    if (std::find(values.begin(), values.end(), r) == values.end()) values.push_back(r);
  std::sort(values.begin(), values.end(), std::greater<>());
  for (size_t v = 0; more > 0 && v < values.size(); ++v)
    for (size_t k = 0; more > 0 && k < leaves.size(); ++k)
      if (rest[k] == values[v]) ++n[k], ++given, --more;
  for (size_t k = 0; given > free && k < n.size(); ++k)  // rounding of the shares: never past the budget
    if (n[k] > keep(leaves[k])) --n[k], --given;
  return n;
}

}  // namespace

void runSubdivision(Work& w, const AdaptiveSampler& a) {
  const int spp = a.spp();
  if (spp < 5) {  // no room for 4 decision samples and a fresh one: the base sampler, nothing decided
    w.tracePixels(std::vector<int>(w.pixels(), spp), std::vector<double>(w.pixels(), 1.0), true);
    return;
  }
  const double alpha0 = 4.0 / spp, alphaBelow = 0.25;
  const auto alphaOf = [&](const Cell& c) { return c.level == 0 ? alpha0 : alphaBelow; };
  const int depth = a.params().depth;
  const double threshold = a.params().threshold;
  std::vector<Cell> leaves, level, next;
  std::vector<double> diff;
  std::vector<uint32_t> byPixel, order;
  std::vector<Key> split, scratch;
  std::vector<uint32_t> buckets;
  std::vector<std::pair<long long, Request>> requests;
  w.tracePixels(std::vector<int>(w.pixels(), 4), std::vector<double>(w.pixels(), alpha0));
  long long free = w.left() - w.pixels();  // beyond the fresh samples every leaf keeps
  // a split costs at least 16 + 4 * kChildFresh - kChildFresh samples of `free`, and adds 3 leaves
  const size_t splitsAtMost = static_cast<size_t>(free / (16 + 3 * kChildFresh));
  leaves.reserve(static_cast<size_t>(w.pixels()) + 3 * splitsAtMost);
  level.resize(static_cast<size_t>(w.pixels()));
  for (long long p = 0; p < w.pixels(); ++p) level[p] = {1.0, static_cast<int>(p), 0, 0, 0};
  for (int d = 0; d <= depth && !level.empty(); ++d) {
    levelDifferences(w, level, d, depth, diff, byPixel, order);
    // a pixel also splits when a neighbour's samples differ: an edge missed by its own 4 is seen
    if (d == 0) diff = dilate(diff, w.width(), static_cast<int>(w.pixels() / w.width()));
    split.clear();
    for (size_t k = 0; k < level.size(); ++k)
      if (diff[k] > threshold)
        split.push_back({std::bit_cast<uint64_t>(diff[k]), w.hash(level[k].p), static_cast<uint32_t>(k)});
      else
        leaves.push_back(level[k]);
    sortKeys(split, scratch, buckets);
    // a split costs 16 decision samples and the fresh samples its children keep (4 each, matching their
    // alpha = 1/2: as many fresh as decision samples), less the parent's own
    requests.clear(), next.clear();
    requests.reserve(4 * split.size()), next.reserve(4 * split.size());
    for (const Key& key : split) {
      const Cell& c = level[key.k];
      const long long cost = 16 + 4 * kChildFresh - keep(c);
      if (free < cost) {
        leaves.push_back(c);
        continue;
      }
      free -= cost;
      const double mass = c.mass * (1 - alphaOf(c)) / 4;
      const float weight = static_cast<float>(mass * alphaBelow / 4);
      for (int k = 0; k < 4; ++k) {
        const Cell child{mass, c.p, c.level + 1, 2 * c.cx + (k & 1), 2 * c.cy + (k >> 1)};
        requests.push_back({c.p, {child.level, child.cx, child.cy, 4, weight}});
        next.push_back(child);
      }
    }
    if (!next.empty()) w.trace(requests);
    std::swap(level, next);
  }
  const std::vector<int> n = freshCounts(leaves, free, alpha0, alphaBelow);
  requests.clear();
  requests.reserve(leaves.size());
  for (size_t k = 0; k < leaves.size(); ++k) {
    const Cell& c = leaves[k];
    requests.push_back({c.p, {c.level, c.cx, c.cy, n[k], static_cast<float>(c.mass * (1 - alphaOf(c)) / n[k])}});
  }
  w.trace(requests, true);
}

}  // namespace aliaslab::adaptiveimpl
