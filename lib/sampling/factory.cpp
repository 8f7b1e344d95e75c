// The one table of sampler names (samplerNames() order) and makeSampler(),
// plus gridShape(), the m x n grid every grid-based pattern uses.
#include <algorithm>
#include <string>
#include <vector>

#include "core/error.h"
#include "sampling/sampler.h"
#include "sampling/sampler_registry.h"

namespace aliaslab {

namespace {
using Maker = std::unique_ptr<Sampler> (*)(int, uint64_t);
struct Entry {
  const char* name;
  Maker make;
};
// Registered samplers, in the fixed order of samplerNames().
constexpr Entry kSamplers[] = {
    {"random", sampling::makeRandomSampler},
    {"uniform", sampling::makeUniformSampler},
    {"uniform-shifted", sampling::makeUniformShiftedSampler},
    {"jittered", sampling::makeJitteredSampler},
    {"nrooks", sampling::makeNRooksSampler},
    {"multijittered", sampling::makeMultiJitteredSampler},
    {"cmj", sampling::makeCmjSampler},
    {"halton", sampling::makeHaltonSampler},
    {"hammersley", sampling::makeHammersleySampler},
    {"sobol", sampling::makeSobolSampler},
    {"pmj02", sampling::makePmj02Sampler},
    {"bluenoise", sampling::makeBlueNoiseSampler},
    {"zsobol", sampling::makeZSobolSampler},
};

// Wrappers, used as "WRAPPER:BASE" with BASE a name of kSamplers.
using WrapperMaker = std::unique_ptr<Sampler> (*)(std::unique_ptr<Sampler>, uint64_t);
struct WrapperEntry {
  const char* name;
  WrapperMaker make;
};
constexpr WrapperEntry kWrappers[] = {
    {"bluenoise-dither", sampling::makeBlueNoiseDitherSampler},
};

std::string validNames() {
  std::string valid;
  for (const std::string& n : samplerNames()) valid += (valid.empty() ? "" : ", ") + n;
  for (const std::string& w : samplerWrapperNames()) valid += ", " + w + ":BASE (BASE one of the above)";
  return valid;
}
}  // namespace

const std::vector<std::string>& samplerNames() {
  static const std::vector<std::string> names = [] {
    std::vector<std::string> v;
    for (const Entry& e : kSamplers) v.emplace_back(e.name);
    return v;
  }();
  return names;
}

const std::vector<std::string>& samplerWrapperNames() {
  static const std::vector<std::string> names = [] {
    std::vector<std::string> v;
    for (const WrapperEntry& e : kWrappers) v.emplace_back(e.name);
    return v;
  }();
  return names;
}

const std::vector<std::string>& allSamplerNames() {
  static const std::vector<std::string> names = [] {
    std::vector<std::string> v = samplerNames();
    for (const std::string& w : samplerWrapperNames())
      for (const std::string& b : samplerNames()) v.push_back(w + ":" + b);
    return v;
  }();
  return names;
}

std::unique_ptr<Sampler> makeSampler(const std::string& name, int spp, uint64_t seed) {
  if (const size_t colon = name.find(':'); colon != std::string::npos) {
    const std::string wrapper = name.substr(0, colon), base = name.substr(colon + 1);
    for (const WrapperEntry& w : kWrappers) {
      if (wrapper != w.name) continue;
      if (base.find(':') != std::string::npos)
        throw OptionError("sampler", "sampler '" + name + "': " + wrapper +
                                           " takes a plain base sampler, not another wrapper; valid: " + validNames());
      bool known = false;
      for (const Entry& e : kSamplers) known = known || base == e.name;
      if (!known)
        throw OptionError("sampler", "sampler '" + name + "': unknown base sampler '" + base +
                                           "'; valid: " + validNames());
      return w.make(makeSampler(base, spp, seed), seed);
    }
  }
  for (const Entry& e : kSamplers) {
    if (name != e.name) continue;
    if (spp < 1) throw OptionError("spp", "samples per pixel must be >= 1, got " + std::to_string(spp));
    return e.make(spp, seed);
  }
  for (const std::string& w : samplerWrapperNames())
    if (name == w)
      throw OptionError("sampler", "sampler '" + name + "' needs a base sampler, e.g. " + w + ":sobol; valid: " +
                                         validNames());
  throw OptionError("sampler", "unknown sampler '" + name + "'; valid: " + validNames());
}

void Sampler::generatePrefix(int px, int py, int count, Vec2* out) const {
  std::vector<Vec2> all(static_cast<size_t>(spp()));
  generate(px, py, all.data());
  std::copy(all.begin(), all.begin() + std::clamp(count, 0, spp()), out);
}

void gridShape(int spp, int& columns, int& rows) {
  columns = 1;
  for (int m = 1; static_cast<long long>(m) * m <= spp; ++m)
    if (spp % m == 0) columns = m;
  rows = spp / columns;
}

namespace sampling {

std::string gridLabel(int spp) {
  int m, n;
  gridShape(spp, m, n);
  return std::to_string(m) + "x" + std::to_string(n);
}

std::string gridWarning(const char* name, int spp) {
  int m, n;
  gridShape(spp, m, n);
  if (m == n) return {};
  return std::string(name) + ": spp " + std::to_string(spp) + " is not a square; using a " +
         std::to_string(m) + "x" + std::to_string(n) + " grid (" + std::to_string(m) + " columns, " +
         std::to_string(n) + " rows)";
}

}  // namespace sampling
}  // namespace aliaslab
