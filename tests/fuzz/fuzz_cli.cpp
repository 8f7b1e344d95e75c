// libFuzzer target: the raytracer's command-line handling and the sampler
// and filter factories. The first byte picks the part:
//   even: the rest is split into argv words (whitespace / NUL), then
//         translateClassicFlags + CLI11 parse + validateRaytracerOptions +
//         makeSamplingPlan, as experiments/raytracer/main.cpp does before
//         any work (nothing is rendered or written);
//   odd:  makeSampler / makeFilter with fuzzed names, counts, radii and
//         shape parameters, then the promises each makes (points in
//         [0,1)^2 and repeatable, weights finite and zero past the radius,
//         importance samples inside the support).
// CLI::Error and InputError are the expected answers to bad input.
#include <algorithm>
#include <cmath>
#include <vector>

#include "../../experiments/raytracer/options.h"
#include "../../experiments/raytracer/sampling_plan.h"
#include "core/error.h"
#include "filter/filter.h"
#include "filter/filter_sampler.h"
#include "fuzz_entry.h"
#include "sampling/sampler.h"

namespace aliaslab::fuzz {
namespace {

/// Samplers whose constructor builds tables that grow with spp (bluenoise:
/// 16 best-candidate sets, ~0.3 s at 256 points under ASan): the fuzzer
/// builds them only for small counts (and past their limits, where the
/// factory refuses them); sampler_test covers every count's points.
bool slowToBuild(const std::string& sampler, int spp) {
  return (sampler == "bluenoise" && spp > 8 && spp <= 4096) || (sampler == "pmj02" && spp > 64 && spp <= 65536);
}

/// Every point in [0,1)^2, the same on a second call.
void checkSampler(const Sampler& s, int px, int py) {
  const int n = s.spp();
  std::vector<Vec2> a(n), b(n);
  s.generate(px, py, a.data());
  s.generate(px, py, b.data());
  for (int i = 0; i < n; ++i) {
    ALIASLAB_FUZZ_CHECK(a[i].x() >= 0.f && a[i].x() < 1.f && a[i].y() >= 0.f && a[i].y() < 1.f);
    ALIASLAB_FUZZ_CHECK(a[i] == b[i]);
  }
}

/// Finite weights, zero past the support, importance samples inside it.
void checkFilter(const Filter& f, FuzzInput& in) {
  const float r = f.radius();
  ALIASLAB_FUZZ_CHECK(r >= 1e-3f && r <= 1024.f);  // makeFilter refuses the rest (findings F1, F2)
  const FilterSampler importance(f);
  ALIASLAB_FUZZ_CHECK(std::isfinite(f.integral()) && std::isfinite(importance.absIntegral()));
  for (int k = 0; k < 4; ++k) {
    const float dx = in.unit(-2 * r, 2 * r), dy = in.unit(-2 * r, 2 * r);
    const float w = f.eval(dx, dy);
    ALIASLAB_FUZZ_CHECK(std::isfinite(w));
    const bool outside = f.radial() ? std::hypot(double(dx), double(dy)) > r : (std::abs(dx) > r || std::abs(dy) > r);
    if (outside) ALIASLAB_FUZZ_CHECK(w == 0.f);
    const Vec2 u(std::min(in.unit(0.f, 1.f), 0x1.fffffep-1f), std::min(in.unit(0.f, 1.f), 0x1.fffffep-1f));
    float weight = 0.f;
    const Vec2 o = importance.sample(u, weight);
    ALIASLAB_FUZZ_CHECK(std::isfinite(o.x()) && std::isfinite(o.y()) && std::isfinite(weight));
    ALIASLAB_FUZZ_CHECK(std::abs(o.x()) <= r && std::abs(o.y()) <= r);
  }
}

void fuzzCommandLine(const std::string& text) {
  // argv words
  std::vector<std::string> words{"raytracer"};
  std::string w;
  for (char c : text) {
    if (c == ' ' || c == '\n' || c == '\t' || c == '\0') {
      if (!w.empty()) words.push_back(w);
      w.clear();
    } else {
      w += c;
    }
  }
  if (!w.empty()) words.push_back(w);
  std::vector<char*> argv;
  for (std::string& s : words) argv.push_back(s.data());

  // What main() does before rendering.
  CLI::App app{"raytracer", "raytracer"};
  RaytracerOptions o;
  addRaytracerOptions(app, o);
  std::vector<std::string> args = translateClassicFlags(static_cast<int>(argv.size()), argv.data());
  std::reverse(args.begin(), args.end());
  try {
    app.parse(args);
    validateRaytracerOptions(app, o);
    if (slowToBuild(o.sampler, o.spp)) return;
    const SamplingPlan plan = makeSamplingPlan(app, o);
    ALIASLAB_FUZZ_CHECK(plan.source != nullptr);
    (void)plan.describe();
    checkSampler(plan.source->pixelSampler(), 0, 0);
    if (plan.filter) ALIASLAB_FUZZ_CHECK(std::isfinite(plan.filter->integral()));
  } catch (const CLI::Error& e) {
    (void)classicMessage(e.what());
  } catch (const InputError&) {
  }
}

void fuzzFactories(FuzzInput& in) {
  // Sampler: a registered name or fuzzed text, a count, a seed.
  const auto& snames = samplerNames();
  const std::string sname = in.flag() ? snames[in.range(0, snames.size() - 1)] : in.text(16);
  const int spp = static_cast<int>(in.flag() ? in.range(-4, 64) : in.range(-(1 << 20), 1 << 12));
  const uint64_t seed = in.raw<uint64_t>();
  if (slowToBuild(sname, spp)) return;
  try {
    auto s = makeSampler(sname, spp, seed);
    ALIASLAB_FUZZ_CHECK(s && s->spp() == spp && s->name() == sname);
    (void)s->describe();
    checkSampler(*s, static_cast<int>(in.range(0, 1 << 14)), static_cast<int>(in.range(0, 1 << 14)));
  } catch (const OptionError&) {
  }

  // Filter: a registered name or fuzzed text, any float radius, parameters.
  const auto& fnames = filterNames();
  const std::string fname = in.flag() ? fnames[in.range(0, fnames.size() - 1)] : in.text(16);
  const float radius = in.flag() ? in.unit(0.f, 8.f) : in.raw<float>();
  FilterParams params;
  static const char* const keys[] = {"sigma", "subtract_edge", "B", "C", "tau"};
  for (int k = static_cast<int>(in.range(0, 3)); k > 0; --k) {
    const std::string key = in.flag() ? keys[in.range(0, 4)] : in.text(8);
    params[key] = in.flag() ? in.unit(-4.f, 8.f) : in.raw<double>();
  }
  try {
    auto f = makeFilter(fname, radius, params);
    ALIASLAB_FUZZ_CHECK(f && f->name() == fname && f->radius() == radius);
    (void)f->describe();
    checkFilter(*f, in);
  } catch (const OptionError&) {
  }
}

}  // namespace

void fuzzCli(const uint8_t* data, size_t size) {
  if (size == 0) return;
  if (data[0] % 2 == 0) {
    fuzzCommandLine(std::string(reinterpret_cast<const char*>(data) + 1, size - 1));
  } else {
    FuzzInput in(data + 1, size - 1);
    fuzzFactories(in);
  }
}

}  // namespace aliaslab::fuzz

ALIASLAB_FUZZ_TARGET(aliaslab::fuzz::fuzzCli)
