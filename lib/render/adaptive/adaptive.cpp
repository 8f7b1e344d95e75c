// Adaptive sampling: the registry of names, describe(), and the counts of a traced set; see adaptive.h.
// The methods are in adaptive_trace.cpp and adaptive_subdiv.cpp, the tracing of their rounds in adaptive_work.cpp.
#include "render/adaptive/adaptive.h"

#include <algorithm>
#include <cmath>

#include "core/error.h"
#include "core/format.h"
#include "core/hash.h"
#include "core/parallel.h"
#include "sampling/progressive.h"

namespace aliaslab {

// Names ------------------------------------------------------------------

namespace {
constexpr const char* kPrefix = "adaptive-";
const char* const kMethodNames[] = {"contrast", "error", "subdiv"};

/// The keys a method takes after '+'.
std::vector<std::string> keysOf(AdaptiveMethod m) {
  switch (m) {
    case AdaptiveMethod::Contrast: return {"first", "cap", "threshold", "tr", "tg", "tb"};
    case AdaptiveMethod::Error: return {"first", "cap", "floor"};
    case AdaptiveMethod::Subdivision: return {"threshold", "depth"};
  }
  return {};
}

std::string joined(const std::vector<std::string>& v) {
  std::string s;
  for (const std::string& x : v) s += (s.empty() ? "" : ", ") + x;
  return s;
}

void setParam(AdaptiveMethod m, AdaptiveParams& p, const std::string& name, const std::string& item) {
  const size_t eq = item.find('=');
  const std::string key = item.substr(0, eq);
  const auto keys = keysOf(m);
  if (eq == std::string::npos || std::find(keys.begin(), keys.end(), key) == keys.end())
    throw OptionError("sampler", "'" + name + "': unknown parameter '" + item +
                                       "'; this method takes key=value with key one of: " + joined(keys));
  double v = 0;
  size_t used = 0;
  try {
    v = std::stod(item.substr(eq + 1), &used);
  } catch (const std::exception&) {
    used = 0;
  }
  auto bad = [&](const std::string& want) {
    throw OptionError("sampler",
                      "'" + name + "': " + key + " must be " + want + ", found '" + item.substr(eq + 1) + "'");
  };
  if (used == 0 || used != item.size() - eq - 1 || !std::isfinite(v)) bad("a finite number");
  if (key == "first") {
    if (!(v > 0 && v <= 1)) bad("in (0, 1]");
    p.first = v;
  } else if (key == "cap") {
    if (!(v >= 1 && v <= 1024)) bad("in [1, 1024]");
    p.cap = v;
  } else if (key == "floor") {
    if (!(v >= 0 && v <= 1)) bad("in [0, 1]");
    p.floor = v;
  } else if (key == "depth") {
    if (!(v >= 0 && v <= 8 && v == std::floor(v))) bad("an integer in [0, 8]");
    p.depth = static_cast<int>(v);
  } else {  // thresholds
    if (!(v > 0)) bad("> 0");
    if (key == "threshold" && m == AdaptiveMethod::Subdivision) p.threshold = v;
    else if (key == "threshold") p.contrast = {v, v, v};
    else p.contrast[key == "tr" ? 0 : key == "tg" ? 1 : 2] = v;
  }
}
}  // namespace

const std::vector<std::string>& adaptiveMethodNames() {
  static const std::vector<std::string> names(std::begin(kMethodNames), std::end(kMethodNames));
  return names;
}

bool isAdaptiveSamplerName(const std::string& name) { return name.rfind(kPrefix, 0) == 0; }

std::unique_ptr<AdaptiveSampler> makeAdaptiveSampler(const std::string& name, int spp, uint64_t seed) {
  const std::string forms = "adaptive-contrast:BASE, adaptive-error:BASE or adaptive-subdiv:BASE";
  if (!isAdaptiveSamplerName(name)) throw OptionError("sampler", "'" + name + "' is not " + forms);
  const size_t colon = name.find(':');
  if (colon == std::string::npos)
    throw OptionError("sampler", "'" + name + "' names no base sampler; expected " + forms + " (BASE: " +
                                       joined(samplerNames()) + ")");
  const std::string method = name.substr(std::string(kPrefix).size(), colon - std::string(kPrefix).size());
  AdaptiveMethod m;
  if (method == "contrast") m = AdaptiveMethod::Contrast;
  else if (method == "error") m = AdaptiveMethod::Error;
  else if (method == "subdiv") m = AdaptiveMethod::Subdivision;
  else throw OptionError("sampler", "unknown adaptive method '" + method + "' in '" + name + "'; valid: " + forms);
  std::vector<std::string> parts;
  for (size_t at = colon + 1;;) {
    const size_t plus = name.find('+', at);
    parts.push_back(name.substr(at, plus == std::string::npos ? std::string::npos : plus - at));
    if (plus == std::string::npos) break;
    at = plus + 1;
  }
  const std::string base = parts[0];
  if (isAdaptiveSamplerName(base)) throw OptionError("sampler", "'" + name + "': the base cannot be adaptive itself");
  if (spp < 1) throw OptionError("spp", "samples per pixel must be >= 1, got " + std::to_string(spp));
  makeSampler(base, spp, seed);  // an unknown base or a count it refuses: the factory names the valid ones
  AdaptiveParams params;
  for (size_t k = 1; k < parts.size(); ++k) setParam(m, params, name, parts[k]);
  return std::make_unique<AdaptiveSampler>(m, base, spp, seed, params);
}

AdaptiveSampler::AdaptiveSampler(AdaptiveMethod method, std::string base, int spp, uint64_t seed,
                                 AdaptiveParams params)
    : method_(method), base_(std::move(base)), spp_(spp), seed_(seed), params_(params),
      progressive_(method != AdaptiveMethod::Subdivision && makeProgressiveSampler(base_, 1, seed)) {}

std::string AdaptiveSampler::name() const {
  return std::string(kPrefix) + kMethodNames[static_cast<int>(method_)] + ":" + base_;
}

std::string AdaptiveSampler::describe() const {
  const AdaptiveParams& p = params_;
  switch (method_) {
    case AdaptiveMethod::Contrast:
      return "adaptive contrast (Mitchell) on " + base_ + ": pilot " + formatNumber(p.first) +
             " of spp, contrast thresholds " + formatNumber(p.contrast[0]) + "/" + formatNumber(p.contrast[1]) + "/" +
             formatNumber(p.contrast[2]) + ", cap " + formatNumber(p.cap) + "x spp";
    case AdaptiveMethod::Error:
      return "adaptive error on " + base_ + ": pilot " + formatNumber(p.first) +
             " of spp, the rest in proportion to the pilot's deviation, floor " + formatNumber(p.floor) +
             " of the flat share, cap " + formatNumber(p.cap) + "x spp";
    case AdaptiveMethod::Subdivision:
      return "adaptive subdivision (Whitted) on " + base_ + ": 4 decision samples per cell, split above " +
             formatNumber(p.threshold) + ", depth " + std::to_string(p.depth);
  }
  return {};
}

std::unique_ptr<Sampler> AdaptiveSampler::baseSampler(int count, uint64_t round) const {
  return makeSampler(base_, count, round == 0 ? seed_ : hashWords(seed_, 0x61646170ULL, round));
}

std::unique_ptr<Sampler> AdaptiveSampler::progressiveSampler(int count) const {
  return makeProgressiveSampler(base_, count, seed_);
}

SpentSamples spentSamples(const SampleBuffer& samples) {
  SpentSamples s;
  const long long n = static_cast<long long>(samples.width()) * samples.height();
  if (n == 0) return s;
  long long total = 0;
  for (int j = 0; j < samples.height(); ++j)
    for (int i = 0; i < samples.width(); ++i) {
      total += samples.count(i, j);
      s.max = std::max(s.max, samples.count(i, j));
    }
  s.mean = static_cast<double>(total) / static_cast<double>(n);
  return s;
}

Image sampleDensity(const SampleBuffer& samples) {
  Image img(samples.width(), samples.height());
  for (int j = 0; j < samples.height(); ++j)
    for (int i = 0; i < samples.width(); ++i) img.set(i, j, Color::Constant(static_cast<float>(samples.count(i, j))));
  return img;
}

}  // namespace aliaslab
