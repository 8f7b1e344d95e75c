// Private to accel/: the leaf tests of the bounding volume hierarchy, shared by the 4-wide traversal
// (bvh_trace.cpp, built for any x86-64-v2 CPU) and the 8-wide one (bvh_trace_avx2.cpp, built with -mavx2), so
// both run the same float operations in the same order and return the same hits, t to the last bit (-mavx2
// does not allow FMA contraction). Everything here is in an unnamed namespace and always inlined: each
// translation unit has its own copy, so no AVX2-encoded copy can stand in for the other's at link time.
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
// accepted ones' Moller-Trumbore t is computed for the four at once too (same operations per lane).
// Closest hit: t in (tmin, hit.t), ties in t to the lower flattened index
// (as brute force's list order gives), whatever order nodes are visited in; the winner's normal and
// material are filled in once, at the end.
#pragma once
#include <xmmintrin.h>

#include <algorithm>
#include <cmath>
#include <cstdint>

#include "accel/bvh.h"
#include "geometry/primitives.h"
#include "geometry/triangle_math.h"

namespace aliaslab::bvhimpl {
namespace {

/// A ray prepared for both box and watertight triangle tests.
struct PreparedRay {
  const Ray* ray;
  __m128 o[3], inv[3], dir[3];  ///< origin, clamped reciprocal and raw direction, broadcast
  bool negative[3];  ///< direction component < 0: the slab is entered through hi
  int kx, ky, kz;
  float sx, sy;
  __m128 okx, oky, okz, vsx, vsy;  ///< origin along kx, ky, kz and the shears, broadcast (pack test)
  /// Vectorised (one division for the three reciprocals, one for both shears), the same bits per lane as
  /// the scalar 1 / d and d[kx] / d[kz]; directions below 1e-30 in magnitude are clamped to +-1e-30.
  [[gnu::always_inline]] explicit PreparedRay(const Ray& r) : ray(&r) {
    const Vec3& d = r.direction;
    const __m128 dv = _mm_setr_ps(d[0], d[1], d[2], 1.f), ov = _mm_setr_ps(r.origin[0], r.origin[1], r.origin[2], 0.f);
    const __m128 signBit = _mm_set1_ps(-0.f), tiny = _mm_set1_ps(1e-30f);
    const __m128 small = _mm_cmplt_ps(_mm_andnot_ps(signBit, dv), tiny);
    const __m128 dc = _mm_or_ps(_mm_andnot_ps(small, dv), _mm_and_ps(small, _mm_or_ps(tiny, _mm_and_ps(signBit, dv))));
    const __m128 iv = _mm_div_ps(_mm_set1_ps(1.f), dc);
    const int neg = _mm_movemask_ps(_mm_cmplt_ps(dc, _mm_setzero_ps()));
    o[0] = _mm_shuffle_ps(ov, ov, 0x00), o[1] = _mm_shuffle_ps(ov, ov, 0x55), o[2] = _mm_shuffle_ps(ov, ov, 0xaa);
    inv[0] = _mm_shuffle_ps(iv, iv, 0x00), inv[1] = _mm_shuffle_ps(iv, iv, 0x55), inv[2] = _mm_shuffle_ps(iv, iv, 0xaa);
    dir[0] = _mm_shuffle_ps(dv, dv, 0x00), dir[1] = _mm_shuffle_ps(dv, dv, 0x55), dir[2] = _mm_shuffle_ps(dv, dv, 0xaa);
    for (int a = 0; a < 3; ++a) negative[a] = (neg >> a) & 1;
    const Vec3 ad = d.cwiseAbs();
    kz = ad.x() > ad.y() ? (ad.x() > ad.z() ? 0 : 2) : (ad.y() > ad.z() ? 1 : 2);
    const int next = kz == 2 ? 0 : kz + 1, after = next == 2 ? 0 : next + 1;
    const bool flip = d[kz] < 0.f;  // keep the winding: swap kx and ky (selects, not a branch)
    kx = flip ? after : next, ky = flip ? next : after;
    const __m128 s = _mm_div_ps(_mm_setr_ps(d[kx], d[ky], 0.f, 0.f), _mm_set1_ps(d[kz]));
    sx = _mm_cvtss_f32(s), sy = _mm_cvtss_f32(_mm_shuffle_ps(s, s, 0x55));
    okx = _mm_set1_ps(r.origin[kx]), oky = _mm_set1_ps(r.origin[ky]), okz = _mm_set1_ps(r.origin[kz]);
    vsx = _mm_shuffle_ps(s, s, 0x00), vsy = _mm_shuffle_ps(s, s, 0x55);
  }
};

/// Woop-Benthin-Wald: does the ray's line pass through the triangle
/// (edges and vertices included)? Direction-agnostic in t; t is checked later.
[[gnu::always_inline]] inline bool watertightHit(const PreparedRay& r, const Item& it) {
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
/// same float operations in the same order per lane up to the edge functions u, v, w (so the same values);
/// then, per lane: all three nonzero and not NaN (their product neither zero nor NaN, a test that may also
/// flag a lane whose product underflows) -> the scalar test's answer is "inside" exactly when the three share
/// a sign (their sum is then nonzero: same-signed floats cannot add to zero), read from the sign bits
/// ((u ^ v) | (u ^ w)); a flagged lane is decided by the scalar test (its double recomputation), as before.
[[gnu::always_inline]] inline int watertightHits(const PreparedRay& r, const TriPack& p, const Item* items) {
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
  const __m128 product = _mm_andnot_ps(_mm_set1_ps(-0.f), _mm_mul_ps(_mm_mul_ps(u, v), w));
  const int valid = (1 << p.n) - 1;
  int exact = _mm_movemask_ps(_mm_cmpngt_ps(product, _mm_setzero_ps())) & valid;  // zero or NaN
  const int mixed = _mm_movemask_ps(_mm_or_ps(_mm_xor_ps(u, v), _mm_xor_ps(u, w)));
  int mask = ~mixed & ~exact & valid;
  while (exact) {
    const int l = __builtin_ctz(exact);
    exact &= exact - 1;
    if (watertightHit(r, items[p.item[l]])) mask |= 1 << l;
  }
  return mask;
}

/// Moller-Trumbore's t, the exact expressions of intersectTriangle().
[[gnu::always_inline]] inline bool mollerTrumboreT(const Ray& ray, const Item& it, float& t) {
  const Vec3 p = ray.direction.cross(it.e2);
  const float det = it.e1.dot(p);
  if (det == 0.f) return false;
  const float inv = 1.f / det;
  const Vec3 s = ray.origin - it.a;
  const Vec3 q = s.cross(it.e1);
  t = it.e2.dot(q) * inv;
  return true;
}

/// mollerTrumboreT() for the four lanes of a pack at once: the same float operations in the same order per
/// lane (Eigen's cross products; its 3-term dot products sum as x + (y + z)), so t has the same bits; the
/// edges b - a and c - a are recomputed from the vertices exactly as the build computed them. Returns the
/// lanes where det != 0 (the others' t is meaningless).
[[gnu::always_inline]] inline int packT(const PreparedRay& r, const TriPack& p, __m128& t) {
  __m128 e1[3], e2[3], s[3];
  for (int k = 0; k < 3; ++k) {
    const __m128 a = _mm_load_ps(p.a[k]);
    e1[k] = _mm_sub_ps(_mm_load_ps(p.b[k]), a), e2[k] = _mm_sub_ps(_mm_load_ps(p.c[k]), a);
    s[k] = _mm_sub_ps(r.o[k], a);
  }
  auto cross = [](const __m128* x, const __m128* y, __m128* out) {
    out[0] = _mm_sub_ps(_mm_mul_ps(x[1], y[2]), _mm_mul_ps(x[2], y[1]));
    out[1] = _mm_sub_ps(_mm_mul_ps(x[2], y[0]), _mm_mul_ps(x[0], y[2]));
    out[2] = _mm_sub_ps(_mm_mul_ps(x[0], y[1]), _mm_mul_ps(x[1], y[0]));
  };
  auto dot = [](const __m128* x, const __m128* y) {
    return _mm_add_ps(_mm_mul_ps(x[0], y[0]), _mm_add_ps(_mm_mul_ps(x[1], y[1]), _mm_mul_ps(x[2], y[2])));
  };
  __m128 pv[3], q[3];
  cross(r.dir, e2, pv);
  const __m128 det = dot(e1, pv);
  cross(s, e1, q);
  t = _mm_mul_ps(dot(e2, q), _mm_div_ps(_mm_set1_ps(1.f), det));
  return _mm_movemask_ps(_mm_cmpneq_ps(det, _mm_setzero_ps()));
}

/// The closest hit so far: hit.t and best (flattened index, -1: none), and tri, its item when it is a triangle
/// (-1: none or another primitive, whose intersect() filled hit's normal and material). A triangle's normal
/// and material are filled in once, at the end, by finishClosest().
[[gnu::always_inline]] inline void finishClosest(const Item* items, int tri, Hit& hit) {
  if (tri < 0) return;
  hit.normal = triangleNormal(items[tri].e1, items[tri].e2);
  hit.material = items[tri].material;
}

/// A primitive with its own intersect(): a tie in t goes to the lower index. intersect() leaves hit untouched
/// on a miss (geometry/object.h), so hit is passed straight in unless a tie must be let through (a copy
/// costs a store-forwarding stall per query on scenes with a plane).
[[gnu::always_inline]] inline void testObject(const Object& obj, int prim, const Ray& ray, float tmin, Hit& hit,
                                              int& best, int& tri) {
  if (best >= 0 && prim < best) {
    Hit h = hit;
    h.t = std::nextafter(hit.t, kInf);
    if (obj.intersect(ray, tmin, h)) hit = h, best = prim, tri = -1;
  } else if (obj.intersect(ray, tmin, hit)) {
    best = prim, tri = -1;
  }
}

/// A triangle with t computed (det != 0): taken when tmin < t and (t, prim) is below (hit.t, best), i.e. ties
/// in t to the lower index, so the result does not depend on the order triangles are tested in.
[[gnu::always_inline]] inline void acceptT(float t, int prim, int item, float tmin, Hit& hit, int& best,
                                           int& tri) {
  if (!(t > tmin)) return;
  if (!(t < hit.t || (t == hit.t && best >= 0 && prim < best))) return;
  hit.t = t, best = prim, tri = item;
}

/// Closest hit within a leaf: child and count as a node stores them (count | kPacked: a TriPack).
[[gnu::always_inline]] inline void leafClosest(int32_t child, uint32_t count, const PreparedRay& r,
                                               const Item* items, const TriPack* packs, float tmin, Hit& hit,
                                               int& best, int& tri) {
  if (count & kPacked) {
    const TriPack& p = packs[child];
    int mask = watertightHits(r, p, items);
    if (!mask) return;
    __m128 tv;
    mask &= packT(r, p, tv);
    alignas(16) float t[4];
    _mm_store_ps(t, tv);
    for (; mask; mask &= mask - 1) {
      const int l = __builtin_ctz(mask);
      acceptT(t[l], p.prim[l], p.item[l], tmin, hit, best, tri);
    }
    return;
  }
  for (uint32_t e = 0; e < count; ++e) {
    const Item& it = items[child + e];
    float t;
    if (it.obj) testObject(*it.obj, it.prim, *r.ray, tmin, hit, best, tri);
    else if (watertightHit(r, it) && mollerTrumboreT(*r.ray, it, t))
      acceptT(t, it.prim, static_cast<int>(child + e), tmin, hit, best, tri);
  }
}

/// Any hit with tmin < t < tmax within a leaf.
[[gnu::always_inline]] inline bool leafAny(int32_t child, uint32_t count, const PreparedRay& r, const Item* items,
                                           const TriPack* packs, float tmin, float tmax) {
  const Ray& ray = *r.ray;
  if (count & kPacked) {
    const TriPack& p = packs[child];
    int mask = watertightHits(r, p, items);
    if (!mask) return false;
    __m128 t;
    mask &= packT(r, p, t);
    const __m128 inside = _mm_and_ps(_mm_cmpgt_ps(t, _mm_set1_ps(tmin)), _mm_cmplt_ps(t, _mm_set1_ps(tmax)));
    return (mask & _mm_movemask_ps(inside)) != 0;
  }
  for (uint32_t e = 0; e < count; ++e) {
    const Item& it = items[child + e];
    if (it.obj) {
      Hit h;
      h.t = tmax;
      if (it.obj->intersect(ray, tmin, h)) return true;
    } else {
      float t;
      if (watertightHit(r, it) && mollerTrumboreT(ray, it, t) && t > tmin && t < tmax) return true;
    }
  }
  return false;
}

}  // namespace
}  // namespace aliaslab::bvhimpl
