// Large buffers backed by transparent huge pages where the kernel offers them.
//
// A traced sample set (film/film.h SampleBuffer) holds width x height x spp
// samples: 100 MB for 512 x 512 at 16 spp. Touching it the first time costs
// one page fault per 4 KB page, and page faults of one process serialise in
// the kernel, so with 4 KB pages a second thread gains little (the raytracer
// measured 1.62x from 1 to 2 threads; results/study_speed.md). Blocks of at
// least 2 MB are therefore aligned to 2 MB and advised MADV_HUGEPAGE: one
// fault per 2 MB instead of 512. Smaller blocks come from malloc as usual.
// Where the kernel says "never" the advice is a no-op; nothing depends on it
// but time. Freed large blocks are kept and handed out
// again for the same rounded size (at most 512 MiB kept): a sweep allocates the same few sizes per
// sample set, and returning them to the kernel costs page faults again plus an
// munmap that stalls every thread of the process. The contents of a reused
// block are whatever the previous owner left; std::vector initialises them.
#pragma once
#include <cstddef>
#include <new>
#include <type_traits>
#include <utility>

namespace aliaslab {

void* allocateLarge(size_t bytes);
void freeLarge(void* p, size_t bytes) noexcept;  ///< bytes: as given to allocateLarge

/// Keeps medium blocks (below 32 MB: a row's image, FLIP's planes, per-row sums) in the C heap once freed,
/// instead of glibc's default of returning each one to the kernel (munmap, or a heap trim) and faulting it in
/// again at the next allocation: a study frees thousands of them per group (0.17 s of a 19 s one-thread
/// study, all of it serial; results/study_speed.md). Process-wide, idempotent; the heap then stays at its
/// peak size. A no-op under AddressSanitizer (its allocator ignores it).
void keepMediumBlocks();

/// std::allocator with allocateLarge/freeLarge underneath.
template <class T>
struct HugePageAllocator {
  using value_type = T;
  HugePageAllocator() = default;
  template <class U>
  HugePageAllocator(const HugePageAllocator<U>&) noexcept {}
  T* allocate(size_t n) {
    if (n > size_t(-1) / sizeof(T)) throw std::bad_array_new_length();
    return static_cast<T*>(allocateLarge(n * sizeof(T)));
  }
  void deallocate(T* p, size_t n) noexcept { freeLarge(p, n * sizeof(T)); }
  template <class U>
  bool operator==(const HugePageAllocator<U>&) const noexcept { return true; }
  template <class U>
  bool operator!=(const HugePageAllocator<U>&) const noexcept { return false; }
};

/// Huge pages, and construction without arguments leaves a T (an implicit-lifetime type: FilmSample, double)
/// as the memory holds it, for storage whose owner writes every element before reading it: the sample store
/// (film/film.h SampleBuffer decides who first writes each sample), the Accumulator's sums (its first batch sets
/// them) and the metrics' running means (measure/metrics.h: the first image sets them).
template <class T>
struct UninitializedAllocator : HugePageAllocator<T> {
  using value_type = T;
  template <class U>
  struct rebind {
    using other = UninitializedAllocator<U>;
  };
  UninitializedAllocator() = default;
  template <class U>
  UninitializedAllocator(const UninitializedAllocator<U>&) noexcept {}
  template <class U, class... Args>
  void construct(U* p, Args&&... args) {
    if constexpr (sizeof...(Args) > 0 || !std::is_same_v<U, T>) ::new (static_cast<void*>(p)) U(std::forward<Args>(args)...);
  }
};

}  // namespace aliaslab
