// Bounding volume hierarchy behind makeBvh(); the protocol is in aggregate.h.
//
// Build: a binary tree by binned SAH over primitive centroids (kBins bins
// per axis, leaves of at most kMaxLeaf primitives), collapsed into 4-wide
// nodes (each node adopts the children of its largest-area inner children
// until it has four), boxes stored axis by axis so one SSE instruction tests
// a ray against four boxes. Boxes are padded like the grid's so that the
// float slab test never drops a box a hit lies in.
//
// Triangles: the watertight test of Woop, Benthin and Wald (2013) decides
// hit or miss (shear the triangle into the ray's space, signs of three 2D
// edge functions, recomputed in double when one is exactly zero), so a ray
// through a shared edge or vertex of a closed mesh hits at least one of the
// triangles. The distance t of an accepted triangle is then computed with
// the Moller-Trumbore formula Triangle::intersect uses, so t (and hence
// every shaded value) is bit-identical to brute force whenever both tests
// accept; they differ only for rays within rounding of an edge.
// Leaves made only of triangles (all but a few) are stored as a TriPack, so
// the watertight test runs on up to four triangles per SSE instruction; the
// accepted ones are then taken in item order, as the one-by-one loop would.
// Closest hit: t in (tmin, hit.t), ties in t to the lower flattened index
// (as brute force's list order gives), whatever order nodes are visited in.
#include <xmmintrin.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <vector>

#include "accel/aggregate.h"
#include "geometry/primitives.h"
#include "geometry/triangle_math.h"

namespace aliaslab {
namespace {

constexpr int kBins = 16, kMaxLeaf = 4, kStack = 128;

struct Item {
  Vec3 a, b, c;      ///< triangle vertices (unused for other primitives)
  Vec3 e1, e2;       ///< b - a, c - a as Triangle::intersect computes them
  const Object* obj; ///< nullptr for a triangle, else a primitive tested by its own intersect()
  const Material* material;
  int prim;          ///< flattened index
};

struct alignas(16) Node4 {
  float lo[3][4], hi[3][4];  ///< child boxes, axis by axis
  int32_t child[4];          ///< inner: node index; leaf: first item (packed leaf: TriPack index); -1: empty
  uint32_t count[4];         ///< 0: inner node, else number of items of the leaf (| kPacked: a TriPack)
};

/// A leaf made only of triangles, vertices stored axis by axis so that one SSE
/// instruction runs a step of the watertight test for all of them. Lanes >= n
/// are unused; item[l] is lane l's entry in items_ (material, prim, edges).
struct alignas(16) TriPack {
  float a[3][4], b[3][4], c[3][4];
  int32_t item[4];
  int32_t n;
};
constexpr uint32_t kPacked = 0x80000000u;  ///< in Node4::count: child is a TriPack index, low bits the count

/// A ray prepared for both box and watertight triangle tests.
struct PreparedRay {
  const Ray* ray;
  __m128 o[3], inv[3];
  bool negative[3];  ///< direction component < 0: the slab is entered through hi
  int kx, ky, kz;
  float sx, sy, sz;
  __m128 okx, oky, okz, vsx, vsy;  ///< origin along kx, ky, kz and the shears, broadcast (pack test)
  explicit PreparedRay(const Ray& r) : ray(&r) {
    const Vec3& d = r.direction;
    for (int a = 0; a < 3; ++a) {
      float da = d[a];
      if (std::abs(da) < 1e-30f) da = std::signbit(da) ? -1e-30f : 1e-30f;
      o[a] = _mm_set1_ps(r.origin[a]);
      inv[a] = _mm_set1_ps(1.f / da);
      negative[a] = da < 0.f;
    }
    const Vec3 ad = d.cwiseAbs();
    kz = ad.x() > ad.y() ? (ad.x() > ad.z() ? 0 : 2) : (ad.y() > ad.z() ? 1 : 2);
    kx = (kz + 1) % 3, ky = (kx + 1) % 3;
    if (d[kz] < 0.f) std::swap(kx, ky);  // keep the winding
    sx = d[kx] / d[kz], sy = d[ky] / d[kz], sz = 1.f / d[kz];
    okx = _mm_set1_ps(r.origin[kx]), oky = _mm_set1_ps(r.origin[ky]), okz = _mm_set1_ps(r.origin[kz]);
    vsx = _mm_set1_ps(sx), vsy = _mm_set1_ps(sy);
  }
};

/// Woop-Benthin-Wald: does the ray's line pass through the triangle
/// (edges and vertices included)? Direction-agnostic in t; t is checked later.
inline bool watertightHit(const PreparedRay& r, const Item& it) {
  const Vec3& o = r.ray->origin;
  const Vec3 A = it.a - o, B = it.b - o, C = it.c - o;
  const float ax = A[r.kx] - r.sx * A[r.kz], ay = A[r.ky] - r.sy * A[r.kz];
  const float bx = B[r.kx] - r.sx * B[r.kz], by = B[r.ky] - r.sy * B[r.kz];
  const float cx = C[r.kx] - r.sx * C[r.kz], cy = C[r.ky] - r.sy * C[r.kz];
  float u = cx * by - cy * bx, v = ax * cy - ay * cx, w = bx * ay - by * ax;
  if (u == 0.f || v == 0.f || w == 0.f) {
    u = static_cast<float>(static_cast<double>(cx) * by - static_cast<double>(cy) * bx);
    v = static_cast<float>(static_cast<double>(ax) * cy - static_cast<double>(ay) * cx);
    w = static_cast<float>(static_cast<double>(bx) * ay - static_cast<double>(by) * ax);
  }
  if ((u < 0.f || v < 0.f || w < 0.f) && (u > 0.f || v > 0.f || w > 0.f)) return false;
  return u + v + w != 0.f;  // zero: the ray lies in the triangle's plane
}

/// watertightHit() for the triangles of a pack at once, as a lane mask: the
/// same float operations in the same order per lane (so the same answers);
/// a lane with an edge function exactly zero is decided by the scalar test
/// (its double recomputation).
inline int watertightHits(const PreparedRay& r, const TriPack& p, const std::vector<Item>& items) {
  const __m128 zero = _mm_setzero_ps();
  auto shear = [&](const float (*v)[4], __m128& x, __m128& y) {
    const __m128 vz = _mm_sub_ps(_mm_load_ps(v[r.kz]), r.okz);
    x = _mm_sub_ps(_mm_sub_ps(_mm_load_ps(v[r.kx]), r.okx), _mm_mul_ps(r.vsx, vz));
    y = _mm_sub_ps(_mm_sub_ps(_mm_load_ps(v[r.ky]), r.oky), _mm_mul_ps(r.vsy, vz));
  };
  __m128 ax, ay, bx, by, cx, cy;
  shear(p.a, ax, ay), shear(p.b, bx, by), shear(p.c, cx, cy);
  const __m128 u = _mm_sub_ps(_mm_mul_ps(cx, by), _mm_mul_ps(cy, bx));
  const __m128 v = _mm_sub_ps(_mm_mul_ps(ax, cy), _mm_mul_ps(ay, cx));
  const __m128 w = _mm_sub_ps(_mm_mul_ps(bx, ay), _mm_mul_ps(by, ax));
  const __m128 neg = _mm_or_ps(_mm_or_ps(_mm_cmplt_ps(u, zero), _mm_cmplt_ps(v, zero)), _mm_cmplt_ps(w, zero));
  const __m128 pos = _mm_or_ps(_mm_or_ps(_mm_cmpgt_ps(u, zero), _mm_cmpgt_ps(v, zero)), _mm_cmpgt_ps(w, zero));
  const __m128 ok = _mm_andnot_ps(_mm_and_ps(neg, pos), _mm_cmpneq_ps(_mm_add_ps(_mm_add_ps(u, v), w), zero));
  const __m128 edge = _mm_or_ps(_mm_or_ps(_mm_cmpeq_ps(u, zero), _mm_cmpeq_ps(v, zero)), _mm_cmpeq_ps(w, zero));
  const int valid = (1 << p.n) - 1;
  int mask = _mm_movemask_ps(ok) & valid;
  int exact = _mm_movemask_ps(edge) & valid;
  while (exact) {
    const int l = __builtin_ctz(exact);
    exact &= exact - 1;
    mask = watertightHit(r, items[p.item[l]]) ? (mask | (1 << l)) : (mask & ~(1 << l));
  }
  return mask;
}

/// Moller-Trumbore's t, the exact expressions of intersectTriangle().
inline bool mollerTrumboreT(const Ray& ray, const Item& it, float& t) {
  const Vec3 p = ray.direction.cross(it.e2);
  const float det = it.e1.dot(p);
  if (det == 0.f) return false;
  const float inv = 1.f / det;
  const Vec3 s = ray.origin - it.a;
  const Vec3 q = s.cross(it.e1);
  t = it.e2.dot(q) * inv;
  return true;
}

float area(const BBox& b) {
  if (b.empty()) return 0.f;
  const Vec3 e = b.extent();
  return 2.f * (e.x() * e.y() + e.y() * e.z() + e.z() * e.x());
}

struct BinaryNode {
  BBox box;
  int left = -1, right = -1;  ///< -1: leaf
  int start = 0, count = 0;
};

class Bvh final : public Aggregate {
 public:
  explicit Bvh(const Object& root) {
    const auto t0 = std::chrono::steady_clock::now();
    root.flatten(Mat4::Identity(), prims_);
    std::vector<BBox> boxes;
    BBox world;
    for (size_t i = 0; i < prims_.size(); ++i) {
      const Object& p = *prims_[i];
      if (!p.bounded()) {
        unbounded_.push_back(static_cast<int>(i));
        continue;
      }
      Item it{};
      it.prim = static_cast<int>(i);
      if (const auto* tri = dynamic_cast<const Triangle*>(&p)) {
        it.a = tri->a, it.b = tri->b, it.c = tri->c;
        it.e1 = tri->b - tri->a, it.e2 = tri->c - tri->a;
        it.material = tri->material;
        it.obj = nullptr;
      } else {
        it.obj = &p;
      }
      items_.push_back(it);
      boxes.push_back(p.bounds());
      world.extend(boxes.back());
    }
    if (!items_.empty()) {
      const float maxAbs = std::max(world.min.cwiseAbs().maxCoeff(), world.max.cwiseAbs().maxCoeff());
      const float pad = 1e-5f * world.extent().norm() + 1e-6f * maxAbs + 1e-30f;
      for (auto& b : boxes) b.min.array() -= pad, b.max.array() += pad;
      std::vector<int> order(items_.size());
      for (size_t i = 0; i < order.size(); ++i) order[i] = static_cast<int>(i);
      std::vector<Vec3> centroids(boxes.size());
      for (size_t i = 0; i < boxes.size(); ++i) centroids[i] = 0.5f * (boxes[i].min + boxes[i].max);
      std::vector<BinaryNode> bin;
      bin.reserve(2 * items_.size());
      bin.push_back({});
      split(0, 0, static_cast<int>(order.size()), order, boxes, centroids, bin);
      std::vector<Item> sorted(items_.size());
      for (size_t i = 0; i < order.size(); ++i) sorted[i] = items_[order[i]];
      items_.swap(sorted);
      nodes_.reserve(bin.size() / 2 + 1);
      collapse(0, bin);
    }
    buildSeconds_ = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  }

  bool intersect(const Ray& ray, float tmin, Hit& hit) const override {
    int best = -1;  // flattened index of the current closest primitive
    for (int i : unbounded_) testObject(*prims_[i], i, ray, tmin, hit, best);
    if (!nodes_.empty()) {
      const PreparedRay r(ray);
      int stack[kStack];
      float near[kStack];
      int top = 0;
      stack[top] = 0, near[top++] = -kInf;
      while (top > 0) {
        --top;
        if (near[top] > hit.t) continue;
        const Node4& n = nodes_[stack[top]];
        float tn[4];
        const int mask = boxes(n, r, tmin, hit.t, tn);
        // Ordered: push hit children far to near, so the nearest is visited first
        int idx[4], k = 0;
        for (int c = 0; c < 4; ++c)
          if ((mask & (1 << c)) && n.child[c] >= 0) {
            int j = k++;
            while (j > 0 && tn[idx[j - 1]] < tn[c]) idx[j] = idx[j - 1], --j;
            idx[j] = c;
          }
        for (int m = 0; m < k; ++m) {
          const int c = idx[m];
          if (n.count[c] == 0) {
            stack[top] = n.child[c], near[top++] = tn[c];
          } else if (n.count[c] & kPacked) {
            const TriPack& p = packs_[n.child[c]];
            for (int mask = watertightHits(r, p, items_); mask; mask &= mask - 1)  // lanes in item order
              acceptTriangle(items_[p.item[__builtin_ctz(mask)]], ray, tmin, hit, best);
          } else {
            for (uint32_t e = 0; e < n.count[c]; ++e) testItem(items_[n.child[c] + e], r, tmin, hit, best);
          }
        }
      }
    }
    if (best < 0) return false;
    hit.primitive = best;
    return true;
  }

  bool occluded(const Ray& ray, float tmin, float tmax) const override {
    for (int i : unbounded_) {
      Hit h;
      h.t = tmax;
      if (prims_[i]->intersect(ray, tmin, h)) return true;
    }
    if (nodes_.empty()) return false;
    const PreparedRay r(ray);
    int stack[kStack];
    int top = 0;
    stack[top++] = 0;
    while (top > 0) {
      const Node4& n = nodes_[stack[--top]];
      float tn[4];
      const int mask = boxes(n, r, tmin, tmax, tn);
      for (int c = 0; c < 4; ++c) {
        if (!(mask & (1 << c)) || n.child[c] < 0) continue;
        if (n.count[c] == 0) {
          stack[top++] = n.child[c];
          continue;
        }
        if (n.count[c] & kPacked) {
          const TriPack& p = packs_[n.child[c]];
          for (int mask = watertightHits(r, p, items_); mask; mask &= mask - 1) {
            float t;
            if (mollerTrumboreT(ray, items_[p.item[__builtin_ctz(mask)]], t) && t > tmin && t < tmax) return true;
          }
          continue;
        }
        for (uint32_t e = 0; e < n.count[c]; ++e) {
          const Item& it = items_[n.child[c] + e];
          if (it.obj) {
            Hit h;
            h.t = tmax;
            if (it.obj->intersect(ray, tmin, h)) return true;
          } else {
            float t;
            if (watertightHit(r, it) && mollerTrumboreT(ray, it, t) && t > tmin && t < tmax) return true;
          }
        }
      }
    }
    return false;
  }

  AggregateStats stats() const override {
    AggregateStats s;
    s.primitives = prims_.size();
    s.unbounded = unbounded_.size();
    s.references = items_.size();
    s.nodes = nodes_.size();
    s.buildSeconds = buildSeconds_;
    return s;
  }

  std::string describe() const override {
    return "bvh 4-wide, " + std::to_string(nodes_.size()) + " nodes over " + std::to_string(items_.size()) +
           " bounded prims + " + std::to_string(unbounded_.size()) + " unbounded";
  }

 private:
  /// Slab test of the four child boxes against (tmin, tmax); bit c of the
  /// result is set when child c is hit, tn[c] its entry distance.
  static int boxes(const Node4& n, const PreparedRay& r, float tmin, float tmax, float* tn) {
    __m128 lo = _mm_set1_ps(tmin), hi = _mm_set1_ps(tmax);
    for (int a = 0; a < 3; ++a) {  // entry through lo, exit through hi (swapped for a negative direction)
      const float* enter = r.negative[a] ? n.hi[a] : n.lo[a];
      const float* exit = r.negative[a] ? n.lo[a] : n.hi[a];
      lo = _mm_max_ps(lo, _mm_mul_ps(_mm_sub_ps(_mm_load_ps(enter), r.o[a]), r.inv[a]));
      hi = _mm_min_ps(hi, _mm_mul_ps(_mm_sub_ps(_mm_load_ps(exit), r.o[a]), r.inv[a]));
    }
    _mm_storeu_ps(tn, lo);
    return _mm_movemask_ps(_mm_cmple_ps(lo, hi));
  }

  /// A primitive with its own intersect(): a tie in t goes to the lower index.
  static void testObject(const Object& obj, int prim, const Ray& ray, float tmin, Hit& hit, int& best) {
    Hit h = hit;
    if (best >= 0 && prim < best) h.t = std::nextafter(hit.t, kInf);
    if (obj.intersect(ray, tmin, h)) hit = h, best = prim;
  }

  static void testItem(const Item& it, const PreparedRay& r, float tmin, Hit& hit, int& best) {
    if (it.obj) return testObject(*it.obj, it.prim, *r.ray, tmin, hit, best);
    if (watertightHit(r, it)) acceptTriangle(it, *r.ray, tmin, hit, best);
  }

  /// A triangle the watertight test accepted: its Moller-Trumbore t, ties in t to the lower index.
  static void acceptTriangle(const Item& it, const Ray& ray, float tmin, Hit& hit, int& best) {
    float t;
    if (!mollerTrumboreT(ray, it, t)) return;
    if (!(t > tmin)) return;
    if (!(t < hit.t || (t == hit.t && best >= 0 && it.prim < best))) return;
    hit.t = t;
    hit.normal = triangleNormal(it.e1, it.e2);
    hit.material = it.material;
    best = it.prim;
  }

  /// Binned SAH split of order[start, end) into bin[node].
  void split(int node, int start, int end, std::vector<int>& order, const std::vector<BBox>& boxes,
             const std::vector<Vec3>& centroids, std::vector<BinaryNode>& bin) {
    BBox box, cbox;
    for (int i = start; i < end; ++i) box.extend(boxes[order[i]]), cbox.extend(centroids[order[i]]);
    bin[node].box = box, bin[node].start = start, bin[node].count = end - start;
    const int n = end - start;
    if (n <= 1) return;
    int bestAxis = -1, bestSplit = 0;
    float bestCost = kInf;
    for (int a = 0; a < 3; ++a) {
      const float extent = cbox.max[a] - cbox.min[a];
      if (!(extent > 0.f)) continue;
      BBox bb[kBins];
      int cnt[kBins] = {};
      const float scale = kBins / extent;
      for (int i = start; i < end; ++i) {
        const int b = std::min(kBins - 1, static_cast<int>((centroids[order[i]][a] - cbox.min[a]) * scale));
        bb[b].extend(boxes[order[i]]), ++cnt[b];
      }
      float rightArea[kBins];
      int rightCount[kBins];
      BBox acc;
      int c = 0;
      for (int b = kBins - 1; b > 0; --b) acc.extend(bb[b]), c += cnt[b], rightArea[b] = area(acc), rightCount[b] = c;
      acc = BBox{}, c = 0;
      for (int b = 0; b < kBins - 1; ++b) {
        acc.extend(bb[b]), c += cnt[b];
        if (c == 0 || rightCount[b + 1] == 0) continue;
        const float cost = area(acc) * c + rightArea[b + 1] * rightCount[b + 1];
        if (cost < bestCost) bestCost = cost, bestAxis = a, bestSplit = b;
      }
    }
    // Leaf when small and splitting does not pay (intersection cost ~ 1 box test per 1 primitive)
    const float leafCost = area(box) * n;
    int mid;
    if (bestAxis < 0) {  // all centroids equal: split by count if too many
      if (n <= kMaxLeaf) return;
      mid = start + n / 2;
    } else {
      if (n <= kMaxLeaf && bestCost + area(box) >= leafCost) return;
      const float lo = cbox.min[bestAxis], scale = kBins / (cbox.max[bestAxis] - lo);
      const auto it = std::partition(order.begin() + start, order.begin() + end, [&](int i) {
        return std::min(kBins - 1, static_cast<int>((centroids[i][bestAxis] - lo) * scale)) <= bestSplit;
      });
      mid = static_cast<int>(it - order.begin());
      if (mid == start || mid == end) mid = start + n / 2;
    }
    const int l = static_cast<int>(bin.size());
    bin.push_back({}), bin.push_back({});
    bin[node].left = l, bin[node].right = l + 1;
    split(l, start, mid, order, boxes, centroids, bin);
    split(l + 1, mid, end, order, boxes, centroids, bin);
  }

  /// 4-wide node for binary node b (an inner node); returns its index.
  int collapse(int b, const std::vector<BinaryNode>& bin) {
    std::vector<int> kids;
    if (bin[b].left < 0) kids = {b};  // the root is a leaf
    else kids = {bin[b].left, bin[b].right};
    while (kids.size() < 4) {
      int pick = -1;
      float bestArea = -1.f;
      for (size_t i = 0; i < kids.size(); ++i)
        if (bin[kids[i]].left >= 0 && area(bin[kids[i]].box) > bestArea) bestArea = area(bin[kids[i]].box), pick = static_cast<int>(i);
      if (pick < 0) break;
      const int k = kids[pick];
      kids[pick] = bin[k].left;
      kids.push_back(bin[k].right);
    }
    const int index = static_cast<int>(nodes_.size());
    nodes_.push_back({});
    for (int c = 0; c < 4; ++c) {
      Node4& n = nodes_[index];
      if (c >= static_cast<int>(kids.size())) {
        for (int a = 0; a < 3; ++a) n.lo[a][c] = kInf, n.hi[a][c] = -kInf;
        n.child[c] = -1, n.count[c] = 0;
        continue;
      }
      const BinaryNode& k = bin[kids[c]];
      for (int a = 0; a < 3; ++a) n.lo[a][c] = k.box.min[a], n.hi[a][c] = k.box.max[a];
      if (k.left < 0) {
        n.child[c] = k.start, n.count[c] = static_cast<uint32_t>(k.count);
        bool triangles = k.count <= 4;
        for (int e = 0; e < k.count; ++e) triangles = triangles && !items_[k.start + e].obj;
        if (triangles) {  // the watertight test runs on all of them at once (TriPack)
          TriPack p{};
          p.n = k.count;
          for (int e = 0; e < 4; ++e) {
            const Item& it = items_[k.start + std::min(e, k.count - 1)];  // unused lanes repeat the last
            p.item[e] = k.start + std::min(e, k.count - 1);
            for (int a = 0; a < 3; ++a) p.a[a][e] = it.a[a], p.b[a][e] = it.b[a], p.c[a][e] = it.c[a];
          }
          n.child[c] = static_cast<int32_t>(packs_.size()), n.count[c] = kPacked | static_cast<uint32_t>(k.count);
          packs_.push_back(p);
        }
      } else {
        n.count[c] = 0;
        const int child = collapse(kids[c], bin);
        nodes_[index].child[c] = child;
      }
    }
    return index;
  }

  ObjectList prims_;
  std::vector<int> unbounded_;
  std::vector<Item> items_;
  std::vector<Node4> nodes_;
  std::vector<TriPack> packs_;  ///< the triangle-only leaves
  double buildSeconds_ = 0;
};

}  // namespace

std::unique_ptr<Aggregate> makeBvh(const Object& root) { return std::make_unique<Bvh>(root); }

}  // namespace aliaslab

namespace aliaslab {

std::unique_ptr<Aggregate> makeDefaultAggregate(const Object& root, int nx, int ny, int nz) {
  ObjectList flat;
  root.flatten(Mat4::Identity(), flat);
  for (const auto& p : flat)
    if (dynamic_cast<const Triangle*>(p.get())) return makeBvh(root);
  return makeGrid(root, nx, ny, nz);
}

}  // namespace aliaslab
