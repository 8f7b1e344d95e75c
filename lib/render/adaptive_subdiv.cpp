// Adaptive subdivision (Whitted 1980) with fresh leaf samples; see adaptive.h and docs/adaptive.md ("Bias").
//
// Every cell c of a pixel's quadtree is estimated as V_c = alpha_c mean(D_c) + (1 - alpha_c) X_c: D_c its 4
// decision samples, X_c the mean of its 4 children's V if it was split, else the mean of its fresh samples F_c
// (at least one in a pixel, four in a cell below it, drawn after every decision). alpha_c is fixed when the cell is made (4 / spp for the pixel,
// 1/2 below), so each sample's weight (its share of the pixel's V) is known before it is traced, and
// E[V_c] = the cell's mean whatever the decisions: the decision to split reads D_c (and the samples of its
// ancestors inside it), and only changes how X_c is formed, from samples not yet drawn.
#include <algorithm>
#include <cmath>
#include <cstdint>

#include "render/adaptive_work.h"

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
  Bounds(const Work& w, const Cell& c) {
    const double side = cellSide(c.level);
    x0 = static_cast<double>(c.p % w.width()) + c.cx * side, y0 = static_cast<double>(c.p / w.width()) + c.cy * side;
    x1 = x0 + side, y1 = y0 + side;
    fx0 = static_cast<float>(x0), fx1 = static_cast<float>(x1);
    fy0 = static_cast<float>(y0), fy1 = static_cast<float>(y1);
    exact = fx0 == x0 && fx1 == x1 && fy0 == y0 && fy1 == y1;
  }
};

/// Max over channels of (max - min) of the pixel's samples inside each of the cells c[0 .. n), all of one pixel
/// (0 with fewer than 2), into diff[0 .. n): one pass over the pixel's samples for the n cells.
template <int n>
void spreadIn(const Work& w, const Cell* c, double* diff) {
  Bounds b[n] = {Bounds(w, c[0])};
  bool exact = b[0].exact;
  for (int k = 1; k < n; ++k) b[k] = Bounds(w, c[k]), exact = exact && b[k].exact;
  Color lo[n], hi[n];
  int in[n];
  for (int k = 0; k < n; ++k) lo[k] = Color::Constant(INFINITY), hi[k] = Color::Constant(-INFINITY), in[k] = 0;
  w.forSamples(c[0].p, [&](const FilmSample& s) {
    if (!s.L.allFinite()) return;
    for (int k = 0; k < n; ++k)
      if (exact ? s.x >= b[k].fx0 && s.x < b[k].fx1 && s.y >= b[k].fy0 && s.y < b[k].fy1
                : s.x >= b[k].x0 && s.x < b[k].x1 && s.y >= b[k].y0 && s.y < b[k].y1)
        lo[k] = lo[k].min(s.L), hi[k] = hi[k].max(s.L), ++in[k];
  });
  for (int k = 0; k < n; ++k) diff[k] = in[k] >= 2 ? static_cast<double>((hi[k] - lo[k]).maxCoeff()) : 0.0;
}

/// A split candidate: the sort key and where the cell is in its level.
struct Key {
  double diff;
  uint64_t hash;
  uint32_t k;
};

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
  std::vector<Key> split;
  std::vector<std::pair<long long, Request>> requests;
  leaves.reserve(static_cast<size_t>(w.pixels())), level.reserve(static_cast<size_t>(w.pixels()));
  for (long long p = 0; p < w.pixels(); ++p) level.push_back({1.0, static_cast<int>(p), 0, 0, 0});
  w.tracePixels(std::vector<int>(w.pixels(), 4), std::vector<double>(w.pixels(), alpha0));
  long long free = w.left() - w.pixels();  // beyond the fresh samples every leaf keeps
  for (int d = 0; d <= depth && !level.empty(); ++d) {
    diff.assign(level.size(), 0.0);
    if (d == 0 && d < depth) {
      for (size_t k = 0; k < level.size(); ++k) spreadIn<1>(w, &level[k], &diff[k]);
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
      for (uint32_t g : order) spreadIn<4>(w, &level[4 * size_t(g)], &diff[4 * size_t(g)]);
    }
    if (d == 0) {  // a pixel also splits when a neighbour's samples differ: an edge missed by its own 4 is seen
      const std::vector<double> own(diff);
      const int W = w.width(), H = static_cast<int>(w.pixels() / W);
      for (int j = 0; j < H; ++j)
        for (int i = 0; i < W; ++i)
          for (int y = std::max(0, j - 1); y <= std::min(H - 1, j + 1); ++y)
            for (int x = std::max(0, i - 1); x <= std::min(W - 1, i + 1); ++x)
              diff[size_t(j) * W + i] = std::max(diff[size_t(j) * W + i], own[size_t(y) * W + x]);
    }
    split.clear();
    for (size_t k = 0; k < level.size(); ++k)
      if (diff[k] > threshold) split.push_back({diff[k], w.hash(level[k].p), static_cast<uint32_t>(k)});
      else leaves.push_back(level[k]);
    // largest difference first; equal ones in the pixel-hash order (no bias towards the first rows), then in
    // the level's order: a strict order, so the unstable sort of 24-byte keys gives the order a stable sort of
    // the cells by (difference, hash) would
    std::sort(split.begin(), split.end(), [](const Key& x, const Key& y) {
      if (x.diff != y.diff) return x.diff > y.diff;
      return x.hash != y.hash ? x.hash < y.hash : x.k < y.k;
    });
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
  // fresh samples: what every leaf keeps, and what is left in proportion to the share each leaf's fresh mean
  // carries (largest remainders; ties in the order of the leaves)
  double total = 0;
  for (const Cell& c : leaves) total += c.mass * (1 - alphaOf(c));
  std::vector<int> n(leaves.size());
  for (size_t k = 0; k < leaves.size(); ++k) n[k] = keep(leaves[k]);
  std::vector<std::pair<double, size_t>> rest;
  rest.reserve(leaves.size());
  long long given = 0;
  for (size_t k = 0; k < leaves.size(); ++k) {
    const double share = static_cast<double>(free) * leaves[k].mass * (1 - alphaOf(leaves[k])) / total;
    const long long whole = static_cast<long long>(std::floor(share));
    n[k] += static_cast<int>(whole), given += whole;
    rest.push_back({share - static_cast<double>(whole), k});
  }
  // the (free - given) largest remainders, ties to the earlier leaf: a strict order, so the set is unique and
  // only it is needed (a selection, not a sort of every leaf)
  const auto larger = [](const auto& x, const auto& y) { return x.first != y.first ? x.first > y.first : x.second < y.second; };
  const size_t more = static_cast<size_t>(std::clamp<long long>(free - given, 0, static_cast<long long>(rest.size())));
  if (more < rest.size()) std::nth_element(rest.begin(), rest.begin() + static_cast<long long>(more), rest.end(), larger);
  for (size_t k = 0; k < more; ++k) ++n[rest[k].second], ++given;
  for (size_t k = 0; given > free && k < n.size(); ++k)  // rounding of the shares: never past the budget
    if (n[k] > keep(leaves[k])) --n[k], --given;
  requests.clear();
  requests.reserve(leaves.size());
  for (size_t k = 0; k < leaves.size(); ++k) {
    const Cell& c = leaves[k];
    requests.push_back({c.p, {c.level, c.cx, c.cy, n[k], static_cast<float>(c.mass * (1 - alphaOf(c)) / n[k])}});
  }
  w.trace(requests, true);
}

}  // namespace aliaslab::adaptiveimpl
