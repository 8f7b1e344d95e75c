// Aliasing in motion: shimmer and flicker of a frame sequence, measured in the content's frame
// (docs/science.md, "Motion").
//
// Protocol: a configuration renders F frames of a camera moving d = (dx, dy) pixels per frame (frame t: the
// camera moved by t d, scene/camera.h frameScreenOffset) with each of K independent seeds, I[k][t].
// computeMotionMetrics() registers each frame t + 1 to frame t (R: moved by +d with band-limited
// interpolation, measure/registration.h) and takes, over the interior pixels (registrationMargin from every
// side), channels and the F - 1 consecutive pairs, the registered change a_{k,t} = R I_{k,t+1} - I_{k,t}:
//   shimmer   = mean over seed pairs k != l of mean a_k a_l  (= mean (mean_k a_k)^2 - mean s_a^2 / K)
//     the squared change of the part every seed shares, noise removed; no target enters. Error that moves with
//     the content (a shift-invariant blur, a steady offset) does not change after registration: below Nyquist
//     every linear resolve of a moving grating scores zero however blurred. Standard error: pairStatisticSe.
//   flicker_same_seed = mean_k mean a_{k,t}^2: one sequence rendered with the same seed in every frame;
//   flicker_new_seed  = the same for sequences with a new seed per frame: sequence j takes seed (j + t) mod K in
//     frame t, so the K sequences use every image once and no two consecutive frames share a seed.
//   Both flickers' standard errors: sd over the K sequences / sqrt(K).
// Expected values (b_t the shared part, n noise of variance v, independent across frames): shimmer =
// mean (R b_{t+1} - b_t)^2; flicker_new_seed = shimmer + 2 v (the interpolation nearly keeps white noise's
// variance); flicker_same_seed = shimmer + Var(R n_{t+1} - n_t).
// targetShimmer(): the same registered change of a target sequence T_t (RefEstimate: mean and half-difference
// D_t), mean (R T_{t+1} - T_t)^2 less its estimated variance mean (R D_{t+1} - D_t)^2: the pixel-area image
// aliases too, and this is its own shimmer.
#pragma once
#include <vector>

#include "core/image.h"
#include "measure/metrics.h"

namespace aliaslab {

struct MotionMetrics {
  double shimmer = 0, shimmerSe = 0;
  double flickerSameSeed = 0, flickerSameSeedSe = 0;
  double flickerNewSeed = 0, flickerNewSeedSe = 0;
  int frames = 0, seeds = 0;
};

/// images[k][t]: seed k, frame t, of a camera moving (dx, dy) pixels per frame. Throws std::invalid_argument
/// for fewer than 2 frames or seeds, ragged input, mismatched sizes or images with no pixel inside the margin.
MotionMetrics computeMotionMetrics(const std::vector<std::vector<Image>>& images, double dx, double dy);

/// The registered shimmer of targets[t] (frame t), its reference noise subtracted (above). Throws
/// std::invalid_argument like computeMotionMetrics.
double targetShimmer(const std::vector<RefEstimate>& targets, double dx, double dy);

}  // namespace aliaslab
