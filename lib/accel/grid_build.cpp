// Grid construction: classify the flattened primitives, choose the
// resolution, and bin primitive boxes into cells (CSR).
#include <algorithm>
#include <cmath>

#include "accel/grid.h"
#include "accel/triangle_box.h"
#include "core/error.h"
#include "geometry/primitives.h"

namespace aliaslab {

Grid::Grid(const Object& root, int nx, int ny, int nz) {
  if (nx < 0 || ny < 0 || nz < 0) throw OptionError("grid", "resolution must be >= 0 (0 = automatic)");
  root.flatten(Mat4::Identity(), prims_);

  // Classify: packed triangles first, then other bounded primitives
  std::vector<int> others;
  std::vector<BBox> triBoxes, otherBoxes;
  BBox world;
  for (size_t i = 0; i < prims_.size(); ++i) {
    const Object& p = *prims_[i];
    if (!p.bounded()) {
      unbounded_.push_back(static_cast<int>(i));
      continue;
    }
    const BBox b = p.bounds();
    world.extend(b);
    if (const auto* tri = dynamic_cast<const Triangle*>(&p)) {
      tris_.push_back({tri->a, tri->b - tri->a, tri->c - tri->a});
      triMaterial_.push_back(tri->material);
      primOf_.push_back(static_cast<int>(i));
      triBoxes.push_back(b);
    } else {
      others.push_back(static_cast<int>(i));
      otherBoxes.push_back(b);
    }
  }
  numTris_ = tris_.size();
  primOf_.insert(primOf_.end(), others.begin(), others.end());
  triBoxes.insert(triBoxes.end(), otherBoxes.begin(), otherBoxes.end());
  if (triBoxes.empty()) return;  // nothing to grid: only planes (or nothing)

  // Padded bounds: a hit point may round slightly outside its primitive's box
  // (in double: at coordinates near the float limit the extent's norm overflows float, and an infinite pad made
  // every cell size NaN and the resolution a garbage int: a crash)
  const double maxAbs = std::max(world.min.cwiseAbs().maxCoeff(), world.max.cwiseAbs().maxCoeff());
  const float pad = static_cast<float>(
      std::min(1e-5 * world.extent().cast<double>().norm() + 1e-6 * maxAbs + 1e-30, 1e-3 * double(kFloatMax)));
  for (int a = 0; a < 3; ++a) {
    lo_[a] = static_cast<double>(world.min[a]) - 2 * pad;
    hi_[a] = static_cast<double>(world.max[a]) + 2 * pad;
  }
  diag_ = static_cast<float>(std::min(double(kFloatMax), std::sqrt((hi_[0] - lo_[0]) * (hi_[0] - lo_[0]) + (hi_[1] - lo_[1]) * (hi_[1] - lo_[1]) +
                                       (hi_[2] - lo_[2]) * (hi_[2] - lo_[2]))));
  chooseResolution(nx, ny, nz);
  for (auto& b : triBoxes) {
    b.min.array() -= pad;
    b.max.array() += pad;
  }
  fillCells(triBoxes, pad);
}

void Grid::chooseResolution(int nx, int ny, int nz) {
  const int given[3] = {nx, ny, nz};
  const double ext[3] = {hi_[0] - lo_[0], hi_[1] - lo_[1], hi_[2] - lo_[2]};
  const double longest = std::max({ext[0], ext[1], ext[2]});
  const double cellsLong = std::ceil(2.0 * std::cbrt(static_cast<double>(primOf_.size())));
  for (int a = 0; a < 3; ++a) {
    // Degenerate (flat) axes and the automatic choice
    const double autoN = std::round(cellsLong * ext[a] / longest);
    n_[a] = given[a] > 0 ? given[a] : static_cast<int>(std::clamp(autoN, 1.0, 256.0));
    size_[a] = ext[a] / n_[a];
    invSize_[a] = 1.0 / size_[a];
  }
  const double cells = static_cast<double>(n_[0]) * n_[1] * n_[2];
  if (cells > double(1 << 27))
    throw OptionError("grid", "at most 2^27 cells (" + std::to_string(n_[0]) + "x" + std::to_string(n_[1]) + "x" +
                                   std::to_string(n_[2]) + " requested)");
}

void Grid::fillCells(const std::vector<BBox>& boxes, float pad) {
  const size_t ncells = static_cast<size_t>(n_[0]) * n_[1] * n_[2];
  // Cell range of a box, per axis
  auto range = [&](const BBox& b, int lo[3], int hi[3]) {
    for (int a = 0; a < 3; ++a) {
      lo[a] = cellIndex((b.min[a] - lo_[a]) * invSize_[a], n_[a], 0);
      hi[a] = cellIndex((b.max[a] - lo_[a]) * invSize_[a], n_[a], n_[a] - 1);
    }
  };
  // Cells a primitive overlaps: its box range, pruned for triangles by the
  // separating-axis test against the padded cell
  auto forEachCell = [&](size_t id, auto&& f) {
    int lo[3], hi[3];
    range(boxes[id], lo, hi);
    const bool tri = id < numTris_;
    Eigen::Vector3d a, b, c;
    if (tri) {
      a = tris_[id].a.cast<double>();
      b = a + tris_[id].e1.cast<double>();
      c = a + tris_[id].e2.cast<double>();
    }
    const Eigen::Vector3d half = 0.5 * Eigen::Vector3d(size_[0], size_[1], size_[2]) + Eigen::Vector3d::Constant(2.0 * pad);
    for (int z = lo[2]; z <= hi[2]; ++z)
      for (int y = lo[1]; y <= hi[1]; ++y)
        for (int x = lo[0]; x <= hi[0]; ++x) {
          const Eigen::Vector3d center(lo_[0] + (x + 0.5) * size_[0], lo_[1] + (y + 0.5) * size_[1],
                                       lo_[2] + (z + 0.5) * size_[2]);
          if (tri && !triangleOverlapsBox(a, b, c, center, half)) continue;
          f(static_cast<size_t>(x) + n_[0] * (static_cast<size_t>(y) + n_[1] * z));
        }
  };

  // Count, prefix-sum, fill
  cellStart_.assign(ncells + 1, 0);
  for (size_t id = 0; id < boxes.size(); ++id) forEachCell(id, [&](size_t c) { ++cellStart_[c + 1]; });
  occupied_.assign((ncells + 63) / 64, 0);
  for (size_t c = 0; c < ncells; ++c) {
    if (cellStart_[c + 1] > 0) occupied_[c >> 6] |= uint64_t{1} << (c & 63);
    cellStart_[c + 1] += cellStart_[c];
  }
  refs_.resize(cellStart_[ncells]);
  std::vector<uint32_t> cursor(cellStart_.begin(), cellStart_.end() - 1);
  for (size_t id = 0; id < boxes.size(); ++id)
    forEachCell(id, [&](size_t c) { refs_[cursor[c]++] = static_cast<uint32_t>(id); });
}

AggregateStats Grid::stats() const {
  AggregateStats s;
  s.primitives = prims_.size();
  s.unbounded = unbounded_.size();
  s.cells = {n_[0], n_[1], n_[2]};
  s.references = refs_.size();
  return s;
}

std::string Grid::describe() const {
  return "grid " + std::to_string(n_[0]) + "x" + std::to_string(n_[1]) + "x" + std::to_string(n_[2]) + ", " +
         std::to_string(refs_.size()) + " refs";
}

std::unique_ptr<Aggregate> makeGrid(const Object& root, int nx, int ny, int nz) {
  return std::make_unique<Grid>(root, nx, ny, nz);
}

}  // namespace aliaslab
