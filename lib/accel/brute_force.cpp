// Brute force: every flattened primitive, in order. The reference that the
// grid must reproduce exactly.
#include "accel/aggregate.h"

namespace aliaslab {
namespace {

class BruteForce final : public Aggregate {
 public:
  explicit BruteForce(const Object& root) { root.flatten(Mat4::Identity(), prims_); }

  bool intersect(const Ray& ray, float tmin, Hit& hit) const override {
    bool any = false;
    for (size_t i = 0; i < prims_.size(); ++i)
      if (prims_[i]->intersect(ray, tmin, hit)) {
        hit.primitive = static_cast<int>(i);
        any = true;
      }
    return any;
  }

  bool occluded(const Ray& ray, float tmin, float tmax) const override {
    for (const auto& p : prims_) {
      Hit h;
      h.t = tmax;
      if (p->intersect(ray, tmin, h)) return true;
    }
    return false;
  }

  AggregateStats stats() const override {
    AggregateStats s;
    s.primitives = prims_.size();
    for (const auto& p : prims_) s.unbounded += p->bounded() ? 0 : 1;
    return s;
  }

  std::string describe() const override { return "brute force " + std::to_string(prims_.size()) + " prims"; }

 private:
  ObjectList prims_;
};

}  // namespace

std::unique_ptr<Aggregate> makeBruteForce(const Object& root) { return std::make_unique<BruteForce>(root); }

}  // namespace aliaslab
