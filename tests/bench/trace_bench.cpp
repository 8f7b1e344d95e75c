// Primary closest-hit queries per second on every scenes/*.txt: the grid,
// brute force and (with -DALIASLAB_EMBREE=ON) Embree's rtcIntersect1.
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
#include "scene/scene.h"
#ifdef ALIASLAB_HAVE_EMBREE
#include <embree3/rtcore.h>
#endif

namespace aliaslab {
namespace {

constexpr int kSize = 200, kStrata = 4, kSpp = kStrata * kStrata;

struct Workload {
  Scene scene;
  std::unique_ptr<Aggregate> grid, brute;
  std::vector<Ray> rays;  ///< pixel-major, kSpp per pixel
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
  return w;
}

void traceAggregate(benchmark::State& state, const std::string& path, bool useGrid) {
  Workload& w = workload(path);
  const Aggregate& agg = useGrid ? *w.grid : *w.brute;
  const size_t stride = useGrid ? 1 : kSpp;
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
/// Registers an Embree run when the scene's bounded primitives are all triangles.
void traceEmbree(benchmark::State& state, const std::string& path) {
  Workload& w = workload(path);
  ObjectList flat;
  w.scene.root->flatten(Mat4::Identity(), flat);
  std::vector<float> vertices;
  std::vector<const Object*> planes;
  for (const auto& p : flat) {
    if (const auto* t = dynamic_cast<const Triangle*>(p.get())) {
      for (const Vec3* v : {&t->a, &t->b, &t->c}) vertices.insert(vertices.end(), {v->x(), v->y(), v->z()});
    } else if (!p->bounded()) {
      planes.push_back(p.get());
    } else {
      state.SkipWithError("scene has non-triangle bounded primitives");
      return;
    }
  }
  RTCDevice device = rtcNewDevice("threads=1");
  RTCScene scene = rtcNewScene(device);
  RTCGeometry geom = rtcNewGeometry(device, RTC_GEOMETRY_TYPE_TRIANGLE);
  const size_t nt = vertices.size() / 9;
  auto* vb = static_cast<float*>(rtcSetNewGeometryBuffer(geom, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3,
                                                         3 * sizeof(float), 3 * nt));
  std::copy(vertices.begin(), vertices.end(), vb);
  auto* ib = static_cast<unsigned*>(rtcSetNewGeometryBuffer(geom, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3,
                                                            3 * sizeof(unsigned), nt));
  for (unsigned i = 0; i < 3 * nt; ++i) ib[i] = i;
  rtcCommitGeometry(geom);
  rtcAttachGeometry(scene, geom);
  rtcReleaseGeometry(geom);
  rtcCommitScene(scene);
  RTCIntersectContext context;
  rtcInitIntersectContext(&context);

  // Whole-line rays (tmin = -inf) start far behind the scene instead
  RTCBounds b;
  rtcGetSceneBounds(scene, &b);
  const Vec3 lo(b.lower_x, b.lower_y, b.lower_z), hi(b.upper_x, b.upper_y, b.upper_z);
  size_t hits = 0, n = 0;
  for (auto _ : state) {
    for (const Ray& r0 : w.rays) {
      Ray r = r0;
      float tmin = w.tmin;
      if (tmin == -kInf && nt > 0) {
        const float back = ((r.origin - 0.5f * (lo + hi)).norm() + (hi - lo).norm()) / r.direction.norm();
        r.origin -= back * r.direction;
        tmin = 0.f;
      }
      Hit h;
      for (const Object* p : planes) p->intersect(r, tmin, h);
      RTCRayHit rh;
      rh.ray = {r.origin.x(), r.origin.y(), r.origin.z(), std::max(tmin, 0.f), r.direction.x(), r.direction.y(), r.direction.z(),
                0.f, std::min(h.t, std::numeric_limits<float>::max()), 0xffffffffu, 0, 0};
      rh.hit.geomID = RTC_INVALID_GEOMETRY_ID;
      if (nt > 0) rtcIntersect1(scene, &context, &rh);
      hits += (rh.hit.geomID != RTC_INVALID_GEOMETRY_ID || h.found());
      ++n;
    }
  }
  state.SetItemsProcessed(static_cast<int64_t>(n));
  state.counters["hit_fraction"] = static_cast<double>(hits) / static_cast<double>(n);
  state.SetLabel("embree 3, " + std::to_string(nt) + " triangles + " + std::to_string(planes.size()) + " planes");
  rtcReleaseScene(scene);
  rtcReleaseDevice(device);
}
#endif

/// One benchmark per scene and method, named Trace/<method>/<scene>.
const bool registered = [] {
  const std::filesystem::path dir = std::filesystem::path(ALIASLAB_SOURCE_DIR) / "scenes";
  std::vector<std::filesystem::path> files;
  for (const auto& e : std::filesystem::directory_iterator(dir))
    if (e.path().extension() == ".txt") files.push_back(e.path());
  std::sort(files.begin(), files.end());
  for (const auto& f : files) {
    const std::string name = f.stem().string(), path = f.string();
    benchmark::RegisterBenchmark(("Trace/grid/" + name).c_str(), traceAggregate, path, true)->Unit(benchmark::kMillisecond);
    benchmark::RegisterBenchmark(("Trace/brute/" + name).c_str(), traceAggregate, path, false)->Unit(benchmark::kMillisecond);
    if (name == "vase")  // the former automatic resolution (3 cbrt(N) along the longest axis)
      benchmark::RegisterBenchmark("Trace/grid_34x48x34/vase", traceFixedGrid, path, std::array{34, 48, 34})
          ->Unit(benchmark::kMillisecond);
#ifdef ALIASLAB_HAVE_EMBREE
    benchmark::RegisterBenchmark(("Trace/embree/" + name).c_str(), traceEmbree, path)->Unit(benchmark::kMillisecond);
#endif
  }
  return true;
}();

}  // namespace
}  // namespace aliaslab

BENCHMARK_MAIN();
