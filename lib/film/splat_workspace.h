// Private to lib/film's splat pass (splat_pass.cpp): the band buffers in pages of their own and the work
// spaces (band buffers, weights, batch) a pass hands from band to band.
#pragma once
#include <algorithm>
#include <cstddef>
#include <memory>
#include <mutex>
#include <new>
#include <utility>
#include <vector>

#include <sys/mman.h>

#include "film/splat_impl.h"

namespace aliaslab::filmimpl {

/// n zeroed Sums in pages of their own, returned to the system when destroyed. The band buffers of a
/// fused pass (K at once per thread) held through the heap raised a 256 x 256 reference's peak by 4-9 MB:
/// glibc kept the freed blocks (results/study_speed.md).
class SumPages {
 public:
  explicit SumPages(size_t n) : bytes_(std::max<size_t>(n * sizeof(Sum), 1)) {
    void* p = ::mmap(nullptr, bytes_, PROT_READ | PROT_WRITE, MAP_PRIVATE | MAP_ANONYMOUS, -1, 0);
    if (p == MAP_FAILED) throw std::bad_alloc();
    data_ = static_cast<Sum*>(p);
    std::uninitialized_value_construct_n(data_, n);
  }
  SumPages(const SumPages&) = delete;
  SumPages& operator=(const SumPages&) = delete;
  ~SumPages() { ::munmap(data_, bytes_); }
  Sum* data() { return data_; }

 private:
  size_t bytes_;
  Sum* data_ = nullptr;
};

/// A thread's work space in a pass: K band buffers one after the other, the weights, a batch.
struct Workspace {
  Workspace(size_t sums, size_t weights) : buffer(sums), w(weights) {}
  SumPages buffer;
  std::vector<float> w;
  Batch batch;
};

/// Work spaces of one size reused from band to band within one pass: at most one per thread. (Kept from
/// radius to radius, they raised a 256 x 256 reference's peak by 2.3 MB: results/study_speed.md.)
class WorkspacePool {
 public:
  WorkspacePool(size_t sums, size_t weights) : sums_(sums), weights_(weights) {}
  /// A work space with zeroed sums.
  std::unique_ptr<Workspace> take() {
    std::unique_ptr<Workspace> space;
    {
      std::lock_guard lock(mutex_);
      if (!free_.empty()) space = std::move(free_.back()), free_.pop_back();
    }
    if (!space) return std::make_unique<Workspace>(sums_, weights_);
    return space;
  }
  /// Returns a work space whose sums are zero again (the band that used it cleared them as it read them).
  void give(std::unique_ptr<Workspace> space) {
    std::lock_guard lock(mutex_);
    free_.push_back(std::move(space));
  }

 private:
  size_t sums_, weights_;
  std::mutex mutex_;
  std::vector<std::unique_ptr<Workspace>> free_;
};

}  // namespace aliaslab::filmimpl
