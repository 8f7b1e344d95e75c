// Primary closest-hit queries per second on every scenes/*.txt: the grid,
// the BVH (bvh4: 4-wide SSE nodes; bvh8: 8-wide AVX2 nodes, where the CPU has
// AVX2), brute force and (with -DALIASLAB_EMBREE=ON) Embree's rtcIntersect1;
// any-hit (shadow) queries: grid, both BVHs and rtcOccluded1; build times of
// the grid and both BVHs.
//
// Shadow rays: from the hit point of every 4th primary ray that hits
// (offset 1e-3 along the normal, towards the light) to each scene light,
// tmax = the light's distance; scenes without lights use a point light
// above the scene's box. For same-run ratios run with
// --benchmark_repetitions=N --benchmark_enable_random_interleaving=true.
//
// Rays: 200 x 200 pixels, 16 jittered samples per pixel (a 4 x 4 grid of
// strata, offsets hashed from (pixel, sample, dimension)), through
// filmToScreen and the scene's camera, misses included, one thread. Brute
// force traces only the first sample of each pixel (40,000 rays): it is
// far too slow for all 640,000, and items/s is a rate either way.
// Trace/grid_34x48x34/vase keeps the former automatic resolution for a
// before/after comparison in the same run. Embree traces the flattened triangles and tests planes analytically, as
// the grid does; scenes with other bounded primitives (spheres) are skipped.
#include "aliaslab_paths.h"
#include <benchmark/benchmark.h>

#include <array>
#include <filesystem>
#include <map>

#include "accel/aggregate.h"
#include "core/hash.h"
#include "geometry/primitives.h"
#include "scene/light.h"
#include "scene/scene.h"
#include "study/config.h"
#ifdef ALIASLAB_HAVE_EMBREE
#include <embree3/rtcore.h>
#endif

namespace aliaslab {
namespace {

constexpr int kSize = 200, kStrata = 4, kSpp = kStrata * kStrata;

struct ShadowRay {
  Ray ray;
  float tmax;
};

struct Workload {
  Scene scene;
  std::unique_ptr<Aggregate> grid, brute, bvh, bvh8;  ///< bvh: 4-wide; bvh8: null without AVX2
  std::vector<Ray> rays;  ///< pixel-major, kSpp per pixel
  std::vector<ShadowRay> shadowRays;
  float tmin = 0.f;
};

Workload& workload(const std::string& path) {
  static std::map<std::string, Workload> cache;
  auto it = cache.find(path);
  if (it != cache.end()) return it->second;
  Workload& w = cache[path];
  w.scene = parseScene(path);
  w.grid = makeGrid(*w.scene.root);
  w.brute = makeBruteForce(*w.scene.root);
  w.tmin = w.scene.camera->tMin();
  for (int py = 0; py < kSize; ++py)
    for (int px = 0; px < kSize; ++px)
      for (int k = 0; k < kSpp; ++k) {
        const uint64_t key = pixelSeed(1, px, py);
        const float u = (k % kStrata + toUnitFloat(hashWords(key, k, 0))) / kStrata;
        const float v = (k / kStrata + toUnitFloat(hashWords(key, k, 1))) / kStrata;
        w.rays.push_back(w.scene.camera->generateRay(filmToScreen(px + u, py + v, kSize, kSize)));
      }
  w.bvh = makeBvh(*w.scene.root, BvhWidth::Four);
  if (bvhEightWideSupported()) w.bvh8 = makeBvh(*w.scene.root, BvhWidth::Eight);
  // Shadow rays from the hits of every 4th primary ray
  std::vector<std::unique_ptr<Light>> fallback;
  const auto* lights = &w.scene.lights;
  if (lights->empty()) {
    ObjectList flat;
    w.scene.root->flatten(Mat4::Identity(), flat);
    BBox box;
    for (const auto& p : flat)
      if (p->bounded()) box.extend(p->bounds());
    const Vec3 above = box.empty() ? Vec3(0, 10, 0) : Vec3(0.5f * (box.min + box.max) + Vec3(0.3f, 1.f, 0.2f) * box.extent().norm());
    fallback.push_back(makePointLight(above, Color::Ones()));
    lights = &fallback;
  }
  for (size_t i = 0; i < w.rays.size(); i += 4) {
    Hit h;
    if (!w.bvh->intersect(w.rays[i], w.tmin, h)) continue;
    const Vec3 p = w.rays[i].at(h.t);
    const Vec3 n = w.rays[i].direction.dot(h.normal) > 0.f ? Vec3(-h.normal) : h.normal;
    for (const auto& light : *lights) {
      Vec3 toLight;
      Color c;
      float distance;
      light->illuminate(p, toLight, c, distance);
      w.shadowRays.push_back({Ray{p + 1e-3f * n, toLight}, distance});
    }
  }
  return w;
}

/// Any-hit queries of the shadow rays.
void occludedAggregate(benchmark::State& state, const std::string& path, int bvhWidth) {
  Workload& w = workload(path);
  if (bvhWidth == 8 && !w.bvh8) return state.SkipWithError("this CPU has no AVX2");
  const Aggregate& agg = bvhWidth == 0 ? *w.grid : bvhWidth == 8 ? *w.bvh8 : *w.bvh;
  size_t blocked = 0, n = 0;
  for (auto _ : state)
    for (const ShadowRay& s : w.shadowRays) blocked += agg.occluded(s.ray, 0.f, s.tmax), ++n;
  state.SetItemsProcessed(static_cast<int64_t>(n));
  state.counters["occluded_fraction"] = static_cast<double>(blocked) / static_cast<double>(std::max<size_t>(n, 1));
  state.SetLabel(agg.describe());
}

/// Build time of the grid (automatic resolution, bvhWidth 0) or the BVH of the given width.
void buildAggregate(benchmark::State& state, const std::string& path, int bvhWidth) {
  Workload& w = workload(path);
  if (bvhWidth == 8 && !w.bvh8) return state.SkipWithError("this CPU has no AVX2");
  size_t nodes = 0;
  for (auto _ : state) {
    const auto agg = bvhWidth == 0   ? makeGrid(*w.scene.root)
                     : bvhWidth == 4 ? makeBvh(*w.scene.root, BvhWidth::Four)
                                     : makeBvh(*w.scene.root, BvhWidth::Eight);
    nodes += agg->stats().nodes + agg->stats().references;
    benchmark::DoNotOptimize(nodes);
  }
}

enum class Method { Grid, Brute, Bvh, Bvh8 };

void traceAggregate(benchmark::State& state, const std::string& path, Method method) {
  Workload& w = workload(path);
  if (method == Method::Bvh8 && !w.bvh8) return state.SkipWithError("this CPU has no AVX2");
  const Aggregate& agg = method == Method::Grid  ? *w.grid
                         : method == Method::Bvh ? *w.bvh
                         : method == Method::Bvh8 ? *w.bvh8
                                                  : *w.brute;
  const size_t stride = method == Method::Brute ? kSpp : 1;
  size_t hits = 0, n = 0;
  for (auto _ : state) {
    for (size_t i = 0; i < w.rays.size(); i += stride) {
      Hit h;
      hits += agg.intersect(w.rays[i], w.tmin, h);
      ++n;
    }
  }
  state.SetItemsProcessed(static_cast<int64_t>(n));
  state.counters["hit_fraction"] = static_cast<double>(hits) / static_cast<double>(n);
  state.SetLabel(agg.describe());
}

/// The grid at an explicit resolution, for comparisons with the automatic one
/// in the same run (e.g. the former automatic 3 cbrt(N) rule on the vase).
void traceFixedGrid(benchmark::State& state, const std::string& path, std::array<int, 3> res) {
  Workload& w = workload(path);
  const auto grid = makeGrid(*w.scene.root, res[0], res[1], res[2]);
  size_t hits = 0, n = 0;
  for (auto _ : state) {
    for (const Ray& r : w.rays) {
      Hit h;
      hits += grid->intersect(r, w.tmin, h);
      ++n;
    }
  }
  state.SetItemsProcessed(static_cast<int64_t>(n));
  state.counters["hit_fraction"] = static_cast<double>(hits) / static_cast<double>(n);
  state.SetLabel(grid->describe());
}

#ifdef ALIASLAB_HAVE_EMBREE
/// The scene's flattened triangles in Embree 3 (one thread), planes kept
/// aside and tested analytically as the grid does.
struct EmbreeScene {
  RTCDevice device = nullptr;
  RTCScene scene = nullptr;
  std::vector<const Object*> planes;
  size_t triangles = 0;
  bool usable = false;
  Vec3 lo, hi;
  RTCIntersectContext context;  ///< the default context (one thread)
};

EmbreeScene& embreeScene(const std::string& path) {
  static std::map<std::string, EmbreeScene> cache;
  auto it = cache.find(path);
  if (it != cache.end()) return it->second;
  EmbreeScene& e = cache[path];
  Workload& w = workload(path);
  static std::map<std::string, ObjectList> flats;  // keeps the planes alive
  ObjectList& flat = flats[path];
  w.scene.root->flatten(Mat4::Identity(), flat);
  std::vector<float> vertices;
  for (const auto& p : flat) {
    if (const auto* t = dynamic_cast<const Triangle*>(p.get())) {
      for (const Vec3* v : {&t->a, &t->b, &t->c}) vertices.insert(vertices.end(), {v->x(), v->y(), v->z()});
    } else if (!p->bounded()) {
      e.planes.push_back(p.get());
    } else {
      return e;  // non-triangle bounded primitives: not comparable
    }
  }
  e.usable = true;
  rtcInitIntersectContext(&e.context);
  e.device = rtcNewDevice("threads=1");
  e.scene = rtcNewScene(e.device);
  RTCGeometry geom = rtcNewGeometry(e.device, RTC_GEOMETRY_TYPE_TRIANGLE);
  const size_t nt = vertices.size() / 9;
  e.triangles = nt;
  auto* vb = static_cast<float*>(rtcSetNewGeometryBuffer(geom, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3,
                                                         3 * sizeof(float), 3 * nt));
  std::copy(vertices.begin(), vertices.end(), vb);
  auto* ib = static_cast<unsigned*>(rtcSetNewGeometryBuffer(geom, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3,
                                                            3 * sizeof(unsigned), nt));
  for (unsigned i = 0; i < 3 * nt; ++i) ib[i] = i;
  rtcCommitGeometry(geom);
  rtcAttachGeometry(e.scene, geom);
  rtcReleaseGeometry(geom);
  rtcCommitScene(e.scene);
  RTCBounds b;
  rtcGetSceneBounds(e.scene, &b);
  e.lo = Vec3(b.lower_x, b.lower_y, b.lower_z), e.hi = Vec3(b.upper_x, b.upper_y, b.upper_z);
  return e;
}

/// The scene's Embree copy, or nullptr (the benchmark skipped) when it has non-triangle bounded primitives.
EmbreeScene* usableEmbree(benchmark::State& state, const std::string& path) {
  EmbreeScene& e = embreeScene(path);
  if (!e.usable) state.SkipWithError("scene has non-triangle bounded primitives");
  return e.usable ? &e : nullptr;
}

/// Closest hit with rtcIntersect1 when the scene's bounded primitives are all triangles.
void traceEmbree(benchmark::State& state, const std::string& path) {
  Workload& w = workload(path);
  EmbreeScene* found = usableEmbree(state, path);
  if (!found) return;
  EmbreeScene& e = *found;
  const size_t nt = e.triangles;
  // Whole-line rays (tmin = -inf) start far behind the scene instead
  size_t hits = 0, n = 0;
  for (auto _ : state) {
    for (const Ray& r0 : w.rays) {
      Ray r = r0;
      float tmin = w.tmin;
      if (tmin == -kInf && nt > 0) {
        const float back = ((r.origin - 0.5f * (e.lo + e.hi)).norm() + (e.hi - e.lo).norm()) / r.direction.norm();
        r.origin -= back * r.direction;
        tmin = 0.f;
      }
      Hit h;
      for (const Object* p : e.planes) p->intersect(r, tmin, h);
      RTCRayHit rh;
      rh.ray = {r.origin.x(), r.origin.y(), r.origin.z(), std::max(tmin, 0.f), r.direction.x(), r.direction.y(), r.direction.z(),
                0.f, std::min(h.t, std::numeric_limits<float>::max()), 0xffffffffu, 0, 0};
      rh.hit.geomID = RTC_INVALID_GEOMETRY_ID;
      if (nt > 0) rtcIntersect1(e.scene, &e.context, &rh);
      hits += (rh.hit.geomID != RTC_INVALID_GEOMETRY_ID || h.found());
      ++n;
    }
  }
  state.SetItemsProcessed(static_cast<int64_t>(n));
  state.counters["hit_fraction"] = static_cast<double>(hits) / static_cast<double>(n);
  state.SetLabel("embree 3, " + std::to_string(nt) + " triangles + " + std::to_string(e.planes.size()) + " planes");
}

/// Any hit with rtcOccluded1 on the same shadow rays (planes first, analytically).
void occludedEmbree(benchmark::State& state, const std::string& path) {
  Workload& w = workload(path);
  EmbreeScene* found = usableEmbree(state, path);
  if (!found) return;
  EmbreeScene& e = *found;
  size_t blocked = 0, n = 0;
  for (auto _ : state)
    for (const ShadowRay& s : w.shadowRays) {
      ++n;
      bool hit = false;
      for (const Object* p : e.planes) {
        Hit h;
        h.t = s.tmax;
        if (p->intersect(s.ray, 0.f, h)) {
          hit = true;
          break;
        }
      }
      if (!hit && e.triangles > 0) {
        const Ray& r = s.ray;
        RTCRay ray{r.origin.x(), r.origin.y(), r.origin.z(), 0.f, r.direction.x(), r.direction.y(), r.direction.z(),
                   0.f, std::min(s.tmax, std::numeric_limits<float>::max()), 0xffffffffu, 0, 0};
        rtcOccluded1(e.scene, &e.context, &ray);
        hit = ray.tfar < 0.f;
      }
      blocked += hit;
    }
  state.SetItemsProcessed(static_cast<int64_t>(n));
  state.counters["occluded_fraction"] = static_cast<double>(blocked) / static_cast<double>(std::max<size_t>(n, 1));
}
#endif

/// One benchmark per scene and method, named Trace/<method>/<scene>.
const bool registered = [] {
  for (const std::string& path : expandScenePaths({ALIASLAB_SOURCE_DIR "/scenes"})) {  // sorted scenes/*.txt
    const std::string name = std::filesystem::path(path).stem().string();
    auto add = [&](const std::string& what, auto fn, auto arg) {
      benchmark::RegisterBenchmark((what + "/" + name).c_str(), fn, path, arg)->Unit(benchmark::kMillisecond);
    };
    add("Trace/grid", traceAggregate, Method::Grid), add("Trace/bvh4", traceAggregate, Method::Bvh);
    add("Trace/bvh8", traceAggregate, Method::Bvh8), add("Trace/brute", traceAggregate, Method::Brute);
    add("Occluded/grid", occludedAggregate, 0), add("Occluded/bvh4", occludedAggregate, 4);
    add("Occluded/bvh8", occludedAggregate, 8);
    add("Build/grid", buildAggregate, 0), add("Build/bvh4", buildAggregate, 4), add("Build/bvh8", buildAggregate, 8);
    if (name == "vase")  // the former automatic resolution (3 cbrt(N) along the longest axis)
      benchmark::RegisterBenchmark("Trace/grid_34x48x34/vase", traceFixedGrid, path, std::array{34, 48, 34})
          ->Unit(benchmark::kMillisecond);
#ifdef ALIASLAB_HAVE_EMBREE
    benchmark::RegisterBenchmark(("Trace/embree/" + name).c_str(), traceEmbree, path)->Unit(benchmark::kMillisecond);
    benchmark::RegisterBenchmark(("Occluded/embree/" + name).c_str(), occludedEmbree, path)->Unit(benchmark::kMillisecond);
#endif
  }
  return true;
}();

}  // namespace
}  // namespace aliaslab

BENCHMARK_MAIN();
