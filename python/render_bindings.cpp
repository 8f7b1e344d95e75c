// render() and reference(): the raytracer's render path (render/render_image.h) and the sweep's reference pass
// (study/reference.h) over a scene prepared as the sweep prepares it (study/study_scene.h: its `# render:` line
// gives the size and the tracing flags).
#include <cmath>
#include <optional>
#include <string>
#include <utility>

#include <pybind11/stl.h>

#include "bindings.h"
#include "core/error.h"
#include "core/files.h"
#include "core/memory_limit.h"
#include "filter/filter.h"
#include "render/render_image.h"
#include "study/filter_cache.h"
#include "study/reference/reference.h"
#include "study/study_scene.h"

namespace aliaslab::python {
namespace {

using Size = std::optional<std::pair<int, int>>;

/// The scene at `size` (None: its render line's size), checked as the raytracer checks -size.
std::unique_ptr<StudyScene> sceneAt(const std::string& path, const Size& size) {
  requireFile(path, "scene_file");
  if (size && !(size->first >= 1 && size->first <= 16384 && size->second >= 1 && size->second <= 16384))
    throw OptionError("size", "width and height must be in 1..16384, found " + std::to_string(size->first) + " " +
                                  std::to_string(size->second));
  return loadStudyScene(path, size ? size->first : 0, size ? size->second : 0);  // FileError: no size known
}

/// The filter the raytracer uses for these arguments (experiments/raytracer/sampling_plan.h): the one named (radius
/// None: its natural radius); else, for several samples, an adaptive source or supersampling, the pixel-area
/// box 0.5 (supersampling ignores it); else none (each pixel its first sample).
std::unique_ptr<Filter> renderFilter(const std::optional<std::string>& name, const std::optional<double>& radius,
                                     const FilterParams& params, int spp, bool adaptive, ReconMode mode) {
  if (name && mode == ReconMode::Supersample)
    throw OptionError("reconstruction", "supersample uses its own filters (3x3 binomial, then a box down); "
                                        "give filter=None");
  if (name) {
    const double r = radius ? *radius : defaultFilterRadius(*name, params);
    if (!std::isfinite(r)) throw OptionError("radius", "must be a finite number of pixels, found " + std::to_string(r));
    return makeFilter(*name, static_cast<float>(r), params);
  }
  if (radius || !params.empty()) throw OptionError(radius ? "radius" : "filter-param", "needs a filter");
  if (spp > 1 || adaptive || mode == ReconMode::Supersample) return makeFilter("box", 0.5f);
  if (mode != ReconMode::WeightedAverage)
    throw OptionError("reconstruction", "'" + toString(mode) + "' needs a filter");
  return nullptr;
}

py::object render(const std::string& sceneFile, const std::string& sampler, int spp,
                  const std::optional<std::string>& filterName, const std::optional<double>& radius, uint64_t seed,
                  const Size& size, const std::string& reconstruction, const FilterParams& params, int threads) {
  if (threads < 0) throw OptionError("threads", "must be >= 0 (0: all cores), found " + std::to_string(threads));
  const ReconMode mode = parseReconMode(reconstruction);
  const std::unique_ptr<SampleSource> source = makeSampleSource(sampler, spp, seed);  // "sampler" / "spp"
  if (source->adaptive() && (mode == ReconMode::Supersample || mode == ReconMode::ImportanceSampled))
    throw OptionError("reconstruction", "'" + reconstruction + "' cannot take an adaptive sampler");
  const std::unique_ptr<Filter> filter = renderFilter(filterName, radius, params, spp, source->adaptive(), mode);
  const std::unique_ptr<StudyScene> scene = sceneAt(sceneFile, size);
  const int w = scene->width, h = scene->height, pixelSpp = source->pixelSampler().spp();
  if (double(w) * h * std::max(spp, 1) > double(1 << 28))
    throw OptionError("spp", "width x height x spp exceeds 2^28 samples (about 7 GB)");
  requireMemory(double(w) * h * (double(pixelSpp) * sizeof(FilmSample) + 5 * 3 * sizeof(float)), "size",
                "a " + std::to_string(w) + " x " + std::to_string(h) + " image at " + std::to_string(spp) +
                    " samples per pixel");
  TraceOptions options = scene->options;  // the raytracer's tracer for these flags (experiments/raytracer)
  options.footprintPixels = 1.f / std::sqrt(static_cast<float>(pixelSpp));
  const Tracer tracer(scene->scene, *scene->aggregate, options);
  RenderedImage r;
  {
    py::gil_scoped_release free;  // the library's threads trace; Python may run meanwhile
    r = renderImage(tracer, *source, filter.get(), mode, w, h, threads);
  }
  if (r.nonFiniteSamples > 0)
    throw InputError(sceneFile + ": " + std::to_string(r.nonFiniteSamples) + " of " +
                     std::to_string(r.samples.samples().size()) + " samples are NaN or infinite (lights or colours "
                     "whose products exceed float range, about 3.4e38?)");
  return imageArray(r.image);
}

py::object reference(const std::string& sceneFile, const std::string& filterName, const std::optional<double>& radius,
                     int spp, const Size& size, const std::string& sampler, uint64_t seed, int batch, int threads) {
  ReferenceOptions o;
  o.spp = spp, o.sampler = sampler, o.seed = seed, o.batchSpp = batch, o.threads = threads, o.progress = false;
  validateReferenceOptions(o);  // "ref-spp", "ref-batch", "sampler"
  if (threads < 0) throw OptionError("threads", "must be >= 0 (0: all cores), found " + std::to_string(threads));
  const double r = radius ? *radius : defaultFilterRadius(filterName);
  if (!std::isfinite(r)) throw OptionError("radius", "must be a finite number of pixels, found " + std::to_string(r));
  FilterCache filters;
  const StudyFilter filter = filters.get({filterName, r});  // "filter" / "radius", before any work
  const std::unique_ptr<StudyScene> scene = sceneAt(sceneFile, size);
  requireMemory(referenceMemoryBytes(scene->width, scene->height, 1, o), "size",
                "a reference of " + scene->stem + " at " + std::to_string(scene->width) + " x " +
                    std::to_string(scene->height));
  ReferenceSet set;
  {
    py::gil_scoped_release free;
    set = renderReferences(*scene, {filter}, o);
  }
  const ReferenceImage& image = set.images.at(0);
  py::dict out;
  out["image"] = imageArray(image.image);
  out["half_diff"] = imageArray(image.halfDiff);
  out["error"] = image.error;
  out["describe"] = image.describe;
  out["spp"] = set.spp;
  out["sampler"] = set.sampler;
  out["seed"] = set.seed;
  return out;
}

}  // namespace

void bindRender(py::module_& m) {
  m.def(
      "render",
      [](const std::string& scene_file, const std::string& sampler, int spp, const std::optional<std::string>& filter,
         const std::optional<double>& radius, uint64_t seed, const Size& size, const std::string& reconstruction,
         const FilterParams& params, int threads) {
        return guarded([&] {
          return render(scene_file, sampler, spp, filter, radius, seed, size, reconstruction, params, threads);
        });
      },
      py::arg("scene_file"), py::arg("sampler") = "uniform", py::arg("spp") = 1, py::arg("filter") = py::none(),
      py::arg("radius") = py::none(), py::arg("seed") = 0, py::arg("size") = py::none(),
      py::arg("reconstruction") = "weighted", py::arg("params") = FilterParams{}, py::arg("threads") = 0,
      "Renders a scene file as the raytracer does with --sampler, --spp, --filter, --radius, --seed, "
      "--reconstruction and the tracing flags of the scene's # render: line; returns the (H, W, 3) float32 "
      "image, equal to the raytracer's EXR. size=(W, H); None: the render line's size.");
  m.def(
      "reference",
      [](const std::string& scene_file, const std::string& filter, const std::optional<double>& radius, int spp,
         const Size& size, const std::string& sampler, uint64_t seed, int batch, int threads) {
        return guarded([&] {
          return reference(scene_file, filter, radius, spp, size, sampler, seed, batch, threads);
        });
      },
      py::arg("scene_file"), py::arg("filter") = "box", py::arg("radius") = 0.5, py::arg("spp") = kDefaultReferenceSpp,
      py::arg("size") = py::none(), py::arg("sampler") = "sobol", py::arg("seed") = ReferenceOptions{}.seed,
      py::arg("batch") = ReferenceOptions{}.batchSpp, py::arg("threads") = 0,
      "The study's streamed reference of a scene for one filter (the reference program's pass): a dict with "
      "'image' (H, W, 3) float32, 'half_diff' (its two halves' half-difference D, D^2 estimating the variance), "
      "'error' (mean D^2), 'describe', 'spp', 'sampler', 'seed'.");
}

}  // namespace aliaslab::python
