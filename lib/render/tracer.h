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
//
// Pre-filtering (options.prefilter, --prefilter footprint): every material
// query gets the hit's pixel footprint (SurfacePoint). Primary rays carry
// exact ray differentials from the camera (one pixel step in film x and y),
// transferred to the hit's tangent plane; reflected and refracted rays carry
// a cone that starts at the parent footprint's half-width and widens by the
// primary ray's angular spread (details and limits in docs/prefiltering.md).
// Shadow rays and the number of rays traced are unchanged.
#pragma once
#include <atomic>
#include <cstdint>
#include <string>

#include "accel/aggregate.h"
#include "scene/render_settings.h"
#include "scene/scene.h"

namespace aliaslab {

/// Work per sample is bounded: one primary sample spawns at most this many reflected and refracted rays in
/// all (its ray tree is cut, depth first, once they are spent). Two facing glass spheres with -bounces 256
/// would otherwise double the work every level. samplesWithCappedRayTrees() counts the samples cut so far
/// (the raytracer warns with the count).
inline constexpr uint32_t kMaxSecondaryRaysPerSample = 1u << 16;
// The deepest ray tree, kMaxBounces (-bounces, scene/render_settings.h): the tracer recurses once per level, so
// the depth is bounded to keep every thread's stack safe (also under sanitizers).
uint64_t samplesWithCappedRayTrees();

struct TraceOptions {
  bool shadows = false;     ///< -shadows: cast shadow rays (transparent objects shadow as opaque)
  int bounces = 0;          ///< -bounces n: maximum reflection/refraction depth
  float weight = 0.f;       ///< -weight w: stop a ray whose accumulated weight falls below w
  bool shadeBack = false;   ///< -shade_back: flip the normal when a ray hits a back face
  float epsilon = 1e-3f;    ///< scene units: tmin of reflected/refracted rays, shadow origin p + epsilon n
  bool prefilter = false;   ///< --prefilter footprint: materials average over each hit's pixel footprint
  /// Side of a sample's footprint in pixels: each of spp samples stands for
  /// 1/spp of the pixel's area, so the sweep and the raytracer use 1/sqrt(spp).
  float footprintPixels = 1.f;
  /// One line, e.g. "shadows bounces 5 weight 0.01 shade_back epsilon 0.001".
  std::string describe() const;
};

/// The tracing settings of a scene's render line (shadows, bounces, weight, shade_back); the rest as defaulted.
TraceOptions traceOptionsOf(const RenderSettings& render);

/// Ray totals, as -stats and the sweep's summary report them.
struct RayCounts {
  uint64_t primary = 0, shadow = 0, reflected = 0, refracted = 0;
};

/// Ray counters written by many threads, summed only when asked for.
/// Each thread counts into its own cache-line-sized slot (threads take
/// slots round-robin, so threads running at the same time do not share one
/// unless there are more than kSlots), and total() adds the slots up. The
/// slots are relaxed atomics, so counts are exact even when two threads do
/// share a slot; what is avoided is every thread writing the same cache line
/// for every ray. Totals never affect images.
class TraceCounters {
 public:
  enum Kind { Primary, Shadow, Reflected, Refracted };
  void add(Kind kind) const;
  RayCounts total() const;

 private:
  static constexpr int kSlots = 64;
  struct alignas(64) Slot {
    std::atomic<uint64_t> n[4] = {0, 0, 0, 0};
  };
  mutable Slot slots_[kSlots];
};

/// Mirror direction of d about the normal n (either orientation of n).
Vec3 mirrorDirection(const Vec3& d, const Vec3& n);

/// Snell refraction of the unit direction d at a surface whose unit normal n
/// faces the incoming ray (d.n < 0); eta = incident index / transmitted
/// index. Writes the unit transmitted direction and returns true, or returns
/// false on total internal reflection.
bool refractDirection(const Vec3& d, const Vec3& n, float eta, Vec3& transmitted);

/// A ray's footprint for pre-filtering: exact differentials (primary rays:
/// origin and direction change per pixel step in film x and y) or a cone
/// (secondary rays: half-width `radius` at the origin, growing by `spread`
/// per unit distance).
struct RayFootprint {
  bool differential = false;
  Vec3 dOriginDx = Vec3::Zero(), dOriginDy = Vec3::Zero();
  Vec3 dDirectionDx = Vec3::Zero(), dDirectionDy = Vec3::Zero();
  float radius = 0.f, spread = 0.f;
};

/// The footprint at a hit at distance t (in units of `ray`'s direction) on
/// a surface of unit normal n: the world-space axes dpdx, dpdy of
/// SurfacePoint (differentials transferred to the tangent plane, Igehy 1999;
/// a cone as two orthogonal diameters projected along the ray).
void footprintAt(const RayFootprint& footprint, const Ray& ray, float t, const Vec3& n, Vec3& dpdx, Vec3& dpdy);

/// The footprint of the primary ray through film position (fx, fy) of a
/// width x height image: differentials for a step of `pixels` pixels.
RayFootprint primaryFootprint(const Camera& camera, float fx, float fy, int width, int height, float pixels = 1.f);

class Tracer {
 public:
  Tracer(const Scene& scene, const Aggregate& aggregate, const TraceOptions& options);

  /// Radiance arriving along `ray` (hits with t > tmin); `depth` counts
  /// bounces so far, `weight` the accumulated reflective/transparent weight,
  /// `ior` the index of refraction of the medium the ray travels in. `hit`
  /// receives the first hit (for depth and normal images). `footprint`:
  /// the ray's footprint when pre-filtering (null: point samples).
  Color trace(const Ray& ray, float tmin, int depth, float weight, float ior, Hit& hit,
              const RayFootprint* footprint = nullptr) const;

  /// Radiance through film position (fx, fy) of a width x height image.
  Color radianceAt(float fx, float fy, int width, int height) const;

  const Scene& scene() const { return scene_; }
  const Aggregate& aggregate() const { return aggregate_; }
  const TraceOptions& options() const { return options_; }
  const TraceCounters& counters() const { return counters_; }

 private:
  const Scene& scene_;
  const Aggregate& aggregate_;
  TraceOptions options_;
  TraceCounters counters_;
};

}  // namespace aliaslab
