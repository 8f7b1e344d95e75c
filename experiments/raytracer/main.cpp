// raytracer: renders a classic course scene file with the course's flags.
// Usage errors exit with 2, bad input files with 1; nothing is written then.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <iostream>

#include "accel/aggregate.h"
#include "common/cli.h"
#include "common/front_end.h"
#include "core/error.h"
#include "core/files.h"
#include "core/image.h"
#include "core/memory_limit.h"
#include "core/parallel.h"
#include "measure/registration.h"
#include "options.h"
#include "render/render.h"
#include "sampling_plan.h"
#include "scene/scene.h"
#include "study/config.h"

using namespace aliaslab;

namespace {

using Clock = std::chrono::steady_clock;
double seconds(Clock::time_point a, Clock::time_point b) { return std::chrono::duration<double>(b - a).count(); }

/// Writes every image, or none: files already written are removed on failure.
void writeAll(const std::vector<std::pair<std::string, Image>>& images) {
  std::vector<std::string> done;
  try {
    for (const auto& [path, image] : images) {
      writeImage(path, image);
      done.push_back(path);
    }
  } catch (...) {
    std::error_code ec;
    for (const std::string& p : done) std::filesystem::remove(p, ec);
    throw;
  }
}

/// No image with NaN or infinite pixels is written (values beyond float range, e.g. a light of 3e38 on a colour
/// of 3e38): InputError naming the scene, the image and the count, before anything is written.
void refuseNonFinite(const std::string& scene, const std::vector<std::pair<std::string, Image>>& images) {
  for (const auto& [path, image] : images)
    if (const size_t n = countNonFinitePixels(image))
      throw InputError(scene + ": " + std::to_string(n) + " of " + std::to_string(size_t(image.width()) * image.height()) +
                       " pixels of " + path + " are NaN or infinite (lights or colours whose products exceed float "
                       "range, about 3.4e38?); no image written");
}

// The library's keys in this program's flags (the classic course flags are single-dash).
const FrontEnd kRaytracer{"raytracer",
                          {{"sampler", "--sampler"},   {"spp", "--spp"},
                           {"filter", "--filter"},     {"radius", "--radius"},
                           {"filter-param", "--filter-param"}, {"reconstruction", "--reconstruction"},
                           {"prefilter", "--prefilter"}, {"threads", "--threads"},
                           {"size", "-size"},          {"grid", "-grid"},
                           {"depth", "-depth"}},
                          2, 1, 1, "error: "};  // bad options exit 2, bad input files 1

int run(const RaytracerOptions& o, const SamplingPlan& plan) {
  const auto t0 = Clock::now();
  const int w = o.size[0], h = o.size[1];
  std::vector<std::pair<std::string, Image>> images;

  // Filter visualisation needs no scene.
  if (!o.renderFilter.empty()) images.emplace_back(o.renderFilter[0], renderFilterImage(plan, o));

  // Memory first: the traced samples of the whole image, the image and each further picture.
  const int spp = plan.source->pixelSampler().spp();  // (an adaptive method: its base at 1 spp)
  requireMemory(double(w) * h * (double(spp) * sizeof(FilmSample) + 5 * 3 * sizeof(float)), "-size",
                "a " + std::to_string(w) + " x " + std::to_string(h) + " image at " + std::to_string(spp) +
                    " samples per pixel");
  // Scene, accelerator, tracer.
  Scene scene = parseScene(o.input);  // (its camera is swapped per frame with -frames)
  // No output may overwrite an input: the scene is checked with the options, its OBJ files here.
  refuseOutputsOverInputs(writtenFiles(o), scene.dependencies);
  const auto t1 = Clock::now();
  std::unique_ptr<Aggregate> aggregate =
      o.bruteForce ? makeBruteForce(*scene.root)
                   : (o.grid.empty() ? makeDefaultAggregate(*scene.root)  // mesh scenes: the BVH
                                     : makeGrid(*scene.root, o.grid[0], o.grid[1], o.grid[2]));
  const auto t2 = Clock::now();
  TraceOptions to;
  to.shadows = o.shadows;
  to.bounces = o.bounces;
  to.weight = o.weight;
  to.shadeBack = o.shadeBack;
  to.prefilter = parsePrefilter(o.prefilter);
  to.footprintPixels = 1.f / std::sqrt(static_cast<float>(spp));
  const Tracer tracer(scene, *aggregate, to);

  // Colour image (and sample visualisation), depth, normals; or the frames.
  if (o.frames > 0) {
    const std::unique_ptr<Camera> base = std::move(scene.camera);
    const double dx = o.motion.empty() ? 0 : o.motion[0], dy = o.motion.empty() ? 0 : o.motion[1];
    for (int t = 0; t < o.frames; ++t) {
      scene.camera = makeShiftedCamera(*base, frameScreenOffset(t, dx, dy, w, h));
      RenderedImage r = renderImage(tracer, plan, w, h, o.threads);
      if (o.registerFrames && t > 0) {  // out(p) = frame t(p - t d): frame 0's content where it is the same
        const std::vector<double> moved = shiftImage(r.image, t * dx, t * dy);
        std::transform(moved.begin(), moved.end(), r.image.data(), [](double v) { return static_cast<float>(v); });
      }
      images.emplace_back(framePath(o.output, t), std::move(r.image));
    }
    scene.camera.reset();
  } else if (!o.output.empty() || !o.renderSamples.empty()) {
    RenderedImage r = renderImage(tracer, plan, w, h, o.threads);
    // A filter leaves NaN / infinite samples out of its pixels (which then look finite, often black): refused like
    // non-finite pixels, so every filter and the unfiltered image give the same answer (docs/integrity.md).
    if (r.nonFiniteSamples > 0)
      throw InputError(o.input + ": " + std::to_string(r.nonFiniteSamples) + " of " +
                       std::to_string(r.samples.samples().size()) + " samples are NaN or infinite (lights or colours "
                       "whose products exceed float range, about 3.4e38?); no image written");
    refuseNonFinite(o.input, {{o.output.empty() ? o.renderSamples[0] : o.output, r.image}});  // (the samples' colours)
    if (!o.output.empty()) images.emplace_back(o.output, std::move(r.image));
    if (!o.renderSamples.empty()) images.emplace_back(o.renderSamples[0], renderSamplesImage(r, o));
  }
  if (!o.depth.empty())
    images.emplace_back(o.depth[2], renderDepth(tracer, w, h, std::stof(o.depth[0]), std::stof(o.depth[1]), o.threads));
  if (!o.normals.empty()) images.emplace_back(o.normals, renderNormals(tracer, w, h, o.threads));
  if (const uint64_t capped = samplesWithCappedRayTrees())
    std::cerr << "raytracer: warning: " << capped << " samples reached the cap of " << kMaxSecondaryRaysPerSample
              << " reflected/refracted rays per sample; their ray trees were cut (lower -bounces or raise -weight)\n";
  const auto t3 = Clock::now();
  refuseNonFinite(o.input, images);
  writeAll(images);
  const auto t4 = Clock::now();

  if (o.stats) {
    const RayCounts c = tracer.counters().total();
    const AggregateStats s = aggregate->stats();
    std::printf("scene: %s (%zu lights, %zu materials)\n", o.input.c_str(), scene.lights.size(),
                scene.materials.size());
    std::printf("image: %d x %d, %s\n", w, h, plan.describe().c_str());
    std::printf("accelerator: %s\n", aggregate->describe().c_str());
    std::printf("  primitives %zu (unbounded %zu), cells %d x %d x %d, references %zu\n", s.primitives,
                s.unbounded, s.cells[0], s.cells[1], s.cells[2], s.references);
    std::printf("rays: primary %llu, shadow %llu, reflected %llu, refracted %llu\n",
                static_cast<unsigned long long>(c.primary), static_cast<unsigned long long>(c.shadow),
                static_cast<unsigned long long>(c.reflected),
                static_cast<unsigned long long>(c.refracted));
    std::printf("time: parse %.4f s, accelerator %.4f s, render %.4f s, write %.4f s, total %.4f s (%d threads)\n",
                seconds(t0, t1), seconds(t1, t2), seconds(t2, t3), seconds(t3, t4), seconds(t0, t4),
                resolveThreads(o.threads));
  }
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"raytracer: render a classic course scene file (aliaslab)", "raytracer"};
  RaytracerOptions o;
  setupCommandLine(app, "raytracer", false);  // defaults stated in words: zero values mean "off"
  addRaytracerOptions(app, o);
  try {
    std::vector<std::string> args = translateClassicFlags(argc, argv);
    std::reverse(args.begin(), args.end());  // CLI11 takes a vector in reverse order
    app.parse(args);
    refuseNonFiniteNumbers(app);
  } catch (const OptionError& e) {
    std::cerr << "raytracer: " << e.what() << "\nRun with --help for the options.\n";
    return 2;
  } catch (const CLI::CallForHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForVersion& e) {
    return app.exit(e);
  } catch (const CLI::ParseError& e) {
    std::cerr << "raytracer: " << classicMessage(e.what()) << "\nRun with --help for the options.\n";
    return 2;
  }
  return runFrontEnd(kRaytracer, [&] {
    validateRaytracerOptions(app, o);
    const SamplingPlan plan = makeSamplingPlan(app, o);
    if (!plan.note.empty()) std::cerr << "raytracer: note: " << plan.note << "\n";
    const std::string warning = plan.source->pixelSampler().warning();
    if (!warning.empty()) std::cerr << "raytracer: warning: " << warning << "\n";
    return run(o, plan);
  });
}
