// The adaptive methods' shared state (adaptive_work.h): the samples of each round traced in parallel, the
// budget spent, and the orders and summaries the methods ask of it.
#include <algorithm>
#include <bit>
#include <cfloat>
#include <cmath>
#include <map>
#include <memory>
#include <stdexcept>

#include "core/hash.h"
#include "core/parallel.h"
#include "render/adaptive/adaptive_work.h"

namespace aliaslab::adaptiveimpl {

namespace {
constexpr int kTile = 16;  ///< a round's tiles, kTile x kTile pixels

/// The float below v (v >= 1): std::nextafter(float(v), 0) without the libm call.
float below(int v) { return std::bit_cast<float>(std::bit_cast<uint32_t>(static_cast<float>(v)) - 1); }
}  // namespace

Work::Work(const Tracer& tracer, const AdaptiveSampler& a, int width, int height, int threads, const Progress& progress)
    : tracer_(tracer), a_(a), W_(width), H_(height), threads_(threads), progress_(progress),
      N_(static_cast<long long>(width) * height), B_(N_ * a.spp()), count_(N_, 0), hash_(N_) {
  for (long long p = 0; p < N_; ++p) hash_[p] = hashWords(a.seed(), 0x72616e6bULL, static_cast<uint64_t>(p));
}

void Work::trace(const std::vector<std::pair<long long, Request>>& requests, bool last) {
  if (finished_) throw std::logic_error("adaptive Work: a round after the last one");
  // The round's layout: requests grouped by pixel (a counting sort keeping each pixel's order), and the
  // samples of pixel p at [start[p], start[p + 1]) of one flat buffer.
  Round round;
  round.start.assign(static_cast<size_t>(N_) + 1, 0);
  std::vector<size_t> first(static_cast<size_t>(N_) + 1, 0);
  for (const auto& [p, r] : requests) ++first[p + 1], round.start[p + 1] += static_cast<size_t>(std::max(0, r.n));
  for (long long p = 0; p < N_; ++p) first[p + 1] += first[p], round.start[p + 1] += round.start[p];
  std::vector<Request> cells(requests.size());
  for (const auto& [p, r] : requests) cells[first[p]++] = r;  // first[p] ends where pixel p + 1's cells start
  for (long long p = N_; p > 0; --p) first[p] = first[p - 1];
  first[0] = 0;
  const long long total = static_cast<long long>(round.start[N_]);
  // Before the parallel part: for every count n requested, the samplers of its parts (by part count and the
  // index of the part among equal counts, which goes into the seed so two parts of one count in a cell are
  // independent), as a plan indexed by n that the workers only read.
  std::map<std::pair<int, int>, std::unique_ptr<Sampler>> samplers;
  std::vector<std::vector<const Sampler*>> plan;
  int most = 0;  // the largest part: the workers' point arrays are that long
  int longest = 0;  // progressive requests: the longest prefix, one sampler of that count serves every prefix
  for (const Request& r : cells)
    if (r.n > 0 && r.first >= 0) longest = std::max(longest, r.first + r.n);
  const std::unique_ptr<Sampler> progressive = longest > 0 ? a_.progressiveSampler(longest) : nullptr;
  most = longest;
  for (const Request& r : cells) {
    if (r.n <= 0 || r.first >= 0) continue;
    if (static_cast<size_t>(r.n) >= plan.size()) plan.resize(static_cast<size_t>(r.n) + 1);
    if (!plan[r.n].empty()) continue;
    std::map<int, int> seen;
    for (int part : parts(r.n)) {
      const std::pair<int, int> key{part, seen[part]++};
      auto& s = samplers[key];
      if (!s) s = a_.baseSampler(part, key.second == 0 ? round_ : hashWords(round_, 0x70617274ULL, key.second));
      plan[r.n].push_back(s.get());
      most = std::max(most, s->spp());
    }
  }
  for (long long p = 0; p < N_; ++p) count_[p] += static_cast<int>(round.start[p + 1] - round.start[p]);
  // Where the round's samples go: its own flat buffer, or (last round) the final buffer after each pixel's
  // earlier samples, which are copied there first.
  if (last) final_ = SampleBuffer(W_, H_, count_, SampleBuffer::Unwritten{});  // every sample written below
  else round.samples = SampleBuffer::Storage(static_cast<size_t>(total));
  const bool inFloat = W_ < (1 << 24) && H_ < (1 << 24);  // every pixel index a float
  // One pixel's cells of the round, into its place (u: the worker's point array).
  const auto tracePixel = [&](int i, int j, Vec2* u) {
    const size_t p = static_cast<size_t>(j) * W_ + i;
    FilmSample* out = round.samples.data() + round.start[p];
    if (last) {
      out = final_.pixel(i, j);
      for (const Round& r : rounds_)
        out = std::copy(r.samples.data() + r.start[p], r.samples.data() + r.start[p + 1], out);
      if (!earlierWeight_.empty())
        for (FilmSample* s = final_.pixel(i, j); s != out; ++s) s->weight = earlierWeight_[p];
    }
    if (first[p] == first[p + 1]) return;
    // Two passes: the pixel's positions and weights, then its rays in one tight loop (the position arithmetic's
    // values are not spilled and reloaded around every radianceAt call).
    FilmSample* const begin = out;
    const float fi = static_cast<float>(i), topX = below(i + 1), fj = static_cast<float>(j), topY = below(j + 1);
    for (size_t c = first[p]; c < first[p + 1]; ++c) {
      const Request r = cells[c];
      if (r.n <= 0) continue;
      const int px = (i << r.level) + r.cx, py = (j << r.level) + r.cy;
      const double side = cellSide(r.level);  // 1 / 2^level
      const float fside = static_cast<float>(side);  // a power of two: exact
      const auto emit = [&](const Vec2* pts, int n) {
        for (int k = 0; k < n; ++k, ++out) {
          const Vec2 q = pts[k];
          // The position i + (cx + q) * side, the sum in double rounded to float (inside), is computed in float
          // with the same bits: cx + q is a float either way; times a power of two it stays exact unless the
          // product is subnormal; and a sum of two floats (i is one below 2^24) rounded to double and then to
          // float is rounded once (53 >= 2 * 24 + 2 bits). Else in double, as written.
          const float tx = (r.cx + q.x()) * fside, ty = (r.cy + q.y()) * fside;
          if (inFloat && (tx == 0 || tx >= FLT_MIN) && (ty == 0 || ty >= FLT_MIN))
            out->x = std::clamp(fi + tx, fi, topX), out->y = std::clamp(fj + ty, fj, topY);
          else
            out->x = inside(i + (r.cx + q.x()) * side, i, topX), out->y = inside(j + (r.cy + q.y()) * side, j, topY);
          out->weight = r.weight;
        }
      };
      if (r.first >= 0) {
        progressive->generatePrefix(px, py, r.first + r.n, u);
        emit(u + r.first, r.n);
      } else {
        for (const Sampler* sampler : plan[r.n]) {
          sampler->generate(px, py, u);
          emit(u, sampler->spp());
        }
      }
    }
    for (FilmSample* s = begin; s != out; ++s) s->L = tracer_.radianceAt(s->x, s->y, W_, H_);
  };
  // Tile by tile (kTile x kTile pixels, as traceSamples): a round's rays close together on the film, so the BVH
  // nodes they visit stay in cache (row by row, a round's rays spread over whole rows of the scene).
  const int tilesX = (W_ + kTile - 1) / kTile, tilesY = (H_ + kTile - 1) / kTile;
  parallelFor(tilesX * tilesY, threads_, [&](int tile) {
    std::vector<Vec2> u(static_cast<size_t>(most));
    const int x0 = (tile % tilesX) * kTile, y0 = (tile / tilesX) * kTile;
    for (int j = y0; j < std::min(y0 + kTile, H_); ++j)
      for (int i = x0; i < std::min(x0 + kTile, W_); ++i) tracePixel(i, j, u.data());
  });
  if (last) {
    final_.setAreaWeighted(true);
    rounds_.clear();  // all in final_ now
    finished_ = true;
  } else {
    rounds_.push_back(std::move(round));
  }
  spent_ += total, ++round_;
  if (progress_) {
    const double f = static_cast<double>(spent_) / static_cast<double>(std::max(1LL, B_));
    progress_(static_cast<int>(std::lround(f * 1e6)), 1000000);
  }
}

void Work::tracePixels(const std::vector<int>& add, const std::vector<double>& share, bool last,
                       const std::vector<int>* first) {
  std::vector<std::pair<long long, Request>> requests;
  requests.reserve(static_cast<size_t>(N_));
  for (long long p = 0; p < N_; ++p)
    if (add[p] > 0)
      requests.push_back({p, {0, 0, 0, add[p], static_cast<float>(share[p] / add[p]), first ? (*first)[p] : -1}});
  trace(requests, last);
}

SampleBuffer Work::gather() {
  if (!finished_) throw std::logic_error("adaptive Work: gather() before the method's last round");
  return std::move(final_);
}

bool Work::fullQuality(int n) const {
  auto it = quality_.find(n);
  if (it == quality_.end()) it = quality_.emplace(n, a_.baseSampler(n, 0)->warning().empty()).first;
  return it->second;
}

std::vector<int> Work::parts(int n) const {
  std::vector<int> out;
  while (n > 0) {
    int c = n;
    while (c > 1 && !fullQuality(c)) --c;
    out.push_back(c), n -= c;
  }
  return out;
}

std::vector<long long> Work::rank(const std::vector<double>& priority, long long first) const {
  // the order's key of every pixel side by side (the comparisons read one array, not three at random)
  struct Key {
    double priority;
    int count;
    uint64_t hash;
    long long p;
    bool operator<(const Key& o) const {  // "before"
      if (priority != o.priority) return priority > o.priority;
      if (count != o.count) return count < o.count;
      return hash != o.hash ? hash < o.hash : p < o.p;
    }
  };
  std::vector<Key> keys(static_cast<size_t>(N_));
  for (long long p = 0; p < N_; ++p) keys[p] = {priority[p], count_[p], hash_[p], p};
  const long long k = std::clamp(first, 0LL, N_);
  if (k < N_) std::nth_element(keys.begin(), keys.begin() + k, keys.end());  // the first k, unsorted
  std::sort(keys.begin(), keys.begin() + k);
  std::vector<long long> order(static_cast<size_t>(k));
  for (long long q = 0; q < k; ++q) order[q] = keys[q].p;
  return order;
}

std::vector<int> Work::evenly(long long amount, const std::vector<double>& priority) const {
  const long long q = std::max(0LL, amount) / N_, extra = std::max(0LL, amount) % N_;
  std::vector<int> add(N_, static_cast<int>(q));
  if (extra > 0) {
    const auto order = rank(priority, extra);
    for (long long k = 0; k < extra; ++k) ++add[order[k]];
  }
  return add;
}

std::vector<double> dilate(const std::vector<double>& v, int W, int H) {
  std::vector<double> rows(v.size()), out(v.size());
  for (int j = 0; j < H; ++j) {
    const double* in = v.data() + size_t(j) * W;
    double* r = rows.data() + size_t(j) * W;
    for (int i = 0; i < W; ++i)
      r[i] = std::max({0.0, i > 0 ? in[i - 1] : 0.0, in[i], i + 1 < W ? in[i + 1] : 0.0});
  }
  for (int j = 0; j < H; ++j) {
    const double* up = rows.data() + size_t(std::max(0, j - 1)) * W;
    const double* mid = rows.data() + size_t(j) * W;
    const double* down = rows.data() + size_t(std::min(H - 1, j + 1)) * W;
    double* o = out.data() + size_t(j) * W;
    for (int i = 0; i < W; ++i) o[i] = std::max({up[i], mid[i], down[i]});
  }
  return out;
}

std::vector<double> neighbourMax(const std::vector<double>& v, int W, int H) {
  std::vector<double> out(v.size(), 0.0);
  for (int j = 0; j < H; ++j)
    for (int i = 0; i < W; ++i) {
      double m = 0;
      for (int y = std::max(0, j - 1); y <= std::min(H - 1, j + 1); ++y)
        for (int x = std::max(0, i - 1); x <= std::min(W - 1, i + 1); ++x)
          if (x != i || y != j) m = std::max(m, v[size_t(y) * W + x]);
      out[size_t(j) * W + i] = m;
    }
  return out;
}

void Work::pixelRanges(std::vector<Color>& lo, std::vector<Color>& hi) const {
  lo.assign(N_, Color::Constant(INFINITY)), hi.assign(N_, Color::Constant(-INFINITY));
  for (long long p = 0; p < N_; ++p)
    forSamples(p, [&](const FilmSample& s) {
      if (s.L.allFinite()) lo[p] = lo[p].min(s.L), hi[p] = hi[p].max(s.L);
    });
}

}  // namespace aliaslab::adaptiveimpl
