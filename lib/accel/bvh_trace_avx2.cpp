// The 8-wide traversal of the bounding volume hierarchy (bvh.h): a ray against eight child boxes per AVX
// instruction, the leaves tested as the 4-wide traversal tests them (bvh_leaf.h), so both give the same hits.
// This file alone is built with -mavx2 (CMakeLists.txt); bvh_trace.cpp calls it only where the CPU has AVX2.
// It shares code with the other translation units only through unnamed-namespace, always-inlined functions
// (bvh_leaf.h) and the layout's plain structs, so no AVX2 code can stand in for theirs at link time.
#include <immintrin.h>

#include "accel/bvh_leaf.h"

namespace aliaslab::bvhimpl {
namespace {

constexpr int kStack8 = 256;  ///< up to 7 more entries per level

/// The ray's origin and reciprocal direction on eight lanes, and which slab face it enters through.
struct Ray8 {
  __m256 o[3], inv[3];
  bool negative[3];
  explicit Ray8(const PreparedRay& r) {
    for (int a = 0; a < 3; ++a)
      o[a] = _mm256_broadcastss_ps(r.o[a]), inv[a] = _mm256_broadcastss_ps(r.inv[a]), negative[a] = r.negative[a];
  }
};

/// Slab test of the eight child boxes against (tmin, tmax), the float operations of the 4-wide test; bit c of
/// the result is set when child c is hit, tn[c] its entry distance.
[[gnu::always_inline]] inline int boxes8(const Node8& n, const Ray8& r, __m256 lo, __m256 hi, float* tn) {
  for (int a = 0; a < 3; ++a) {  // entry through lo, exit through hi (swapped for a negative direction)
    const float* enter = r.negative[a] ? n.hi[a] : n.lo[a];
    const float* exit = r.negative[a] ? n.lo[a] : n.hi[a];
    lo = _mm256_max_ps(lo, _mm256_mul_ps(_mm256_sub_ps(_mm256_load_ps(enter), r.o[a]), r.inv[a]));
    hi = _mm256_min_ps(hi, _mm256_mul_ps(_mm256_sub_ps(_mm256_load_ps(exit), r.o[a]), r.inv[a]));
  }
  _mm256_store_ps(tn, lo);
  return _mm256_movemask_ps(_mm256_cmp_ps(lo, hi, _CMP_LE_OQ));
}

}  // namespace

void closestHit8(const Bvh8View& bvh, const Ray& ray, float tmin, Hit& hit, int& best) {
  const PreparedRay r(ray);
  const Ray8 r8(r);
  const __m256 vtmin = _mm256_set1_ps(tmin);
  // Leaves go on the stack like inner nodes (count != 0), so they too are opened nearest first, and not at all
  // once a hit nearer than their box is found
  int32_t stack[kStack8];
  uint32_t count[kStack8];
  float near[kStack8];
  int top = 0;
  stack[top] = 0, count[top] = 0, near[top++] = -kInf;
  while (top > 0) {
    --top;
    if (near[top] > hit.t) continue;
    if (count[top] != 0) {
      leafClosest(stack[top], count[top], r, bvh.items, bvh.packs, tmin, hit, best);
      continue;
    }
    const Node8& n = bvh.nodes[stack[top]];
    alignas(32) float tn[8];
    int mask = boxes8(n, r8, vtmin, _mm256_set1_ps(hit.t), tn);
    // Hit children pushed far to near, so the nearest is visited next
    int idx[8], k = 0;
    for (; mask; mask &= mask - 1) {
      const int c = __builtin_ctz(mask);
      if (n.child[c] < 0) continue;
      int j = k++;
      while (j > 0 && tn[idx[j - 1]] < tn[c]) idx[j] = idx[j - 1], --j;
      idx[j] = c;
    }
    for (int m = 0; m < k; ++m) {
      const int c = idx[m];
      stack[top] = n.child[c], count[top] = n.count[c], near[top++] = tn[c];
    }
  }
}

bool anyHit8(const Bvh8View& bvh, const Ray& ray, float tmin, float tmax) {
  const PreparedRay r(ray);
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
