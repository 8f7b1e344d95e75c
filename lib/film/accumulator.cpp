// The streaming weighted-average accumulator (references without stored samples).
#include <algorithm>
#include <stdexcept>

#include "core/parallel.h"
#include "core/stopwatch.h"

#include "film/film_impl.h"

namespace aliaslab {

Accumulator::Accumulator(int width, int height, std::vector<const Filter*> filters)
    : width_(width), height_(height), filters_(std::move(filters)) {
  const size_t n = 4 * static_cast<size_t>(width) * height;
  sums_.resize(filters_.size());
  for (auto& s : sums_) s.resize(n);  // uninitialised: the first add() overwrites every value (0.0 + its sum)
  plain_.assign(n, 0.0);
}

void Accumulator::add(const SampleBuffer& batch, int threads) {
  if (batch.width() != width_ || batch.height() != height_)
    throw std::invalid_argument("Accumulator::add: batch is " + std::to_string(batch.width()) + "x" +
                                std::to_string(batch.height()) + ", accumulator " + std::to_string(width_) + "x" +
                                std::to_string(height_));
  const Stopwatch clock;
  nonFinite_ += filmimpl::addPlainSums(batch, plain_.data());
  std::vector<double*> sums;
  for (auto& s : sums_) sums.push_back(s.data());
  std::vector<double> own(filters_.size(), 0.0);
  filmimpl::splatAll(batch, {filters_, sums, measureShares_ ? own.data() : nullptr, fresh_}, threads);
  fresh_ = false;
  samplesAdded_ += batch.samples().size();
  if (measureShares_ && !filters_.empty()) {
    // own CPU time over the threads the bands could use approximates wall time; the rest is shared equally
    const double wall = clock.seconds();
    const int used = std::max(1, std::min(resolveThreads(threads), (height_ + filmimpl::kBand - 1) / filmimpl::kBand));
    double ownWall = 0;
    for (double& o : own) ownWall += (o /= used);
    const double rest = std::max(0.0, wall - ownWall), shared = rest / static_cast<double>(filters_.size());
    filterSeconds_.resize(filters_.size());
    for (size_t k = 0; k < own.size(); ++k) filterSeconds_[k] = own[k] + shared;
    sharedSeconds_ = rest;
  }
}

Reconstruction Accumulator::resolve(size_t k) const {
  const Filter& filter = *filters_.at(k);
  const std::vector<double> zero(fresh_ ? plain_.size() : 0, 0.0);  // nothing added yet: the sums are zero
  return filmimpl::resolveSums(width_, height_, fresh_ ? zero.data() : sums_[k].data(), plain_.data(),
                               filmimpl::weightTolerance(filter), nonFinite_);
}

size_t Accumulator::bytes() const {
  size_t n = plain_.size();
  for (const auto& s : sums_) n += s.size();
  return n * sizeof(double);
}

}  // namespace aliaslab
