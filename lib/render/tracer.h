// Whitted-style shading: ambient + direct light (with optional shadow rays)
// + mirror reflection + refraction with total internal reflection.
#pragma once
#include <atomic>
#include <cstdint>

#include "accel/aggregate.h"
#include "scene/scene.h"

namespace aliaslab {

struct TraceOptions {
  bool shadows = false;     ///< -shadows: cast shadow rays (transparent objects shadow as opaque)
  int bounces = 0;          ///< -bounces n: maximum reflection/refraction depth
  float weight = 0.f;       ///< -weight w: stop a ray whose accumulated weight falls below w
  bool shadeBack = false;   ///< -shade_back: flip the normal when a ray hits a back face
  float epsilon = 1e-3f;    ///< offset of secondary-ray origins along the ray, in scene units
};

/// Ray counts for -stats (relaxed atomics; totals do not affect images).
struct TraceCounters {
  std::atomic<uint64_t> primary{0}, shadow{0}, reflected{0}, refracted{0};
};

class Tracer {
 public:
  Tracer(const Scene& scene, const Aggregate& aggregate, const TraceOptions& options);

  /// Radiance arriving along `ray` (hits with t > tmin); `depth` counts
  /// bounces so far, `weight` the accumulated reflective/transparent weight,
  /// `ior` the index of refraction of the medium the ray travels in. `hit`
  /// receives the first hit (for depth and normal images).
  Color trace(const Ray& ray, float tmin, int depth, float weight, float ior, Hit& hit) const;

  /// Radiance through film position (fx, fy) of a width x height image.
  Color radianceAt(float fx, float fy, int width, int height) const;

  const Scene& scene() const { return scene_; }
  const Aggregate& aggregate() const { return aggregate_; }
  const TraceOptions& options() const { return options_; }
  TraceCounters& counters() const { return counters_; }

 private:
  const Scene& scene_;
  const Aggregate& aggregate_;
  TraceOptions options_;
  mutable TraceCounters counters_;
};

}  // namespace aliaslab
