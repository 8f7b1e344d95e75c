// The streaming weighted-average accumulator (references without stored samples).
#include <stdexcept>

#include "film/film_impl.h"

namespace aliaslab {

Accumulator::Accumulator(int width, int height, std::vector<const Filter*> filters)
    : width_(width), height_(height), filters_(std::move(filters)) {
  const size_t n = 4 * static_cast<size_t>(width) * height;
  sums_.assign(filters_.size(), std::vector<double>(n, 0.0));
  plain_.assign(n, 0.0);
}

void Accumulator::add(const SampleBuffer& batch, int threads) {
  if (batch.width() != width_ || batch.height() != height_)
    throw std::invalid_argument("Accumulator::add: batch is " + std::to_string(batch.width()) + "x" +
                                std::to_string(batch.height()) + ", accumulator " + std::to_string(width_) + "x" +
                                std::to_string(height_));
  nonFinite_ += filmimpl::countNonFinite(batch);
  filmimpl::addPlainSums(batch, plain_.data());
  for (size_t k = 0; k < filters_.size(); ++k) filmimpl::splatWeighted(batch, *filters_[k], sums_[k].data(), threads);
  samplesAdded_ += batch.samples().size();
}

Reconstruction Accumulator::resolve(size_t k) const {
  return filmimpl::resolveSums(width_, height_, sums_.at(k).data(), plain_.data(),
                               filmimpl::weightTolerance(*filters_.at(k)), nonFinite_);
}

size_t Accumulator::bytes() const {
  size_t n = plain_.size();
  for (const auto& s : sums_) n += s.size();
  return n * sizeof(double);
}

}  // namespace aliaslab
