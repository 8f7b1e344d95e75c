// Whitted ray tracing; the protocol is documented in tracer.h.
#include "render/tracer.h"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "core/error.h"

namespace aliaslab {
namespace {

const Material& defaultMaterial() {
  static const std::unique_ptr<Material> m = makePhong(PhongParams{});
  return *m;
}

float maxComponent(const Color& c) { return c.maxCoeff(); }

}  // namespace

TraceOptions traceOptionsOf(const RenderSettings& render) {
  TraceOptions o;
  o.shadows = render.shadows;
  o.bounces = render.bounces;
  o.weight = render.weight;
  o.shadeBack = render.shadeBack;
  return o;
}

std::string TraceOptions::describe() const {
  std::ostringstream out;
  out << (shadows ? "shadows" : "no_shadows") << " bounces " << bounces << " weight " << weight
      << (shadeBack ? " shade_back" : "") << " epsilon " << epsilon;
  if (prefilter) out << " prefilter footprint " << footprintPixels << " px";
  return out.str();
}

Vec3 mirrorDirection(const Vec3& d, const Vec3& n) { return d - 2.f * d.dot(n) * n; }

bool refractDirection(const Vec3& d, const Vec3& n, float eta, Vec3& transmitted) {
  const float cosI = -d.dot(n);
  const float k = 1.f - eta * eta * (1.f - cosI * cosI);
  if (k < 0.f) return false;
  transmitted = (eta * d + (eta * cosI - std::sqrt(k)) * n).normalized();
  return true;
}

void footprintAt(const RayFootprint& f, const Ray& ray, float t, const Vec3& n, Vec3& dpdx, Vec3& dpdy) {
  const Vec3& d = ray.direction;
  // d.n, kept away from 0 at grazing hits (the footprint is then huge but finite)
  float dn = d.dot(n);
  const float minDn = 1e-6f * d.norm();
  if (std::abs(dn) < minDn) dn = dn < 0.f ? -minDn : minDn;
  // a world offset dp along the ray's neighbour, moved along d onto the tangent plane
  auto onPlane = [&](const Vec3& dp) { return Vec3(dp - (dp.dot(n) / dn) * d); };
  if (f.differential) {
    dpdx = onPlane(f.dOriginDx + t * f.dDirectionDx);
    dpdy = onPlane(f.dOriginDy + t * f.dDirectionDy);
    return;
  }
  const Vec3 u = d.normalized();
  const float r = f.radius + std::abs(t) * d.norm() * f.spread;
  const Vec3 a = (std::abs(u.x()) < 0.9f ? Vec3::UnitX() : Vec3::UnitY()).cross(u).normalized();
  const Vec3 b = u.cross(a);
  dpdx = onPlane(2.f * r * a), dpdy = onPlane(2.f * r * b);
}

RayFootprint primaryFootprint(const Camera& camera, float fx, float fy, int width, int height, float pixels) {
  const float perPixel = pixels / static_cast<float>(std::max(width, height));  // screen units per step
  const RayDerivatives d = camera.rayDerivatives(filmToScreen(fx, fy, width, height));
  RayFootprint f;
  f.differential = true;
  f.dOriginDx = perPixel * d.dOriginDx, f.dOriginDy = perPixel * d.dOriginDy;
  f.dDirectionDx = perPixel * d.dDirectionDx, f.dDirectionDy = perPixel * d.dDirectionDy;
  return f;
}

void TraceCounters::add(Kind kind) const {
  static std::atomic<unsigned> nextSlot{0};
  thread_local const unsigned slot = nextSlot.fetch_add(1, std::memory_order_relaxed) % kSlots;
  slots_[slot].n[kind].fetch_add(1, std::memory_order_relaxed);
}

RayCounts TraceCounters::total() const {
  uint64_t n[4] = {0, 0, 0, 0};
  for (const Slot& s : slots_)
    for (int k = 0; k < 4; ++k) n[k] += s.n[k].load(std::memory_order_relaxed);
  return {n[Primary], n[Shadow], n[Reflected], n[Refracted]};
}

Tracer::Tracer(const Scene& scene, const Aggregate& aggregate, const TraceOptions& options)
    : scene_(scene), aggregate_(aggregate), options_(options) {}

namespace {
// Secondary rays left to the current primary sample (reset at depth 0; per thread, and one sample is traced by
// one thread in a fixed order, so a cut tree is the same whatever the thread count).
thread_local uint32_t tSecondaryLeft = 0;
thread_local bool tCapped = false;
std::atomic<uint64_t> gCappedSamples{0};
// Takes one secondary ray from the budget; false (and the sample counted once) when it is spent.
bool takeSecondaryRay() {
  if (tSecondaryLeft > 0) return --tSecondaryLeft, true;
  if (!tCapped) tCapped = true, gCappedSamples.fetch_add(1, std::memory_order_relaxed);
  return false;
}
}  // namespace

uint64_t samplesWithCappedRayTrees() { return gCappedSamples.load(); }

Color Tracer::trace(const Ray& ray, float tmin, int depth, float weight, float ior, Hit& hit,
                    const RayFootprint* footprint) const {
  if (depth == 0) tSecondaryLeft = kMaxSecondaryRaysPerSample, tCapped = false;
  hit = Hit{};
  if (!aggregate_.intersect(ray, tmin, hit)) return scene_.background;

  const Vec3 d = ray.direction.normalized();
  SurfacePoint p(ray.at(hit.t));
  RayFootprint cone;  // of the secondary rays: starts at this footprint, widens as the primary ray did
  if (footprint) {
    footprintAt(*footprint, ray, hit.t, hit.normal, p.dpdx, p.dpdy);
    cone.radius = 0.5f * std::max(p.dpdx.norm(), p.dpdy.norm());
    cone.spread = footprint->differential
                      ? 0.5f * std::max(footprint->dDirectionDx.norm(), footprint->dDirectionDy.norm())
                      : footprint->spread;
  }
  const RayFootprint* secondary = footprint ? &cone : nullptr;
  const MaterialAt m(hit.material ? *hit.material : defaultMaterial(), p);  // blend weights once per hit
  const bool backFace = d.dot(hit.normal) > 0.f;
  const Vec3 n = (options_.shadeBack && backFace) ? Vec3(-hit.normal) : hit.normal;
  const float eps = options_.epsilon;

  // Local light: ambient + each visible light, or flat colour without lights
  Color color;
  if (scene_.lights.empty()) {
    color = m.diffuse();
  } else {
    color = scene_.ambient * m.diffuse();
    for (const auto& light : scene_.lights) {
      Vec3 toLight;
      Color lightColor;
      float distance;
      light->illuminate(p.p, toLight, lightColor, distance);
      if (!(n.dot(toLight) > 0.f)) continue;
      if (options_.shadows) {
        counters_.add(TraceCounters::Shadow);
        const Ray shadowRay{p.p + eps * n, toLight};
        if (aggregate_.occluded(shadowRay, 0.f, distance)) continue;
      }
      color += m.shade(n, -d, toLight, lightColor);
    }
  }
  if (depth >= options_.bounces) return color;

  // Mirror reflection
  const Color reflective = m.reflective();
  const float reflectWeight = weight * maxComponent(reflective);
  if (maxComponent(reflective) > 0.f && reflectWeight >= options_.weight && takeSecondaryRay()) {
    counters_.add(TraceCounters::Reflected);
    Hit h;
    const Ray r{p.p, mirrorDirection(d, n)};
    color += reflective * trace(r, eps, depth + 1, reflectWeight, ior, h, secondary);
  }

  // Refraction: the geometric face decides entering (1 -> ior) or leaving (ior -> 1)
  const Color transparent = m.transparent();
  const float refractWeight = weight * maxComponent(transparent);
  if (maxComponent(transparent) > 0.f && refractWeight >= options_.weight) {
    const float materialIor = m.indexOfRefraction();
    const Vec3 facing = backFace ? Vec3(-hit.normal) : hit.normal;
    const float eta = backFace ? materialIor : 1.f / materialIor;
    Vec3 t;
    if (refractDirection(d, facing, eta, t) && takeSecondaryRay()) {
      counters_.add(TraceCounters::Refracted);
      Hit h;
      const Ray r{p.p, t};
      color += transparent * trace(r, eps, depth + 1, refractWeight, backFace ? 1.f : materialIor, h, secondary);
    }
  }
  return color;
}

Color Tracer::radianceAt(float fx, float fy, int width, int height) const {
  if (!scene_.camera) throw InputError(scene_.path + ": the scene has no camera");
  const Ray ray = scene_.camera->generateRay(filmToScreen(fx, fy, width, height));
  counters_.add(TraceCounters::Primary);
  Hit hit;
  if (options_.prefilter) {
    const RayFootprint footprint = primaryFootprint(*scene_.camera, fx, fy, width, height, options_.footprintPixels);
    return trace(ray, scene_.camera->tMin(), 0, 1.f, 1.f, hit, &footprint);
  }
  return trace(ray, scene_.camera->tMin(), 0, 1.f, 1.f, hit);
}

}  // namespace aliaslab
