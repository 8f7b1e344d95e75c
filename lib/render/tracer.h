// Whitted-style shading: ambient + direct light (with optional shadow rays)
// + mirror reflection + refraction with total internal reflection.
//
// At a hit p with material m and unit normal n (flipped towards the viewer
// when -shade_back applies and the ray hit a back face, d.n > 0):
//   local = ambient * m.diffuse(p) + sum over lights of m.shade(p, n, -d, l, c)
//   (no lights at all: local = m.diffuse(p), flat colour). With -shadows a
//   light is skipped when aggregate.occluded() finds anything between
//   p + epsilon n (n on the light's side) and the light; transparent
//   objects shadow as opaque. Lights behind the shading normal are skipped
//   without a shadow ray (Blinn-Phong gives them zero).
//   + reflective(p) * trace(mirror ray) when depth < bounces and
//     weight * max(reflective) >= options.weight,
//   + transparent(p) * trace(refracted ray) under the same test with
//     max(transparent). A ray entering through a front face goes from index
//     1 to m.ior(p); one leaving through a back face from m.ior(p) to 1 (every
//     transparent object is taken to sit in air). Total internal reflection
//     gives no transmitted ray; the reflected ray is traced only through the
//     reflective colour, as the course's ray tracers do.
// Secondary rays start at p with tmin = epsilon. A miss returns the
// background colour. A hit without a material shades as the default
// PhongMaterial (white diffuse).
#pragma once
#include <atomic>
#include <cstdint>
#include <string>

#include "accel/aggregate.h"
#include "scene/scene.h"

namespace aliaslab {

/// Work per sample is bounded: one primary sample spawns at most this many reflected and refracted rays in
/// all (its ray tree is cut, depth first, once they are spent). Two facing glass spheres with -bounces 1000
/// would otherwise double the work every level. samplesWithCappedRayTrees() counts the samples cut so far
/// (the raytracer warns with the count).
inline constexpr uint32_t kMaxSecondaryRaysPerSample = 1u << 16;
uint64_t samplesWithCappedRayTrees();

struct TraceOptions {
  bool shadows = false;     ///< -shadows: cast shadow rays (transparent objects shadow as opaque)
  int bounces = 0;          ///< -bounces n: maximum reflection/refraction depth
  float weight = 0.f;       ///< -weight w: stop a ray whose accumulated weight falls below w
  bool shadeBack = false;   ///< -shade_back: flip the normal when a ray hits a back face
  float epsilon = 1e-3f;    ///< scene units: tmin of reflected/refracted rays, shadow origin p + epsilon n
  /// One line, e.g. "shadows bounces 5 weight 0.01 shade_back epsilon 0.001".
  std::string describe() const;
};

/// Ray counts for -stats (relaxed atomics; totals do not affect images).
struct TraceCounters {
  std::atomic<uint64_t> primary{0}, shadow{0}, reflected{0}, refracted{0};
};

/// Mirror direction of d about the normal n (either orientation of n).
Vec3 mirrorDirection(const Vec3& d, const Vec3& n);

/// Snell refraction of the unit direction d at a surface whose unit normal n
/// faces the incoming ray (d.n < 0); eta = incident index / transmitted
/// index. Writes the unit transmitted direction and returns true, or returns
/// false on total internal reflection.
bool refractDirection(const Vec3& d, const Vec3& n, float eta, Vec3& transmitted);

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
