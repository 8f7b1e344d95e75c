// Grid queries: 3D-DDA marching (Amanatides & Woo 1987) with crossings in
// double precision, closest-hit (with a per-ray mailbox) and any-hit visitors.
#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>

#include "accel/grid.h"

namespace aliaslab {

namespace {

constexpr int kMailbox = 16;  ///< direct-mapped per-ray mailbox slots (power of two)

/// The next float above x (x finite or +inf; +inf stays +inf).
inline float nextUp(float x) {
  if (!(x < kInf)) return x;
  if (x == 0.f) return std::numeric_limits<float>::denorm_min();
  const uint32_t bits = std::bit_cast<uint32_t>(x);
  return std::bit_cast<float>(x > 0.f ? bits + 1 : bits - 1);
}

}  // namespace

float Grid::tolerance(const Ray& ray) const {
  const float len = ray.direction.norm();
  return len > 0.f ? 1e-5f * diag_ / len : 0.f;
}

template <class Visit>
void Grid::march(const Ray& ray, double t0, double t1, Visit&& visit) const {
  if (n_[0] == 0) return;
  double o[3], d[3], inv[3];
  // Clip [t0, t1] to the grid box
  for (int a = 0; a < 3; ++a) {
    o[a] = ray.origin[a];
    d[a] = ray.direction[a];
    if (d[a] == 0.0) {
      if (o[a] < lo_[a] || o[a] > hi_[a]) return;
      inv[a] = 0.0;
      continue;
    }
    inv[a] = 1.0 / d[a];
    double ta = (lo_[a] - o[a]) * inv[a], tb = (hi_[a] - o[a]) * inv[a];
    if (ta > tb) std::swap(ta, tb);
    t0 = std::max(t0, ta);
    t1 = std::min(t1, tb);
  }
  if (!(t0 <= t1) || !std::isfinite(t0)) return;  // missed, or a zero direction

  // Start cell, made consistent with the crossing times used below
  int cell[3], step[3];
  double next[3];
  auto boundary = [&](int a, int c) { return ((lo_[a] + c * size_[a]) - o[a]) * inv[a]; };
  for (int a = 0; a < 3; ++a) {
    const double p = d[a] == 0.0 ? o[a] : o[a] + t0 * d[a];
    int c = cellIndex((p - lo_[a]) * invSize_[a], n_[a], 0);
    if (d[a] > 0.0) {
      while (c > 0 && boundary(a, c) > t0) --c;
      while (c < n_[a] - 1 && boundary(a, c + 1) <= t0) ++c;
      step[a] = 1;
      next[a] = boundary(a, c + 1);
    } else if (d[a] < 0.0) {
      while (c < n_[a] - 1 && boundary(a, c + 1) > t0) ++c;
      while (c > 0 && boundary(a, c) <= t0) --c;
      step[a] = -1;
      next[a] = boundary(a, c);
    } else {
      step[a] = 0;
      next[a] = kInf;
    }
    cell[a] = c;
  }

  // March: crossing times advance by whole cells (exact enough in double)
  double delta[3];
  int stride[3] = {1, n_[0], n_[0] * n_[1]}, left[3];
  for (int a = 0; a < 3; ++a) {
    delta[a] = step[a] == 0 ? kInf : size_[a] * std::abs(inv[a]);
    left[a] = step[a] > 0 ? n_[a] - 1 - cell[a] : cell[a];  // steps before leaving the grid
    stride[a] *= step[a];
  }
  uint32_t index = static_cast<uint32_t>(cell[0] + n_[0] * (cell[1] + n_[1] * cell[2]));
  // One axis per step, kept in registers: nearest crossing first
  auto advance = [&](double& nextA, double deltaA, int strideA, int& leftA) {
    const double tExit = nextA;
    if (visit(index, tExit < t1 ? tExit : t1) || tExit >= t1 || leftA-- == 0) return true;
    index += strideA;
    nextA += deltaA;
    return false;
  };
  double n0 = next[0], n1 = next[1], n2 = next[2];
  for (;;) {
    if (n0 < n1 && n0 < n2) {
      if (advance(n0, delta[0], stride[0], left[0])) return;
    } else if (n1 < n2) {
      if (advance(n1, delta[1], stride[1], left[1])) return;
    } else if (advance(n2, delta[2], stride[2], left[2])) {
      return;
    }
  }
}

bool Grid::intersect(const Ray& ray, float tmin, Hit& hit) const {
  if (n_[0] == 0) {  // only unbounded primitives: brute force over them
    bool any = false;
    for (int prim : unbounded_)
      if (prims_[prim]->intersect(ray, tmin, hit)) {
        hit.primitive = prim;
        any = true;
      }
    return any;
  }
  // Best so far: the caller's bound first (ties with it are not accepted)
  Hit best = hit;
  int bestPrim = -1, bestTri = -1;
  float tLimit = nextUp(best.t);
  const float tol = tolerance(ray);
  double stopAt = static_cast<double>(best.t) + tol + 1e-5 * std::abs(best.t);  // stop once a cell exits beyond
  auto tryObject = [&](int prim) {
    Hit h = best;
    h.t = tLimit;
    if (prims_[prim]->intersect(ray, tmin, h) && (h.t < best.t || prim < bestPrim)) {
      best = h;
      bestPrim = prim;
      bestTri = -1;
      tLimit = nextUp(best.t);
      stopAt = static_cast<double>(best.t) + tol + 1e-5 * std::abs(best.t);
    }
  };

  // Mailbox: a triangle spanning several cells is tested once per ray (a
  // repeated test would give the same t, and tLimit only decreases)
  uint32_t mailbox[kMailbox];
  std::fill(std::begin(mailbox), std::end(mailbox), ~uint32_t{0});

  // Unbounded primitives, then the grid
  for (int prim : unbounded_) tryObject(prim);
  march(ray, tmin, stopAt, [&](uint32_t c, double tExit) {
    if (!((occupied_[c >> 6] >> (c & 63)) & 1)) return stopAt < tExit;  // empty cell
    for (uint32_t k = cellStart_[c], end = cellStart_[c + 1]; k < end; ++k) {
      const uint32_t id = refs_[k];
      if (id < numTris_) {
        uint32_t& slot = mailbox[id & (kMailbox - 1)];
        if (slot == id) continue;
        slot = id;
        const TriangleEdges& tr = tris_[id];
        float t;
        if (intersectTriangle(ray, tr.a, tr.e1, tr.e2, tmin, tLimit, t) && (t < best.t || primOf_[id] < bestPrim)) {
          best.t = t;
          bestPrim = primOf_[id];
          bestTri = static_cast<int>(id);
          tLimit = nextUp(t);
          stopAt = static_cast<double>(t) + tol + 1e-5 * std::abs(t);
        }
      } else {
        tryObject(primOf_[id]);
      }
    }
    return stopAt < tExit;
  });

  if (bestPrim < 0) return false;
  if (bestTri >= 0) {
    best.normal = triangleNormal(tris_[bestTri].e1, tris_[bestTri].e2);
    best.material = triMaterial_[bestTri];
  }
  best.primitive = bestPrim;
  hit = best;
  return true;
}

bool Grid::occluded(const Ray& ray, float tmin, float tmax) const {
  for (int prim : unbounded_) {
    Hit h;
    h.t = tmax;
    if (prims_[prim]->intersect(ray, tmin, h)) return true;
  }
  bool blocked = false;
  march(ray, tmin, static_cast<double>(tmax) + tolerance(ray), [&](uint32_t c, double) {
    for (uint32_t k = cellStart_[c], end = cellStart_[c + 1]; k < end && !blocked; ++k) {
      const uint32_t id = refs_[k];
      if (id < numTris_) {
        float t;
        blocked = intersectTriangle(ray, tris_[id].a, tris_[id].e1, tris_[id].e2, tmin, tmax, t);
      } else {
        Hit h;
        h.t = tmax;
        blocked = prims_[primOf_[id]]->intersect(ray, tmin, h);
      }
    }
    return blocked;
  });
  return blocked;
}

}  // namespace aliaslab
