// Pixel sampling patterns.
//
// Protocol: a Sampler is constructed for one sample count `spp` and one
// `seed`, and is immutable after that. generate(px, py, out) writes exactly
// spp points in [0,1)^2, the positions inside pixel (px, py) (add px, py to
// get film coordinates). The points are a pure function of (seed, px, py):
// calling generate for pixels in any order, on any thread, gives the same
// points, and different pixels get decorrelated sets (independent
// scrambles / permutations / jitter derived from core/hash.h) unless the
// pattern declares otherwise (correlatedAcrossPixels(), below).
//
// Counts a pattern does not naturally take (a non-square count for a grid
// pattern, a non-power of two for a (0,2)-sequence) are handled explicitly:
// either the pattern adapts in a documented way (e.g. an m x n grid with
// m * n = spp), reported by warning(), or the factory throws OptionError.
// Points never leave [0,1)^2 and the count is never rounded.
//
// The order of the points within a pixel carries no meaning (grid patterns
// write them cell by cell): do not split a pixel's points by index into
// "independent halves"; use two seeds instead. Construction may precompute
// (pmj02 and bluenoise build a pool of 16 sequences per seed,
// bluenoise-dither fetches its seed's masks from a process-wide cache); generate()
// is const and safe to call from many threads at once.
//
// Correlation across pixels: by default different pixels are independent
// given the seed. A pattern may instead correlate neighbouring pixels on
// purpose (zsobol shares one sequence over the image, bluenoise-dither
// shifts one pattern by a blue-noise mask) so that the error moves to high
// screen frequencies, or repeat one set in every pixel (uniform-shifted: one
// shifted grid over the whole image); it then returns true from
// correlatedAcrossPixels(). uniform, the fixed grid, is the same in every
// pixel and for every seed (deterministic).
// Each pixel's points are still unbiased (each point uniform over seeds) and
// still a pure function of (seed, px, py): the correlation is between the
// pixels of one seed, never between seeds.
//
// Names: see samplerNames(); each implementation file (lib/sampling/<name>.cpp,
// '-' written '_')
// opens with a table of what the pattern is, how it handles counts and when
// to use it. A composed name "WRAPPER:BASE" applies a wrapper of
// samplerWrapperNames() to any registered base (e.g. bluenoise-dither:sobol);
// allSamplerNames() lists every plain and composed name.
#pragma once
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "core/math.h"

namespace aliaslab {

class Sampler {
 public:
  Sampler(int spp, uint64_t seed) : spp_(spp), seed_(seed) {}
  virtual ~Sampler() = default;

  /// Writes spp() points in [0,1)^2 for pixel (px, py) to out[0 .. spp()).
  virtual void generate(int px, int py, Vec2* out) const = 0;

  /// The factory name ("jittered", "sobol", ...).
  virtual std::string name() const = 0;
  /// One line for logs and CSV rows, e.g. "jittered 2x4 strata".
  virtual std::string describe() const = 0;
  /// Non-empty when spp is not a count this pattern naturally takes; says what it does instead.
  virtual std::string warning() const { return {}; }
  /// True when the points of different pixels of one seed are deliberately correlated (see above).
  virtual bool correlatedAcrossPixels() const { return false; }
  /// The variance bound the pattern's construction guarantees (docs/science.md, "What the samplers
  /// guarantee"): c such that for every square-integrable f on the pixel, Var(mean of f over the spp points)
  /// <= c sigma^2 / spp with sigma^2 = Var f(U), U uniform on the pixel (c = 1: never worse than independent
  /// points). 0: no such theorem is claimed at this count. Every study checks it (study/records/contract.h).
  virtual double varianceBound() const { return 0; }
  /// True when point i of a pixel is the same for every count that includes it (given seed and pixel), and
  /// every prefix is a well-spread set: the first n points of the pattern at spp are the pattern at n. The
  /// adaptive methods continue such a pixel's own sequence (sampling/progressive.h).
  virtual bool progressive() const { return false; }
  /// The first count <= spp() points of pixel (px, py), as generate() writes them (for a progressive pattern: the
  /// pattern at `count`, without generating the rest). The default generates all spp() and copies.
  virtual void generatePrefix(int px, int py, int count, Vec2* out) const;

  int spp() const { return spp_; }
  uint64_t seed() const { return seed_; }

 private:
  int spp_;
  uint64_t seed_;
};

/// Every registered plain name, in a fixed order (tests and the sweep iterate it).
const std::vector<std::string>& samplerNames();

/// Wrappers that take a base sampler, used as "WRAPPER:BASE" (fixed order).
const std::vector<std::string>& samplerWrapperNames();

/// samplerNames(), then WRAPPER:BASE for every wrapper and every plain name.
const std::vector<std::string>& allSamplerNames();

/// Makes a sampler by name (plain or "WRAPPER:BASE"). Throws
/// OptionError("sampler", ...) listing the valid names for an unknown one
/// (or a wrapper without a valid base, or a wrapper of a wrapper), and OptionError("spp", ...) for spp < 1
/// or a count the pattern refuses.
std::unique_ptr<Sampler> makeSampler(const std::string& name, int spp, uint64_t seed);

/// The m x n grid (m columns, n rows, m <= n, m * n = spp, m as large as
/// possible) that grid-based patterns use for any spp; square when spp is.
void gridShape(int spp, int& columns, int& rows);

}  // namespace aliaslab
