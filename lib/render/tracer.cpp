// Whitted ray tracing; the protocol is documented in tracer.h.
#include "render/tracer.h"

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

std::string TraceOptions::describe() const {
  std::ostringstream out;
  out << (shadows ? "shadows" : "no_shadows") << " bounces " << bounces << " weight " << weight
      << (shadeBack ? " shade_back" : "") << " epsilon " << epsilon;
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

Color Tracer::trace(const Ray& ray, float tmin, int depth, float weight, float ior, Hit& hit) const {
  if (depth == 0) tSecondaryLeft = kMaxSecondaryRaysPerSample, tCapped = false;
  hit = Hit{};
  if (!aggregate_.intersect(ray, tmin, hit)) return scene_.background;

  const Material& m = hit.material ? *hit.material : defaultMaterial();
  const Vec3 d = ray.direction.normalized();
  const Vec3 p = ray.at(hit.t);
  const bool backFace = d.dot(hit.normal) > 0.f;
  const Vec3 n = (options_.shadeBack && backFace) ? Vec3(-hit.normal) : hit.normal;
  const float eps = options_.epsilon;

  // Local light: ambient + each visible light, or flat colour without lights
  Color color;
  if (scene_.lights.empty()) {
    color = m.diffuse(p);
  } else {
    color = scene_.ambient * m.diffuse(p);
    for (const auto& light : scene_.lights) {
      Vec3 toLight;
      Color lightColor;
      float distance;
      light->illuminate(p, toLight, lightColor, distance);
      if (!(n.dot(toLight) > 0.f)) continue;
      if (options_.shadows) {
        counters_.shadow.fetch_add(1, std::memory_order_relaxed);
        const Ray shadowRay{p + eps * n, toLight};
        if (aggregate_.occluded(shadowRay, 0.f, distance)) continue;
      }
      color += m.shade(p, n, -d, toLight, lightColor);
    }
  }
  if (depth >= options_.bounces) return color;

  // Mirror reflection
  const Color reflective = m.reflective(p);
  const float reflectWeight = weight * maxComponent(reflective);
  if (maxComponent(reflective) > 0.f && reflectWeight >= options_.weight && takeSecondaryRay()) {
    counters_.reflected.fetch_add(1, std::memory_order_relaxed);
    Hit h;
    const Ray r{p, mirrorDirection(d, n)};
    color += reflective * trace(r, eps, depth + 1, reflectWeight, ior, h);
  }

  // Refraction: the geometric face decides entering (1 -> ior) or leaving (ior -> 1)
  const Color transparent = m.transparent(p);
  const float refractWeight = weight * maxComponent(transparent);
  if (maxComponent(transparent) > 0.f && refractWeight >= options_.weight) {
    const float materialIor = m.indexOfRefraction(p);
    const Vec3 facing = backFace ? Vec3(-hit.normal) : hit.normal;
    const float eta = backFace ? materialIor : 1.f / materialIor;
    Vec3 t;
    if (refractDirection(d, facing, eta, t) && takeSecondaryRay()) {
      counters_.refracted.fetch_add(1, std::memory_order_relaxed);
      Hit h;
      const Ray r{p, t};
      color += transparent * trace(r, eps, depth + 1, refractWeight, backFace ? 1.f : materialIor, h);
    }
  }
  return color;
}

Color Tracer::radianceAt(float fx, float fy, int width, int height) const {
  if (!scene_.camera) throw InputError(scene_.path + ": the scene has no camera");
  const Ray ray = scene_.camera->generateRay(filmToScreen(fx, fy, width, height));
  counters_.primary.fetch_add(1, std::memory_order_relaxed);
  Hit hit;
  return trace(ray, scene_.camera->tMin(), 0, 1.f, 1.f, hit);
}

}  // namespace aliaslab
