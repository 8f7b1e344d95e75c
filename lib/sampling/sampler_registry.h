// Constructors of the concrete samplers, one per source file, called by the
// single name table in factory.cpp (no self-registration: a static library
// would drop it). Internal to lib/sampling; use makeSampler() elsewhere.
// Each takes spp >= 1 (checked by the factory) and the run's seed.
#pragma once
#include <cstdint>
#include <memory>

#include "sampling/sampler.h"

namespace aliaslab::sampling {

std::unique_ptr<Sampler> makeRandomSampler(int spp, uint64_t seed);
std::unique_ptr<Sampler> makeUniformSampler(int spp, uint64_t seed);
std::unique_ptr<Sampler> makeUniformShiftedSampler(int spp, uint64_t seed);
std::unique_ptr<Sampler> makeJitteredSampler(int spp, uint64_t seed);
std::unique_ptr<Sampler> makeNRooksSampler(int spp, uint64_t seed);
std::unique_ptr<Sampler> makeMultiJitteredSampler(int spp, uint64_t seed);
std::unique_ptr<Sampler> makeCmjSampler(int spp, uint64_t seed);
std::unique_ptr<Sampler> makeHaltonSampler(int spp, uint64_t seed);
std::unique_ptr<Sampler> makeHammersleySampler(int spp, uint64_t seed);
std::unique_ptr<Sampler> makeSobolSampler(int spp, uint64_t seed);
std::unique_ptr<Sampler> makePmj02Sampler(int spp, uint64_t seed);
std::unique_ptr<Sampler> makeBlueNoiseSampler(int spp, uint64_t seed);
std::unique_ptr<Sampler> makeZSobolSampler(int spp, uint64_t seed);

/// Wrappers ("WRAPPER:BASE"): take the constructed base sampler (its spp is the wrapper's).
std::unique_ptr<Sampler> makeBlueNoiseDitherSampler(std::unique_ptr<Sampler> base, uint64_t seed);

/// The warning grid samplers give for a non-square spp ("" when square).
std::string gridWarning(const char* name, int spp);
/// "2x4" for gridShape(8).
std::string gridLabel(int spp);

}  // namespace aliaslab::sampling
