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

#include "render/adaptive_work.h"

namespace aliaslab::adaptiveimpl {

namespace {

struct Cell {
  long long p;   ///< pixel
  Request r;     ///< level, cx, cy (n, weight: its decision samples)
  double mass;   ///< share of the pixel's estimate that V_c carries
  double alpha;  ///< share of V_c carried by D_c
  double diff = 0;
};

constexpr int kChildFresh = 4;  ///< fresh samples a cell below the pixel keeps if it stays a leaf

/// Fresh samples a leaf keeps at least: one for a pixel, kChildFresh below.
int keep(const Cell& c) { return c.r.level == 0 ? 1 : kChildFresh; }

/// Max over channels of (max - min) of the pixel's samples inside the cell (0 with fewer than 2).
double spreadIn(const Work& w, const Cell& c) {
  const double side = std::ldexp(1.0, -c.r.level);
  const double x0 = static_cast<double>(c.p % w.width()) + c.r.cx * side;
  const double y0 = static_cast<double>(c.p / w.width()) + c.r.cy * side;
  Color lo = Color::Constant(INFINITY), hi = Color::Constant(-INFINITY);
  int in = 0;
  w.forSamples(c.p, [&](const FilmSample& s) {
    if (s.x >= x0 && s.x < x0 + side && s.y >= y0 && s.y < y0 + side && s.L.allFinite())
      lo = lo.min(s.L), hi = hi.max(s.L), ++in;
  });
  return in >= 2 ? static_cast<double>((hi - lo).maxCoeff()) : 0.0;
}

}  // namespace

void runSubdivision(Work& w, const AdaptiveSampler& a) {
  const int spp = a.spp();
  if (spp < 5) {  // no room for 4 decision samples and a fresh one: the base sampler, nothing decided
    w.tracePixels(std::vector<int>(w.pixels(), spp), std::vector<double>(w.pixels(), 1.0), true);
    return;
  }
  const double alpha0 = 4.0 / spp, alphaBelow = 0.25;
  std::vector<Cell> leaves, level;
  leaves.reserve(static_cast<size_t>(w.pixels())), level.reserve(static_cast<size_t>(w.pixels()));
  for (long long p = 0; p < w.pixels(); ++p)
    level.push_back({p, {0, 0, 0, 4, static_cast<float>(alpha0 / 4)}, 1.0, alpha0});
  w.tracePixels(std::vector<int>(w.pixels(), 4), std::vector<double>(w.pixels(), alpha0));
  long long free = w.left() - w.pixels();  // beyond the fresh samples every leaf keeps
  for (int d = 0; d <= a.params().depth && !level.empty(); ++d) {
    std::vector<Cell> split, next;
    for (Cell& c : level) c.diff = d < a.params().depth ? spreadIn(w, c) : 0.0;
    if (d == 0) {  // a pixel also splits when a neighbour's samples differ: an edge missed by its own 4 is seen
      std::vector<double> own(level.size());
      for (size_t k = 0; k < level.size(); ++k) own[k] = level[k].diff;
      const int W = w.width(), H = static_cast<int>(w.pixels() / W);
      for (int j = 0; j < H; ++j)
        for (int i = 0; i < W; ++i)
          for (int y = std::max(0, j - 1); y <= std::min(H - 1, j + 1); ++y)
            for (int x = std::max(0, i - 1); x <= std::min(W - 1, i + 1); ++x)
              level[size_t(j) * W + i].diff = std::max(level[size_t(j) * W + i].diff, own[size_t(y) * W + x]);
    }
    for (const Cell& c : level) (c.diff > a.params().threshold ? split : leaves).push_back(c);
    // largest difference first; equal ones in the pixel-hash order (no bias towards the first rows)
    std::stable_sort(split.begin(), split.end(), [&](const Cell& x, const Cell& y) {
      return x.diff != y.diff ? x.diff > y.diff : w.hash(x.p) < w.hash(y.p);
    });
    // a split costs 16 decision samples and the fresh samples its children keep (4 each, matching their
    // alpha = 1/2: as many fresh as decision samples), less the parent's own
    std::vector<std::pair<long long, Request>> requests;
    for (const Cell& c : split) {
      const long long cost = 16 + 4 * kChildFresh - keep(c);
      if (free < cost) {
        leaves.push_back(c);
        continue;
      }
      free -= cost;
      const double mass = c.mass * (1 - c.alpha) / 4;
      for (int k = 0; k < 4; ++k) {
        const Request child{c.r.level + 1, 2 * c.r.cx + (k & 1), 2 * c.r.cy + (k >> 1), 4,
                            static_cast<float>(mass * alphaBelow / 4)};
        requests.push_back({c.p, child});
        next.push_back({c.p, child, mass, alphaBelow});
      }
    }
    if (!next.empty()) w.trace(requests);
    level = std::move(next);
  }
  // fresh samples: what every leaf keeps, and what is left in proportion to the share each leaf's fresh mean
  // carries (largest remainders; ties in the order of the leaves)
  double total = 0;
  for (const Cell& c : leaves) total += c.mass * (1 - c.alpha);
  std::vector<int> n(leaves.size());
  for (size_t k = 0; k < leaves.size(); ++k) n[k] = keep(leaves[k]);
  std::vector<std::pair<double, size_t>> rest;
  long long given = 0;
  for (size_t k = 0; k < leaves.size(); ++k) {
    const double share = static_cast<double>(free) * leaves[k].mass * (1 - leaves[k].alpha) / total;
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
  std::vector<std::pair<long long, Request>> requests;
  requests.reserve(leaves.size());
  for (size_t k = 0; k < leaves.size(); ++k) {
    const Cell& c = leaves[k];
    requests.push_back({c.p, {c.r.level, c.r.cx, c.r.cy, n[k], static_cast<float>(c.mass * (1 - c.alpha) / n[k])}});
  }
  w.trace(requests, true);
}

}  // namespace aliaslab::adaptiveimpl
