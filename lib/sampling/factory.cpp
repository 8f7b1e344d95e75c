// The one table of sampler names (samplerNames() order) and makeSampler(),
// plus gridShape(), the m x n grid every grid-based pattern uses.
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
    {"jittered", sampling::makeJitteredSampler},
    {"nrooks", sampling::makeNRooksSampler},
    {"multijittered", sampling::makeMultiJitteredSampler},
    {"cmj", sampling::makeCmjSampler},
    {"halton", sampling::makeHaltonSampler},
    {"hammersley", sampling::makeHammersleySampler},
    {"sobol", sampling::makeSobolSampler},
    {"pmj02", sampling::makePmj02Sampler},
    {"bluenoise", sampling::makeBlueNoiseSampler},
};
}  // namespace

const std::vector<std::string>& samplerNames() {
  static const std::vector<std::string> names = [] {
    std::vector<std::string> v;
    for (const Entry& e : kSamplers) v.emplace_back(e.name);
    return v;
  }();
  return names;
}

std::unique_ptr<Sampler> makeSampler(const std::string& name, int spp, uint64_t seed) {
  for (const Entry& e : kSamplers) {
    if (name != e.name) continue;
    if (spp < 1) throw OptionError("--spp", "samples per pixel must be >= 1, got " + std::to_string(spp));
    return e.make(spp, seed);
  }
  std::string valid;
  for (const std::string& n : samplerNames()) valid += (valid.empty() ? "" : ", ") + n;
  throw OptionError("--sampler", "unknown sampler '" + name + "'; valid: " + valid);
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
