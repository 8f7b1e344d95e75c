// Traversal of the bounding volume hierarchy behind makeBvh() (layout and build in bvh.h,
// bvh_build.cpp; leaf tests in bvh_leaf.h); the protocol is in aggregate.h.
//
// Two traversals over the same leaves: 4-wide nodes tested with SSE (here, for any x86-64-v2 CPU) and
// 8-wide nodes tested with AVX (bvh_trace_avx2.cpp, only where the CPU has AVX2). Both visit every node
// whose padded box the ray's segment enters and run the same leaf tests, so they return the same hits.
// Closest hit: ordered traversal (nearest child first, subtrees beyond the current hit skipped); any hit:
// depth first, out at the first hit. BvhWidth::Automatic on an AVX2 CPU builds both trees and answers closest
// hits with the 8-wide one, any hits with the 4-wide one (each the faster for its query, aggregate.h).
#include <xmmintrin.h>

#include <cstddef>
#include <stdexcept>

#include "accel/bvh_leaf.h"
#include "core/cpu.h"

namespace aliaslab {
namespace {

using namespace bvhimpl;

constexpr int kStack = 128;

/// The byte offsets in a Node4 of the planes a ray enters and leaves each slab through (lo, or hi for a negative
/// direction), chosen once per ray.
struct Planes4 {
  int enter[3], exit[3];
  explicit Planes4(const PreparedRay& r) {
    for (int a = 0; a < 3; ++a) {
      const int lo = static_cast<int>(offsetof(Node4, lo) + a * sizeof(Node4::lo[0]));
      const int hi = static_cast<int>(offsetof(Node4, hi) + a * sizeof(Node4::hi[0]));
      enter[a] = r.negative[a] ? hi : lo, exit[a] = r.negative[a] ? lo : hi;
    }
  }
};

class Bvh final : public Aggregate {
 public:
  /// width 4 or 8: one tree of that width; 0: both, the 8-wide one for closest hits, the 4-wide one for any hits.
  Bvh(const Object& root, int width) : width_(width) {
    BvhLayout layout = buildBvh(root, width);
    prims_ = std::move(layout.prims), unbounded_ = std::move(layout.unbounded), items_ = std::move(layout.items);
    nodes_ = std::move(layout.nodes), nodes8_ = std::move(layout.nodes8), packs_ = std::move(layout.packs);
    buildSeconds_ = layout.buildSeconds;
  }

  bool intersect(const Ray& ray, float tmin, Hit& hit) const override {
    int best = -1;  // flattened index of the current closest primitive
    int none = -1;
    for (int i : unbounded_) testObject(*prims_[i], i, ray, tmin, hit, best, none);
    if (!nodes8_.empty()) closestHit8({items_.data(), nodes8_.data(), packs_.data()}, ray, tmin, hit, best);
    else if (!nodes_.empty()) closestHit4(ray, tmin, hit, best);
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
    if (!nodes_.empty()) return anyHit4(ray, tmin, tmax);
    return !nodes8_.empty() && anyHit8({items_.data(), nodes8_.data(), packs_.data()}, ray, tmin, tmax);
  }

  AggregateStats stats() const override {
    AggregateStats s;
    s.primitives = prims_.size();
    s.unbounded = unbounded_.size();
    s.references = items_.size();
    s.nodes = nodes_.size() + nodes8_.size();
    s.buildSeconds = buildSeconds_;
    return s;
  }

  std::string describe() const override {
    const char* name = width_ == 8 ? "bvh 8-wide" : width_ == 4 ? "bvh 4-wide" : "bvh 8-wide closest, 4-wide any hits";
    return std::string(name) + ", " + std::to_string(nodes_.size() + nodes8_.size()) + " nodes over " +
           std::to_string(items_.size()) + " bounded prims + " + std::to_string(unbounded_.size()) +
           " unbounded";
  }

 private:
  void closestHit4(const Ray& ray, float tmin, Hit& hit, int& best) const {
    const PreparedRay r(ray);
    const Planes4 planes(r);
    int tri = -1;
    int stack[kStack];
    float near[kStack];
    int top = 0, cur = 0;  // cur: the node being visited
    while (true) {
      const Node4& n = nodes_[cur];
      float tn[4];
      const int mask = boxes(n, r, planes, tmin, hit.t, tn);
      // Ordered: the leaves among the hit children opened at once, near to far, each only while its box is not
      // beyond the closest hit so far; the inner ones pushed far to near, the nearest visited next without a
      // push (as if pushed and popped at once)
      int idx[4], k = 0;
      for (int c = 0; c < 4; ++c)
        if ((mask & (1 << c)) && n.child[c] >= 0) {
          int j = k++;
          while (j > 0 && tn[idx[j - 1]] < tn[c]) idx[j] = idx[j - 1], --j;
          idx[j] = c;
        }
      for (int m = k - 1; m >= 0; --m) {
        const int c = idx[m];
        if (n.count[c] != 0 && !(tn[c] > hit.t))
          leafClosest(n.child[c], n.count[c], r, items_.data(), packs_.data(), tmin, hit, best, tri);
      }
      int next = -1;
      for (int m = 0; m < k; ++m) {
        const int c = idx[m];
        if (n.count[c] != 0) continue;
        if (next >= 0) stack[top] = n.child[next], near[top++] = tn[next];
        next = c;
      }
      if (next >= 0 && !(tn[next] > hit.t)) {
        cur = n.child[next];
        continue;
      }
      do {  // pop the nearest node still in front of the closest hit
        if (top == 0) {
          finishClosest(items_.data(), tri, hit);
          return;
        }
        --top;
      } while (near[top] > hit.t);
      cur = stack[top];
    }
  }

  bool anyHit4(const Ray& ray, float tmin, float tmax) const {
    const PreparedRay r(ray);
    const Planes4 planes(r);
    int stack[kStack];
    int top = 0;
    stack[top++] = 0;
    while (top > 0) {
      const Node4& n = nodes_[stack[--top]];
      float tn[4];
      const int mask = boxes(n, r, planes, tmin, tmax, tn);
      for (int c = 0; c < 4; ++c) {
        if (!(mask & (1 << c)) || n.child[c] < 0) continue;
        if (n.count[c] == 0) stack[top++] = n.child[c];
        else if (leafAny(n.child[c], n.count[c], r, items_.data(), packs_.data(), tmin, tmax)) return true;
      }
    }
    return false;
  }

  /// Slab test of the four child boxes against (tmin, tmax); bit c of the
  /// result is set when child c is hit, tn[c] its entry distance.
  static int boxes(const Node4& n, const PreparedRay& r, const Planes4& p, float tmin, float tmax, float* tn) {
    const char* base = reinterpret_cast<const char*>(&n);
    auto plane = [&](int offset) { return _mm_load_ps(reinterpret_cast<const float*>(base + offset)); };
    __m128 lo = _mm_set1_ps(tmin), hi = _mm_set1_ps(tmax);
    lo = _mm_max_ps(lo, _mm_mul_ps(_mm_sub_ps(plane(p.enter[0]), r.o[0]), r.inv[0]));
    hi = _mm_min_ps(hi, _mm_mul_ps(_mm_sub_ps(plane(p.exit[0]), r.o[0]), r.inv[0]));
    lo = _mm_max_ps(lo, _mm_mul_ps(_mm_sub_ps(plane(p.enter[1]), r.o[1]), r.inv[1]));
    hi = _mm_min_ps(hi, _mm_mul_ps(_mm_sub_ps(plane(p.exit[1]), r.o[1]), r.inv[1]));
    lo = _mm_max_ps(lo, _mm_mul_ps(_mm_sub_ps(plane(p.enter[2]), r.o[2]), r.inv[2]));
    hi = _mm_min_ps(hi, _mm_mul_ps(_mm_sub_ps(plane(p.exit[2]), r.o[2]), r.inv[2]));
    _mm_storeu_ps(tn, lo);
    return _mm_movemask_ps(_mm_cmple_ps(lo, hi));
  }

  int width_;
  ObjectList prims_;
  std::vector<int> unbounded_;
  std::vector<Item> items_;      ///< in leaf order, shared by both trees
  std::vector<Node4> nodes_;     ///< the 4-wide tree (any hits, and closest hits without the 8-wide one)
  std::vector<Node8> nodes8_;    ///< the 8-wide tree (closest hits, and any hits without the 4-wide one)
  std::vector<TriPack> packs_;   ///< the triangle-only leaves, each tree's own
  double buildSeconds_ = 0;
};

}  // namespace

bool bvhEightWideSupported() { return cpuFeatures().avx2; }

std::unique_ptr<Aggregate> makeBvh(const Object& root, BvhWidth width) {
  if (width == BvhWidth::Eight && !cpuFeatures().avx2)
    throw std::runtime_error("makeBvh: the 8-wide BVH needs a CPU with AVX2, and this one has none");
  if (width == BvhWidth::Automatic) return std::make_unique<Bvh>(root, cpuFeatures().avx2 ? 0 : 4);
  return std::make_unique<Bvh>(root, width == BvhWidth::Eight ? 8 : 4);
}

std::unique_ptr<Aggregate> makeDefaultAggregate(const Object& root, int nx, int ny, int nz) {
  ObjectList flat;
  root.flatten(Mat4::Identity(), flat);
  for (const auto& p : flat)
    if (dynamic_cast<const Triangle*>(p.get())) return makeBvh(root);
  return makeGrid(root, nx, ny, nz);
}

}  // namespace aliaslab
