// Shading at the cost of its rays: per scenes/*.txt, the rays one shaded
// sample needs, and the time of (a) our full shaded samples against (b) the
// same rays answered by a ray-query engine alone, in the same run.
//
// Workload: the scene as the study loads it (its # render: flags: shadows,
// bounces, weight, shade_back), larger side kMaxSize, jittered kSpp samples
// per pixel. A recording aggregate logs every query one pass of shaded
// samples makes (closest hits: primary, reflected, refracted; any hits:
// shadow rays). Each benchmark iteration then times, one after the other
// on this thread's CPU clock (robust on a loaded machine):
//   shade   Tracer::radianceAt for every sample (the study's trace work)
//   ours    the recorded queries through our aggregate alone (the BVH for mesh scenes)
//   embree  the recorded queries through Embree 3 (rtcIntersect1 /
//           rtcOccluded1; planes tested analytically as ours do), when
//           built with -DALIASLAB_EMBREE=ON and the scene's bounded
//           primitives are all triangles
//   texture the materials' blend weights at every recorded hit point
//           (MaterialAt: the procedural patterns, e.g. Perlin turbulence)
//   local   texture plus the local light at every hit: ambient and each
//           light's Blinn-Phong term (no shadow rays), the course's formulas
// texture and local are floors: a shaded sample does at least the local work
// and answers its rays, so (ours + local) / embree bounds shade/embree from
// below with today's rays, and 1 + local / embree with rays at Embree's cost.
// Counters: rays_per_sample (and per kind), ns per sample of each, and the
// ratios shade/embree (target <= 1.5 on mesh scenes), shade/ours and
// ours/embree, each from interleaved timings of the same iterations.
#include "aliaslab_paths.h"
#include <benchmark/benchmark.h>
#include <time.h>

#include <algorithm>
#include <filesystem>
#include <map>

#include "accel/aggregate.h"
#include "geometry/primitives.h"
#include "render/render.h"
#include "sampling/sampler.h"
#include "study/config.h"
#include "study/study_scene.h"
#ifdef ALIASLAB_HAVE_EMBREE
#include <embree3/rtcore.h>
#endif

namespace aliaslab {
namespace {

constexpr int kMaxSize = 128, kSpp = 4;

struct Query {
  Ray ray;
  float tmin, tmax;
  bool closest;
};

/// A closest hit on a surface with a material: where the tracer shades.
struct HitRecord {
  Vec3 p, normal, direction;
  const Material* material;
};

/// Forwards to an aggregate and logs every query.
class Recorder final : public Aggregate {
 public:
  explicit Recorder(const Aggregate& inner) : inner_(inner) {}
  bool intersect(const Ray& ray, float tmin, Hit& hit) const override {
    queries.push_back({ray, tmin, hit.t, true});
    const bool found = inner_.intersect(ray, tmin, hit);
    if (found && hit.material) hits.push_back({ray.at(hit.t), hit.normal, ray.direction.normalized(), hit.material});
    return found;
  }
  bool occluded(const Ray& ray, float tmin, float tmax) const override {
    queries.push_back({ray, tmin, tmax, false});
    return inner_.occluded(ray, tmin, tmax);
  }
  AggregateStats stats() const override { return inner_.stats(); }
  std::string describe() const override { return inner_.describe(); }
  mutable std::vector<Query> queries;
  mutable std::vector<HitRecord> hits;

 private:
  const Aggregate& inner_;
};

double threadSeconds() {
  timespec ts;
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
  return ts.tv_sec + 1e-9 * ts.tv_nsec;
}

struct Workload {
  std::unique_ptr<StudyScene> scene;
  std::vector<Vec2> film;  ///< sample film positions
  std::vector<Query> queries;
  std::vector<HitRecord> hits;
  size_t closest = 0, anyHit = 0;
};

Workload& workload(const std::string& path) {
  static std::map<std::string, Workload> cache;
  Workload& w = cache[path];
  if (w.scene) return w;
  w.scene = loadStudyScene(path, 0, 0, kMaxSize);
  const auto sampler = makeSampler("jittered", kSpp, 1);
  std::vector<Vec2> u(kSpp);
  for (int j = 0; j < w.scene->height; ++j)
    for (int i = 0; i < w.scene->width; ++i) {
      sampler->generate(i, j, u.data());
      for (const Vec2& v : u) w.film.push_back(Vec2(i + v.x(), j + v.y()));
    }
  const Recorder recorder(*w.scene->aggregate);
  const Tracer tracer(w.scene->scene, recorder, w.scene->tracer->options());
  for (const Vec2& f : w.film) tracer.radianceAt(f.x(), f.y(), w.scene->width, w.scene->height);
  w.queries = std::move(recorder.queries);
  w.hits = std::move(recorder.hits);
  for (const Query& q : w.queries) (q.closest ? w.closest : w.anyHit) += 1;
  return w;
}

double shadePass(const Workload& w) {
  const Tracer& tracer = *w.scene->tracer;
  Color sum = Color::Zero();
  const double t0 = threadSeconds();
  for (const Vec2& f : w.film) sum += tracer.radianceAt(f.x(), f.y(), w.scene->width, w.scene->height);
  benchmark::DoNotOptimize(sum);
  return threadSeconds() - t0;
}

double oursPass(const Workload& w) {
  const Aggregate& agg = *w.scene->aggregate;
  size_t n = 0;
  const double t0 = threadSeconds();
  for (const Query& q : w.queries) {
    if (q.closest) {
      Hit h;
      h.t = q.tmax;
      n += agg.intersect(q.ray, q.tmin, h);
    } else {
      n += agg.occluded(q.ray, q.tmin, q.tmax);
    }
  }
  benchmark::DoNotOptimize(n);
  return threadSeconds() - t0;
}

/// The texture (lights = false) or local (lights = true) floor over the recorded hits.
double localPass(const Workload& w, bool lights) {
  const Scene& scene = w.scene->scene;
  Color sum = Color::Zero();
  const double t0 = threadSeconds();
  for (const HitRecord& h : w.hits) {
    const MaterialAt m(*h.material, SurfacePoint(h.p));
    if (!lights || scene.lights.empty()) {
      sum += m.diffuse();
      continue;
    }
    Color c = scene.ambient * m.diffuse();
    for (const auto& light : scene.lights) {
      Vec3 toLight;
      Color lightColor;
      float distance;
      light->illuminate(h.p, toLight, lightColor, distance);
      if (h.normal.dot(toLight) > 0.f) c += m.shade(h.normal, -h.direction, toLight, lightColor);
    }
    sum += c;
  }
  benchmark::DoNotOptimize(sum);
  return threadSeconds() - t0;
}

#ifdef ALIASLAB_HAVE_EMBREE
struct Embree {
  RTCDevice device = nullptr;
  RTCScene scene = nullptr;
  ObjectList flat;
  std::vector<const Object*> planes;
  size_t triangles = 0;
  Vec3 lo, hi;
  bool usable = false;
  explicit Embree(const Object& root) {
    root.flatten(Mat4::Identity(), flat);
    std::vector<float> v;
    for (const auto& p : flat) {
      if (const auto* t = dynamic_cast<const Triangle*>(p.get())) {
        for (const Vec3* x : {&t->a, &t->b, &t->c}) v.insert(v.end(), {x->x(), x->y(), x->z()});
      } else if (!p->bounded()) {
        planes.push_back(p.get());
      } else {
        return;
      }
    }
    usable = true;
    triangles = v.size() / 9;
    device = rtcNewDevice("threads=1");
    scene = rtcNewScene(device);
    RTCGeometry g = rtcNewGeometry(device, RTC_GEOMETRY_TYPE_TRIANGLE);
    auto* vb = static_cast<float*>(
        rtcSetNewGeometryBuffer(g, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3, 3 * sizeof(float), 3 * triangles));
    std::copy(v.begin(), v.end(), vb);
    auto* ib = static_cast<unsigned*>(
        rtcSetNewGeometryBuffer(g, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3, 3 * sizeof(unsigned), triangles));
    for (unsigned i = 0; i < 3 * triangles; ++i) ib[i] = i;
    rtcCommitGeometry(g);
    rtcAttachGeometry(scene, g);
    rtcReleaseGeometry(g);
    rtcCommitScene(scene);
    RTCBounds b;
    rtcGetSceneBounds(scene, &b);
    lo = Vec3(b.lower_x, b.lower_y, b.lower_z), hi = Vec3(b.upper_x, b.upper_y, b.upper_z);
  }
  ~Embree() {
    if (scene) rtcReleaseScene(scene);
    if (device) rtcReleaseDevice(device);
  }
};

double embreePass(const Workload& w, const Embree& e) {
  RTCIntersectContext context;
  rtcInitIntersectContext(&context);
  size_t n = 0;
  const double t0 = threadSeconds();
  for (const Query& q : w.queries) {
    Ray r = q.ray;
    float tmin = q.tmin;
    if (tmin == -kInf && e.triangles > 0) {  // whole-line rays start far behind the scene instead
      const float back = ((r.origin - 0.5f * (e.lo + e.hi)).norm() + (e.hi - e.lo).norm()) / r.direction.norm();
      r.origin -= back * r.direction;
      tmin = 0.f;
    }
    const float tfar = std::min(q.tmax, std::numeric_limits<float>::max());
    if (q.closest) {
      Hit h;
      h.t = q.tmax;
      for (const Object* p : e.planes) p->intersect(r, tmin, h);
      if (e.triangles > 0) {
        RTCRayHit rh;
        rh.ray = {r.origin.x(), r.origin.y(), r.origin.z(), std::max(tmin, 0.f), r.direction.x(), r.direction.y(),
                  r.direction.z(), 0.f, std::min(h.t, tfar), 0xffffffffu, 0, 0};
        rh.hit.geomID = RTC_INVALID_GEOMETRY_ID;
        rtcIntersect1(e.scene, &context, &rh);
        n += rh.hit.geomID != RTC_INVALID_GEOMETRY_ID;
      }
      n += h.found();
    } else {
      bool hit = false;
      for (const Object* p : e.planes) {
        Hit h;
        h.t = q.tmax;
        if (p->intersect(r, tmin, h)) {
          hit = true;
          break;
        }
      }
      if (!hit && e.triangles > 0) {
        RTCRay ray{r.origin.x(), r.origin.y(), r.origin.z(), std::max(tmin, 0.f), r.direction.x(), r.direction.y(),
                   r.direction.z(), 0.f, tfar, 0xffffffffu, 0, 0};
        rtcOccluded1(e.scene, &context, &ray);
        hit = ray.tfar < 0.f;
      }
      n += hit;
    }
  }
  benchmark::DoNotOptimize(n);
  return threadSeconds() - t0;
}
#endif

void shade(benchmark::State& state, const std::string& path) {
  Workload& w = workload(path);
#ifdef ALIASLAB_HAVE_EMBREE
  const Embree embree(*w.scene->scene.root);
#endif
  double shadeS = 0, oursS = 0, embreeS = 0, textureS = 0, localS = 0;
  for (auto _ : state) {
    shadeS += shadePass(w);
    oursS += oursPass(w);
    textureS += localPass(w, false);
    localS += localPass(w, true);
#ifdef ALIASLAB_HAVE_EMBREE
    if (embree.usable) embreeS += embreePass(w, embree);
#endif
  }
  const double samples = static_cast<double>(w.film.size()) * static_cast<double>(state.iterations());
  state.SetItemsProcessed(static_cast<int64_t>(samples));
  auto& c = state.counters;
  c["rays_per_sample"] = static_cast<double>(w.queries.size()) / static_cast<double>(w.film.size());
  c["closest_per_sample"] = static_cast<double>(w.closest) / static_cast<double>(w.film.size());
  c["shadow_per_sample"] = static_cast<double>(w.anyHit) / static_cast<double>(w.film.size());
  c["shade_ns"] = 1e9 * shadeS / samples;
  c["ours_ns"] = 1e9 * oursS / samples;
  c["shade/ours"] = shadeS / oursS;
  c["texture_ns"] = 1e9 * textureS / samples;
  c["local_ns"] = 1e9 * localS / samples;
  if (embreeS > 0) {
    c["embree_ns"] = 1e9 * embreeS / samples;
    c["shade/embree"] = shadeS / embreeS;
    c["ours/embree"] = oursS / embreeS;
    c["texture/embree"] = textureS / embreeS;
    c["local/embree"] = localS / embreeS;
    c["floor/embree"] = (oursS + localS) / embreeS;  // shade/embree cannot go below this with today's rays
  }
  state.SetLabel(std::to_string(w.scene->width) + "x" + std::to_string(w.scene->height) + " " +
                 std::to_string(kSpp) + " spp, " + w.scene->aggregate->describe());
}

const bool registered = [] {
  for (const std::string& path : expandScenePaths({ALIASLAB_SOURCE_DIR "/scenes"}))  // sorted scenes/*.txt
    benchmark::RegisterBenchmark(("Shade/" + std::filesystem::path(path).stem().string()).c_str(), shade, path)
        ->Unit(benchmark::kMillisecond)
        ->MeasureProcessCPUTime();
  return true;
}();

}  // namespace
}  // namespace aliaslab

BENCHMARK_MAIN();
