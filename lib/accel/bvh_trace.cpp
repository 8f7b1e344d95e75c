// Traversal of the bounding volume hierarchy behind makeBvh() (layout and build in bvh.h,
// bvh_build.cpp); the protocol is in aggregate.h.
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
#include <cmath>
#include <cstdint>
#include <vector>

#include "accel/bvh.h"
#include "geometry/primitives.h"
#include "geometry/triangle_math.h"

namespace aliaslab {
namespace {

using namespace bvhimpl;

constexpr int kStack = 128;

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

class Bvh final : public Aggregate {
 public:
  explicit Bvh(const Object& root) {
    BvhLayout layout = buildBvh(root);
    prims_ = std::move(layout.prims), unbounded_ = std::move(layout.unbounded), items_ = std::move(layout.items);
    nodes_ = std::move(layout.nodes), packs_ = std::move(layout.packs), buildSeconds_ = layout.buildSeconds;
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

  ObjectList prims_;
  std::vector<int> unbounded_;
  std::vector<Item> items_;
  std::vector<Node4> nodes_;
  std::vector<TriPack> packs_;  ///< the triangle-only leaves
  double buildSeconds_ = 0;
};

}  // namespace

std::unique_ptr<Aggregate> makeBvh(const Object& root) { return std::make_unique<Bvh>(root); }

std::unique_ptr<Aggregate> makeDefaultAggregate(const Object& root, int nx, int ny, int nz) {
  ObjectList flat;
  root.flatten(Mat4::Identity(), flat);
  for (const auto& p : flat)
    if (dynamic_cast<const Triangle*>(p.get())) return makeBvh(root);
  return makeGrid(root, nx, ny, nz);
}

}  // namespace aliaslab
