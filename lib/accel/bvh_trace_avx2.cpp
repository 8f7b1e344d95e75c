// The 8-wide traversal of the bounding volume hierarchy (bvh.h): a ray against eight child boxes per AVX
// instruction, the leaves tested as the 4-wide traversal tests them (bvh_leaf.h), so both give the same hits.
// This file alone is built with -mavx2 (CMakeLists.txt); bvh_trace.cpp calls it only where the CPU has AVX2.
// It shares code with the other translation units only through unnamed-namespace, always-inlined functions
// (bvh_leaf.h) and the layout's plain structs, so no AVX2 code can stand in for theirs at link time.
#include <immintrin.h>

#include <cstddef>

#include "accel/bvh_leaf.h"

namespace aliaslab::bvhimpl {
namespace {

constexpr int kStack8 = 256;  ///< up to 7 more entries per level

/// The ray's origin and reciprocal direction on eight lanes, and the byte offsets in a Node8 of the planes it
/// enters and leaves each slab through (lo, or hi for a negative direction), chosen once per ray.
struct Ray8 {
  __m256 o[3], inv[3];
  int enter[3], exit[3];
  explicit Ray8(const PreparedRay& r) {
    for (int a = 0; a < 3; ++a) {
      o[a] = _mm256_broadcastss_ps(r.o[a]), inv[a] = _mm256_broadcastss_ps(r.inv[a]);
      const int lo = static_cast<int>(offsetof(Node8, lo) + a * sizeof(Node8::lo[0]));
      const int hi = static_cast<int>(offsetof(Node8, hi) + a * sizeof(Node8::hi[0]));
      enter[a] = r.negative[a] ? hi : lo, exit[a] = r.negative[a] ? lo : hi;
    }
  }
};

/// Slab test of the eight child boxes against (tmin, tmax), the float operations of the 4-wide test; bit c of
/// the result is set when child c is hit, tn[c] its entry distance.
[[gnu::always_inline]] inline int boxes8(const Node8& n, const Ray8& r, __m256 lo, __m256 hi, float* tn) {
  const char* base = reinterpret_cast<const char*>(&n);
  auto plane = [&](int offset) { return _mm256_load_ps(reinterpret_cast<const float*>(base + offset)); };
  lo = _mm256_max_ps(lo, _mm256_mul_ps(_mm256_sub_ps(plane(r.enter[0]), r.o[0]), r.inv[0]));
  hi = _mm256_min_ps(hi, _mm256_mul_ps(_mm256_sub_ps(plane(r.exit[0]), r.o[0]), r.inv[0]));
  lo = _mm256_max_ps(lo, _mm256_mul_ps(_mm256_sub_ps(plane(r.enter[1]), r.o[1]), r.inv[1]));
  hi = _mm256_min_ps(hi, _mm256_mul_ps(_mm256_sub_ps(plane(r.exit[1]), r.o[1]), r.inv[1]));
  lo = _mm256_max_ps(lo, _mm256_mul_ps(_mm256_sub_ps(plane(r.enter[2]), r.o[2]), r.inv[2]));
  hi = _mm256_min_ps(hi, _mm256_mul_ps(_mm256_sub_ps(plane(r.exit[2]), r.o[2]), r.inv[2]));
  _mm256_store_ps(tn, lo);
  return _mm256_movemask_ps(_mm256_cmp_ps(lo, hi, _CMP_LE_OQ));
}

/// The prepared ray out of line (bvh_leaf.h inlines its constructor, which the 4-wide traversals gain from):
/// inlined into the 8-wide closest hit it made the fence's and reflective_refractive's queries 6-8 % slower.
[[gnu::noinline]] PreparedRay prepare(const Ray& ray) { return PreparedRay(ray); }

}  // namespace

void closestHit8(const Bvh8View& bvh, const Ray& ray, float tmin, Hit& hit, int& best) {
  const PreparedRay r = prepare(ray);
  const Ray8 r8(r);
  const __m256 vtmin = _mm256_set1_ps(tmin);
  int tri = -1;
  // Leaves go on the stack like inner nodes (count != 0), so they too are opened nearest first, and not at all
  // once a hit nearer than their box is found
  int32_t stack[kStack8];
  uint32_t count[kStack8];
  float near[kStack8];
  int top = 0;
  int32_t cur = 0;  // the entry being visited: a node (curCount 0) or a leaf
  uint32_t curCount = 0;
  while (true) {
    if (curCount != 0) {
      leafClosest(cur, curCount, r, bvh.items, bvh.packs, tmin, hit, best, tri);
    } else {
      const Node8& n = bvh.nodes[cur];
      alignas(32) float tn[8];
      int mask = boxes8(n, r8, vtmin, _mm256_set1_ps(hit.t), tn);
      // Hit children sorted far to near; all but the nearest pushed, the nearest visited next (as if pushed
      // and popped at once)
      int idx[8], k = 0;
      for (; mask; mask &= mask - 1) {
        const int c = __builtin_ctz(mask);
        if (n.child[c] < 0) continue;
        int j = k++;
        while (j > 0 && tn[idx[j - 1]] < tn[c]) idx[j] = idx[j - 1], --j;
        idx[j] = c;
      }
      if (k > 0) {
        for (int m = 0; m < k - 1; ++m) {
          const int c = idx[m];
          stack[top] = n.child[c], count[top] = n.count[c], near[top++] = tn[c];
        }
        cur = n.child[idx[k - 1]], curCount = n.count[idx[k - 1]];
        continue;
      }
    }
    do {  // pop the nearest entry still in front of the closest hit
      if (top == 0) {
        finishClosest(bvh.items, tri, hit);
        return;
      }
      --top;
    } while (near[top] > hit.t);
    cur = stack[top], curCount = count[top];
  }
}

bool anyHit8(const Bvh8View& bvh, const Ray& ray, float tmin, float tmax) {
  const PreparedRay r = prepare(ray);
  const Ray8 r8(r);
  const __m256 vtmin = _mm256_set1_ps(tmin), vtmax = _mm256_set1_ps(tmax);
  int stack[kStack8];
  int top = 0;
  stack[top++] = 0;
  while (top > 0) {
    const Node8& n = bvh.nodes[stack[--top]];
    alignas(32) float tn[8];
    for (int mask = boxes8(n, r8, vtmin, vtmax, tn); mask; mask &= mask - 1) {
      const int c = __builtin_ctz(mask);
      if (n.child[c] < 0) continue;
      if (n.count[c] == 0) stack[top++] = n.child[c];
      else if (leafAny(n.child[c], n.count[c], r, bvh.items, bvh.packs, tmin, tmax)) return true;
    }
  }
  return false;
}

}  // namespace aliaslab::bvhimpl
