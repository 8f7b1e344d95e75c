#include "sampling_plan.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <memory>

#include "core/error.h"
#include "core/format.h"
#include "film/visualize.h"
#include "render/render.h"

namespace aliaslab {
namespace {

/// The one option of `names` that was given, or "" (OptionError when several were).
std::string chooseOne(const CLI::App& app, std::initializer_list<const char*> names) {
  std::string chosen;
  for (const char* n : names) {
    if (app.count(std::string("--") + n) == 0) continue;
    if (!chosen.empty())
      throw OptionError("-" + std::string(n), "cannot be combined with -" + chosen + " (give one of them)");
    chosen = n;
  }
  return chosen;
}

FilterParams parseFilterParams(const std::vector<std::string>& items) {
  FilterParams params;
  for (const std::string& item : items) {
    const size_t eq = item.find('=');
    double value = 0;
    size_t used = 0;
    bool ok = eq != std::string::npos && eq > 0;
    if (ok) {
      try {
        value = std::stod(item.substr(eq + 1), &used);
        ok = used == item.size() - eq - 1 && std::isfinite(value);
      } catch (const std::exception&) {
        ok = false;
      }
    }
    if (!ok) throw OptionError("--filter-param", "expected name=value with a finite number, found '" + item + "'");
    params[item.substr(0, eq)] = value;
  }
  return params;
}

}  // namespace

std::string SamplingPlan::describe() const {
  std::string s = source->describe() + " spp " + std::to_string(source->spp());
  if (mode == ReconMode::Supersample) return s + ", supersample reconstruction (3x3 binomial, k x k box)";
  if (filter)
    return s + ", " + filter->describe() + (defaultFilter ? " (default: no --filter given)" : "") + ", " +
           toString(mode) + " reconstruction";
  return s + ", first sample per pixel";
}

namespace {

bool given(const CLI::App& app, const char* name) { return app.count(std::string("--") + name) > 0; }

/// The sampler chosen: a classic flag (its name, or "") or --sampler/--spp, default the pixel centre.
struct SamplerChoice {
  std::string classic, name = "uniform";
  int spp = 1;
};

SamplerChoice chooseSampler(const CLI::App& app, const RaytracerOptions& o) {
  auto has = [&](const char* n) { return given(app, n); };
  SamplerChoice s;
  s.classic = chooseOne(app, {"random_samples", "uniform_samples", "jittered_samples"});
  if (!s.classic.empty()) {
    if (has("sampler") || has("spp"))
      throw OptionError(has("sampler") ? "--sampler" : "--spp", "cannot be combined with -" + s.classic);
    s.name = s.classic.substr(0, s.classic.find('_'));
    s.spp = s.classic[0] == 'r' ? o.randomSamples : s.classic[0] == 'u' ? o.uniformSamples : o.jitteredSamples;
    if (s.spp < 1) throw OptionError("-" + s.classic, "needs at least 1 sample per pixel");
  } else {
    if (has("sampler")) s.name = o.sampler;
    if (has("spp")) s.spp = o.spp;
  }
  const double total = double(o.size[0]) * o.size[1] * std::max(s.spp, 1);
  if (total > double(1 << 28))
    throw OptionError(s.classic.empty() ? "--spp" : "-" + s.classic,
                      "width x height x spp exceeds 2^28 samples (about 7 GB)");
  return s;
}

/// Sets plan.filter from a classic flag or --filter/--radius/--filter-param (or the pixel-area default when
/// several samples come with no filter); returns the classic filter flag given, or "".
std::string chooseFilter(const CLI::App& app, const RaytracerOptions& o, const SamplerChoice& sampler,
                         SamplingPlan& plan) {
  auto has = [&](const char* n) { return given(app, n); };
  const std::string classicFilter = chooseOne(app, {"box_filter", "tent_filter", "gaussian_filter"});
  FilterParams params = parseFilterParams(o.filterParams);
  if (!classicFilter.empty()) {
    if (has("filter") || has("radius"))
      throw OptionError(has("filter") ? "--filter" : "--radius", "cannot be combined with -" + classicFilter);
    const std::string fname = classicFilter.substr(0, classicFilter.find('_'));
    float radius = classicFilter[0] == 'b' ? o.boxFilter : o.tentFilter;
    if (fname == "gaussian") {
      // the classic support is 2 sigma, and a radius must lie in [0.001, 1024]; sigma itself in [0.001, 1000]
      if (!(o.gaussianFilter >= 1e-3f && o.gaussianFilter <= 512.f))
        throw OptionError("-gaussian_filter", "sigma must be in [0.001, 512] pixels (its support is 2 sigma, at most "
                                              "1024), found " + formatNumber(o.gaussianFilter));
      params["sigma"] = o.gaussianFilter;
      radius = 2.f * o.gaussianFilter;  // (the classic gather uses its course variant, course-gaussian)
    } else if (!(radius > 0.f) || !std::isfinite(radius)) {
      throw OptionError("-" + classicFilter, "radius must be finite and > 0");
    }
    plan.filter = rekeyOption("radius", "-" + classicFilter, [&] { return makeFilter(fname, radius, params); });
  } else if (has("filter")) {
    // one dialect with the studies: gaussian is the library's (sigma = r / 3 unless a sigma is given); the course's
    // fixed-sigma Gaussian is course-gaussian by name (the classic -gaussian_filter keeps the course's meaning)
    // without --radius the filter's natural support (defaultFilterRadius, listed in --help)
    const float radius = has("radius") ? o.radius : static_cast<float>(defaultFilterRadius(o.filter, params));
    plan.filter = makeFilter(o.filter, radius, params);
  } else if (has("radius") || has("filter-param")) {
    throw OptionError(has("radius") ? "--radius" : "--filter-param", "needs --filter");
  } else if (sampler.classic.empty() && sampler.spp > 1 && !has("reconstruction")) {
    // several samples and no filter: the pixel-area average (box 0.5, weighted), not the first sample
    plan.filter = makeFilter("box", 0.5f);
    plan.defaultFilter = true;
  }
  return classicFilter;
}

/// Sets plan.mode: explicit, else classic for classic flags, else weighted; refuses the combinations that
/// cannot work and adds the filters the modes need.
void chooseReconstruction(const CLI::App& app, const RaytracerOptions& o, const SamplerChoice& sampler,
                          const std::string& classicFilter, SamplingPlan& plan) {
  auto has = [&](const char* n) { return given(app, n); };
  if (has("reconstruction")) plan.mode = parseReconMode(o.reconstruction);
  else if (!sampler.classic.empty() || !classicFilter.empty()) plan.mode = ReconMode::Classic;
  if (!plan.filter && has("reconstruction") && plan.mode != ReconMode::Supersample)
    throw OptionError("--reconstruction", "'" + o.reconstruction + "' needs a filter (--filter or a classic filter flag)");
  if (plan.source->adaptive() && (plan.mode == ReconMode::Supersample || plan.mode == ReconMode::ImportanceSampled))
    throw OptionError("--reconstruction", "'" + o.reconstruction + "' cannot take an adaptive sampler (" +
                                              (plan.mode == ReconMode::Supersample
                                                   ? "it needs the same k*k samples in every pixel)"
                                                   : "importance sampling places the samples by the filter)"));
  if (plan.mode == ReconMode::Supersample) {
    if (plan.filter)  // (it would be silently ignored)
      throw OptionError("--reconstruction", "supersample uses its own filters (3x3 binomial, then a box down); drop " +
                                                std::string(classicFilter.empty() ? "--filter" : "-" + classicFilter));
    const int k = static_cast<int>(std::lround(std::sqrt(double(sampler.spp))));
    if (k * k != sampler.spp)
      throw OptionError("--spp", "supersample reconstruction needs a square sample count k*k, got " +
                                     std::to_string(sampler.spp));
    if (!plan.filter) plan.filter = makeFilter("box", 0.5f);  // ignored by Supersample
  }
  if (plan.source->adaptive() && !plan.filter)
    plan.filter = makeFilter("box", 0.5f);  // each pixel's (area-weighted) mean
  if (!sampler.classic.empty() && sampler.spp > 1 && !plan.filter)
    plan.note = "-" + sampler.classic + " " + std::to_string(sampler.spp) +
                " without a filter keeps each pixel's first sample (the course's rule); add -box_filter 0.5 "
                "to average the samples over the pixel";
  if (!o.renderFilter.empty() && !plan.filter)
    throw OptionError("-render_filter", "needs a filter (-box_filter, -tent_filter, -gaussian_filter or --filter)");
}

}  // namespace

SamplingPlan makeSamplingPlan(const CLI::App& app, const RaytracerOptions& o) {
  SamplingPlan plan;
  const SamplerChoice sampler = chooseSampler(app, o);
  plan.source = makeSampleSource(sampler.name, sampler.spp, o.seed);
  const std::string classicFilter = chooseFilter(app, o, sampler, plan);
  chooseReconstruction(app, o, sampler, classicFilter, plan);
  return plan;
}

namespace {
/// Progress on stderr for a render that runs longer than two seconds:
/// "raytracer: tracing 42% (elapsed 3s, ETA 4s)", redrawn at most twice a
/// second; short renders print nothing. Called one call at a time (Progress).
class RenderProgress {
 public:
  void operator()(int done, int total) {
    const double elapsed = std::chrono::duration<double>(Clock::now() - start_).count();
    if (elapsed < 2.0 || total <= 0 || (done < total && elapsed - shown_ < 0.5)) return;
    shown_ = elapsed;
    const double f = static_cast<double>(done) / total;
    std::fprintf(stderr, "\rraytracer: tracing %3d%% (elapsed %.0fs, ETA %.0fs)%s", static_cast<int>(100 * f), elapsed,
                 f > 0 ? elapsed * (1 - f) / f : 0.0, done >= total ? "\n" : "");
    std::fflush(stderr);
  }

 private:
  using Clock = std::chrono::steady_clock;
  Clock::time_point start_ = Clock::now();
  double shown_ = -1;
};
}  // namespace

RenderedImage renderImage(const Tracer& tracer, const SamplingPlan& plan, int width, int height, int threads) {
  auto state = std::make_shared<RenderProgress>();
  const Progress progress = [state](int done, int total) { (*state)(done, total); };
  return aliaslab::renderImage(tracer, *plan.source, plan.filter.get(), plan.mode, width, height, threads, progress);
}

Image renderSamplesImage(const RenderedImage& rendered, const RaytracerOptions& o) {
  // the course's picture for the classic flags; with --sampler, strata outlined and dark samples ringed
  const int zoom = std::stoi(o.renderSamples[1]);
  if (o.sampler.empty()) return renderSamples(rendered.samples, zoom);
  int columns = 0, rows = 0;
  for (const char* grid : {"uniform", "uniform-shifted", "jittered", "multijittered", "cmj"})  // stratified on gridShape
    if (o.sampler == grid) gridShape(std::max(1, o.spp), columns, rows);
  return renderSamplesMarked(rendered.samples, zoom, columns, rows);
}

Image renderFilterImage(const SamplingPlan& plan, const RaytracerOptions& o) {
  // the course's picture (classicSupport, the course variant) where the course's gather is used, else the filter
  const int zoom = std::stoi(o.renderFilter[1]);
  return plan.mode == ReconMode::Classic ? renderFilter(*plan.filter, o.size[0], o.size[1], zoom)
                                         : renderFilterSigned(*plan.filter, o.size[0], o.size[1], zoom);
}

}  // namespace aliaslab
