// The theory contract every study checks (docs/science.md, "What the samplers guarantee").
//
// With the box filter of radius 0.5 each pixel's estimate is the plain mean of its own N samples, so a sampler
// whose construction guarantees Var <= c sigma^2 / N for every square-integrable integrand (Sampler::
// varianceBound: jittered 1, nrooks N/(N-1), Owen-scrambled sobol at N = 2^m 2) has, in every pixel and channel,
// at most c times the variance of N independent points; so does the sum over pixels, and its `noise` (mean over
// pixels of the seeds' variance) is at most c times random's in the same study. For every scene and spp where
// the study has both random and the sampler (box r = 0.5, weighted reconstruction, no pre-filtering):
//   ratio = noise(sampler) / noise(random),
//   se    = ratio sqrt((noise_se(sampler) / noise(sampler))^2 + (noise_se(random) / noise(random))^2)
// (the delta method; the two noises come from independent sample sets). A ratio above its bound by more than
// 3 se is a violation: the sweep prints it as a warning, the report at the top of its page
// (analysis/aliaslab_analysis/findings/contract.py computes the same from the CSV). Samplers with no theorem
// (bound 0) are listed with their ratio and "no bound". A filter wider than the pixel mixes neighbouring pixels'
// samples with unequal weights and is outside the theorem; so are adaptive samplers (their counts vary).
#pragma once
#include <functional>
#include <string>
#include <vector>

namespace aliaslab {

/// One configuration's noise as the contract reads it (a CSV row at box r = 0.5).
struct ContractRow {
  std::string scene, sampler;
  int spp = 0;
  double noise = 0, noiseSe = 0;
};

/// One sampler against random on one scene at one spp.
struct ContractCheck {
  std::string scene, sampler;
  int spp = 0;
  double ratio = 0, se = 0;  ///< noise(sampler) / noise(random) and its standard error (NaN when unknown)
  double bound = 0;          ///< the sampler's varianceBound at spp; 0: no theorem
  /// ratio - bound in standard errors (NaN without a bound or a finite se).
  double z() const;
  /// The ratio exceeds its bound by more than 3 standard errors.
  bool violated() const;
};

/// The bound a sampler name claims at spp: makeSampler(name, spp, 0)->varianceBound(); 0 for names the sampler
/// factory does not know (adaptive samplers: their counts vary, no theorem).
double claimedBound(const std::string& sampler, int spp);

using BoundOf = std::function<double(const std::string& sampler, int spp)>;

/// Every check the rows allow, in the rows' order of (scene, spp), samplers as listed; random itself and rows
/// whose random has noise 0 (a constant scene: nothing to compare) are left out.
std::vector<ContractCheck> checkContract(const std::vector<ContractRow>& rows, const BoundOf& bound = claimedBound);

/// The rows of a study CSV the contract reads: filter box, radius 0.5, weighted, prefilter none, one row per
/// configuration (noise is the same on every target row). Throws FileError when the CSV cannot be read.
std::vector<ContractRow> contractRows(const std::string& csvPath);

/// One line per violation ("scene, sampler at spp: noise r +- se x random's, bound c (z = ...)"); empty when none.
std::vector<std::string> contractViolations(const std::vector<ContractCheck>& checks);

/// One line summing the checks up: how many had a bound, how many held, the largest ratio to its bound.
std::string contractSummary(const std::vector<ContractCheck>& checks);

}  // namespace aliaslab
