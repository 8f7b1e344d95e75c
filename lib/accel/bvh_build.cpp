// The build of the bounding volume hierarchy (layout in bvh.h): a binary tree by binned SAH over
// primitive centroids, collapsed into 4-wide nodes with triangle-only leaves packed as TriPacks; boxes
// padded like the grid's so that the float slab test never drops a box a hit lies in.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <vector>

#include "accel/bvh.h"
#include "geometry/primitives.h"

namespace aliaslab::bvhimpl {
namespace {

constexpr int kBins = 32, kMaxLeaf = 4;

/// Leaf tests a set of n primitives costs: one per pack of (up to) four, tested at once.
float blocks(int n) { return static_cast<float>((n + kMaxLeaf - 1) / kMaxLeaf); }

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

/// The build's state: the items in leaf order and the nodes and packs collapsed so far.
class Builder {
 public:
  Builder(const Object& root, int width) {
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
      std::vector<int> itemOf;
      {
        const std::vector<Reference> refs = presplit(items_, boxes);
        boxes.clear();
        for (const Reference& r : refs) boxes.push_back(r.box), itemOf.push_back(r.item);
      }
      for (auto& b : boxes) b.min.array() -= pad, b.max.array() += pad;
      std::vector<int> order(boxes.size());
      for (size_t i = 0; i < order.size(); ++i) order[i] = static_cast<int>(i);
      std::vector<Vec3> centroids(boxes.size());
      for (size_t i = 0; i < boxes.size(); ++i) centroids[i] = 0.5f * (boxes[i].min + boxes[i].max);
      std::vector<BinaryNode> bin;
      bin.reserve(2 * boxes.size());
      bin.push_back({});
      split(0, 0, static_cast<int>(order.size()), order, boxes, centroids, bin);
      std::vector<Item> sorted(order.size());
      for (size_t i = 0; i < order.size(); ++i) sorted[i] = items_[itemOf[order[i]]];
      items_.swap(sorted);
      // one binary tree, collapsed into the width(s) asked for: both share the items; each appends its own packs
      // (in its own visiting order, as when built alone)
      if (width != 8) nodes_.reserve(bin.size() / 2 + 1), collapse(0, bin, nodes_);
      if (width != 4) nodes8_.reserve(bin.size() / 4 + 1), collapse(0, bin, nodes8_);
    }
    buildSeconds_ = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  }

  BvhLayout take() && {
    return {std::move(prims_), std::move(unbounded_), std::move(items_), std::move(nodes_), std::move(nodes8_),
            std::move(packs_), buildSeconds_};
  }

 private:
  /// Binned SAH split of order[start, end) into bin[node].
  void split(int node, int start, int end, std::vector<int>& order, const std::vector<BBox>& boxes,
             const std::vector<Vec3>& centroids, std::vector<BinaryNode>& bin) {
    BBox box, cbox;
    for (int i = start; i < end; ++i) box.extend(boxes[order[i]]), cbox.extend(centroids[order[i]]);
    bin[node].box = box, bin[node].start = start, bin[node].count = end - start;
    const int n = end - start;
    if (n <= kMaxLeaf) return;  // a leaf: its (up to) four triangles are tested at once
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
        const float cost = area(acc) * blocks(c) + rightArea[b + 1] * blocks(rightCount[b + 1]);
        if (cost < bestCost) bestCost = cost, bestAxis = a, bestSplit = b;
      }
    }
    int mid;
    if (bestAxis < 0) {  // all centroids equal: split by count
      mid = start + n / 2;
    } else {
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

  /// Node of Node::kWidth children for binary node b (an inner node); returns its index.
  template <class Node>
  int collapse(int b, const std::vector<BinaryNode>& bin, std::vector<Node>& nodes) {
    constexpr int W = Node::kWidth;
    std::vector<int> kids;
    if (bin[b].left < 0) kids = {b};  // the root is a leaf
    else kids = {bin[b].left, bin[b].right};
    while (kids.size() < static_cast<size_t>(W)) {
      int pick = -1;
      float bestArea = -1.f;
      for (size_t i = 0; i < kids.size(); ++i)
        if (bin[kids[i]].left >= 0 && area(bin[kids[i]].box) > bestArea) bestArea = area(bin[kids[i]].box), pick = static_cast<int>(i);
      if (pick < 0) break;
      const int k = kids[pick];
      kids[pick] = bin[k].left;
      kids.push_back(bin[k].right);
    }
    const int index = static_cast<int>(nodes.size());
    nodes.push_back({});
    for (int c = 0; c < W; ++c) {
      Node& n = nodes[index];
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
            p.item[e] = k.start + std::min(e, k.count - 1), p.prim[e] = it.prim;
            for (int a = 0; a < 3; ++a) p.a[a][e] = it.a[a], p.b[a][e] = it.b[a], p.c[a][e] = it.c[a];
          }
          n.child[c] = static_cast<int32_t>(packs_.size()), n.count[c] = kPacked | static_cast<uint32_t>(k.count);
          packs_.push_back(p);
        }
      } else {
        n.count[c] = 0;
        const int child = collapse(kids[c], bin, nodes);
        nodes[index].child[c] = child;
      }
    }
    return index;
  }

  ObjectList prims_;
  std::vector<int> unbounded_;
  std::vector<Item> items_;
  std::vector<Node4> nodes_;
  std::vector<Node8> nodes8_;
  std::vector<TriPack> packs_;  ///< the triangle-only leaves
  double buildSeconds_ = 0;
};

}  // namespace

BvhLayout buildBvh(const Object& root, int width) { return Builder(root, width).take(); }

}  // namespace aliaslab::bvhimpl
