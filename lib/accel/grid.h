// Private to accel/: the uniform grid behind makeGrid().
//
// Layout: the flattened primitives are split into triangles (packed as
// vertex + edges, tested inline), other bounded primitives (virtual call)
// and unbounded ones (planes, tested before marching). Cells hold "local
// ids" in one flat array with per-cell offsets (CSR): ids below the number
// of triangles index the packed triangles, the rest the other primitives.
//
// Exactness: the packed test is the same inline code Triangle::intersect
// runs, so t is bit-identical to brute force; ties in t go to the lower
// flattened index, as brute force's strict "t < hit.t" in list order does.
// Primitive boxes are padded, DDA crossings are computed in double, and
// marching stops only once the best t is a small tolerance before the
// current cell's exit, so no closer hit can lie in an unvisited cell.
// Any finite coordinates are safe: extents and cell positions are computed
// in double and cell indices clamped before conversion (cellIndex), so a
// sphere of radius 1e19 or OBJ vertices at 1e38 give brute force's image.
// A small per-ray mailbox skips re-testing a triangle met in an earlier cell
// (the repeated test would give the same t against a bound that only shrinks).
#pragma once
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

#include "accel/aggregate.h"
#include "geometry/triangle_math.h"

namespace aliaslab {

inline constexpr double kFloatMax = 3.4028234663852886e38;

/// The cell of a position in cell units, clamped to [0, n-1] before conversion (a double beyond int's range,
/// +-inf or NaN is undefined behaviour in a cast): NaN gives `ifNaN`. Finite input of any size is safe.
inline int cellIndex(double cells, int n, int ifNaN) {
  if (std::isnan(cells)) return ifNaN;
  return static_cast<int>(std::clamp(std::floor(cells), 0.0, static_cast<double>(n - 1)));
}

class Grid final : public Aggregate {
 public:
  /// Resolution per axis; 0 = automatic (ceil(2 cbrt(N)) along the longest axis).
  Grid(const Object& root, int nx, int ny, int nz);

  bool intersect(const Ray& ray, float tmin, Hit& hit) const override;
  bool occluded(const Ray& ray, float tmin, float tmax) const override;
  AggregateStats stats() const override;
  std::string describe() const override;

 private:
  void chooseResolution(int nx, int ny, int nz);
  void fillCells(const std::vector<BBox>& boxes, float pad);
  /// Visits the cells the ray crosses for t in [t0, t1], in order, calling
  /// visit(cell, tExit); stops when visit returns true.
  template <class Visit>
  void march(const Ray& ray, double t0, double t1, Visit&& visit) const;
  /// A tolerance in t for decisions near cell boundaries.
  float tolerance(const Ray& ray) const;

  ObjectList prims_;                    ///< flattened world-space primitives
  std::vector<int> unbounded_;          ///< flattened indices of planes etc.
  std::vector<TriangleEdges> tris_;     ///< packed triangles, by local id
  std::vector<const Material*> triMaterial_;
  std::vector<int> primOf_;             ///< local id -> flattened index
  size_t numTris_ = 0;

  int n_[3] = {0, 0, 0};                ///< cells per axis (all 0: no bounded primitives)
  double lo_[3] = {0, 0, 0}, hi_[3] = {0, 0, 0};
  double size_[3] = {1, 1, 1}, invSize_[3] = {1, 1, 1};
  float diag_ = 0.f;                    ///< length of the grid box diagonal
  std::vector<uint32_t> cellStart_;     ///< CSR offsets, ncells + 1
  std::vector<uint32_t> refs_;          ///< local ids per cell
  std::vector<uint64_t> occupied_;      ///< one bit per cell: has references (cache-friendly emptiness test)
};

}  // namespace aliaslab
