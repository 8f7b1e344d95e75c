// Progressive pixel sequences: a sampler whose first n points are the same at every count >= n (given seed and
// pixel), and are themselves a well-spread set. The adaptive methods (render/adaptive/) continue a pixel's own
// sequence with them: the fresh samples are points n0 .. n0 + m - 1 of the sequence the pilot's n0 points began,
// so a pixel that gets exactly spp samples holds the base's own spp-point set.
//
//   random, halton, sobol, pmj02   themselves (Sampler::progressive(): point i does not depend on spp)
//   jittered                       progressive jittered (PJ, Christensen, Kensler and Kilpatrick 2018): every
//                                  prefix of 4^k points has one point in each cell of the 2^k x 2^k grid, uniform
//                                  in it and independent of the others, so at spp = 4^k it is distributed exactly
//                                  as jittered (at other counts, between two such grids)
//   anything else                  none (nullptr): the grid patterns' first points fill the first row, zsobol's
//                                  and the dithered patterns' pixels are correlated with their neighbours on
//                                  purpose, which an adaptive decision read from the neighbours would see
#pragma once
#include <cstdint>
#include <memory>
#include <string>

#include "sampling/sampler.h"

namespace aliaslab {

/// The progressive sequence of `base` at `count` points (generatePrefix gives any prefix), or nullptr when the base
/// has none. Throws makeSampler's OptionError for an unknown base.
std::unique_ptr<Sampler> makeProgressiveSampler(const std::string& base, int count, uint64_t seed);

}  // namespace aliaslab
