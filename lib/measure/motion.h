// Aliasing in motion: shimmer and flicker of a frame sequence (docs/science.md, "Motion").
//
// Protocol: a configuration renders F frames (frame t: the camera moved by t times the motion, scene/camera.h
// frameScreenOffset) with each of K independent seeds, I[k][t], and each frame has its own target T_t (a
// RefEstimate: the mean of two halves and their half-difference, or exact). computeMotionMetrics() takes them
// all (F >= 2, K >= 2, every image the same size) and returns, with e_{k,t} = I_{k,t} - T_t, the per-seed
// frame change a_{k,t} = e_{k,t+1} - e_{k,t}, every mean over the F - 1 consecutive frame pairs, pixels and
// channels, and Var(dT) estimated by the mean of (D_{t+1} - D_t)^2 (zero for exact targets):
//   shimmer   = mean (mean_k a_{k,t})^2 - mean s_a^2 / K - mean Var(dT)
//             = mean over seed pairs k != l of mean a_k a_l - mean Var(dT)   (s_a^2: variance of a over seeds)
//     the squared frame change of the structured error m - T (m the seed mean), its noise removed: an estimator
//     whose error is pure noise scores zero within error. Standard error over seeds: pairStatisticSe.
//   flicker_same_seed = mean_k mean a_{k,t}^2 - mean Var(dT): one sequence rendered with the same seed in every
//     frame (what a viewer of one rendering sees), averaged over the K sequences;
//   flicker_new_seed  = the same for sequences with a new seed per frame: sequence j takes seed (j + t) mod K in
//     frame t, so the K sequences use every image once and no two consecutive frames share a seed.
//   Both flickers' standard errors: sd over the K sequences / sqrt(K).
// Expected values (b_t the structured error, n noise of variance v): shimmer = mean (b_{t+1} - b_t)^2;
// flicker_new_seed = shimmer + 2 v; flicker_same_seed = shimmer + Var(n_{t+1} - n_t).
#pragma once
#include <vector>

#include "core/image.h"
#include "measure/metrics.h"

namespace aliaslab {

struct MotionMetrics {
  double shimmer = 0, shimmerSe = 0;
  double flickerSameSeed = 0, flickerSameSeedSe = 0;
  double flickerNewSeed = 0, flickerNewSeedSe = 0;
  double targetChangeVar = 0;  ///< mean Var(T_{t+1} - T_t), the estimate subtracted from each
  int frames = 0, seeds = 0;
};

/// images[k][t]: seed k, frame t; targets[t]: frame t's target. Throws std::invalid_argument for fewer than 2
/// frames or seeds, ragged input or mismatched sizes.
MotionMetrics computeMotionMetrics(const std::vector<std::vector<Image>>& images,
                                   const std::vector<RefEstimate>& targets);

}  // namespace aliaslab
