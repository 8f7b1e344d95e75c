// Whole-image rendering over 16 x 16 tiles; see render.h.
#include "render/render.h"

#include <algorithm>
#include <mutex>
#include <vector>

#include "core/error.h"
#include "core/parallel.h"
#include "filter/filter_sampler.h"

namespace aliaslab {
namespace {

constexpr int kTile = 16;

/// Calls pixel(i, j) for every pixel, tile by tile in parallel. Each pixel
/// is visited exactly once, by one thread.
template <class PixelFn>
void forEachTile(int width, int height, int threads, const Progress& progress, PixelFn pixel) {
  const int tilesX = (width + kTile - 1) / kTile, tilesY = (height + kTile - 1) / kTile;
  const int total = tilesX * tilesY;
  std::mutex progressMutex;
  int done = 0;
  parallelFor(total, threads, [&](int tile) {
    const int x0 = (tile % tilesX) * kTile, y0 = (tile / tilesX) * kTile;
    for (int j = y0; j < std::min(y0 + kTile, height); ++j)
      for (int i = x0; i < std::min(x0 + kTile, width); ++i) pixel(i, j);
    if (progress) {
      std::lock_guard lock(progressMutex);
      progress(++done, total);
    }
  });
}

/// First hit of the primary ray through the centre of pixel (i, j).
bool primaryHit(const Tracer& tracer, int i, int j, int width, int height, Hit& hit) {
  const Camera& camera = *tracer.scene().camera;
  const Ray ray = camera.generateRay(filmToScreen(i + 0.5f, j + 0.5f, width, height));
  tracer.counters().add(TraceCounters::Primary);
  hit = Hit{};
  return tracer.aggregate().intersect(ray, camera.tMin(), hit);
}

void requireCamera(const Tracer& tracer) {
  if (!tracer.scene().camera) throw InputError(tracer.scene().path + ": the scene has no camera");
}


/// Traces sampler.spp() samples in every pixel; place(i, j, u, sample) sets
/// a sample's film position and weight from the pixel's point u in [0,1)^2.
template <class Place>
SampleBuffer traceWith(const Tracer& tracer, const Sampler& sampler, int width, int height, int threads,
                       const Progress& progress, Place&& place) {
  requireCamera(tracer);
  const int spp = sampler.spp();
  SampleBuffer buffer(width, height, spp, SampleBuffer::Unwritten{});  // every field of every sample set below
  forEachTile(width, height, threads, progress, [&](int i, int j) {
    thread_local std::vector<Vec2> u;  // one per worker thread, reused pixel after pixel
    u.resize(spp);
    sampler.generate(i, j, u.data());
    FilmSample* out = buffer.pixel(i, j);
    for (int k = 0; k < spp; ++k) {
      place(i, j, u[k], out[k]);
      out[k].L = tracer.radianceAt(out[k].x, out[k].y, width, height);
    }
  });
  return buffer;
}
}  // namespace

SampleBuffer traceSamples(const Tracer& tracer, const Sampler& sampler, int width, int height, int threads,
                          const Progress& progress) {
  return traceWith(tracer, sampler, width, height, threads, progress, [](int i, int j, const Vec2& u, FilmSample& s) {
    s.x = i + u.x(), s.y = j + u.y(), s.weight = 1.f;
  });
}

SampleBuffer traceImportanceSamples(const Tracer& tracer, const Sampler& sampler, const Filter& filter,
                                    int width, int height, int threads, const Progress& progress) {
  const FilterSampler importance(filter);  // the table, built once for the trace
  return traceWith(tracer, sampler, width, height, threads, progress, [&](int i, int j, const Vec2& u, FilmSample& s) {
    const Vec2 offset = importance.sample(u, s.weight);
    s.x = i + 0.5f + offset.x(), s.y = j + 0.5f + offset.y();
  });
}

Image renderDepth(const Tracer& tracer, int width, int height, float dmin, float dmax, int threads) {
  requireCamera(tracer);
  if (!(dmax > dmin)) throw OptionError("depth", "dmax must be greater than dmin");
  Image image(width, height);
  forEachTile(width, height, threads, {}, [&](int i, int j) {
    Hit hit;
    if (!primaryHit(tracer, i, j, width, height, hit)) return;
    const float v = std::clamp((dmax - hit.t) / (dmax - dmin), 0.f, 1.f);
    image.set(i, j, Color::Constant(v));
  });
  return image;
}

Image renderNormals(const Tracer& tracer, int width, int height, int threads) {
  requireCamera(tracer);
  Image image(width, height);
  forEachTile(width, height, threads, {}, [&](int i, int j) {
    Hit hit;
    if (primaryHit(tracer, i, j, width, height, hit)) image.set(i, j, hit.normal.cwiseAbs().array());
  });
  return image;
}

}  // namespace aliaslab
